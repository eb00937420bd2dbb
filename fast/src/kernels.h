// The inner loops over a block of samples (up to 64 x 64 pixels, one sample index), in SIMD with runtime
// dispatch (Highway): coverage by edge functions and the z-buffer test, one call per triangle and tile, or
// per run of a tile's small triangles (depth_small_run_kernel) (integer edges find each row's run of
// covered samples first, then depth-test the run, or a narrow block's whole rows masked by it; the other
// kinds are fused with the test). Bit k of a row mask stands for the sample of pixel i0 + k. Every lane
// computes exactly what the scalar definition in the comments computes (integers, or the same IEEE
// operations without contraction), so the result does not depend on the instruction set.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace rast::fast::detail {

inline constexpr int kRowLanes = 64;

// The row mask of the first n samples, n in [0, kRowLanes] (a shift by 64 would be undefined).
inline std::uint64_t first_bits(int n) {
    return n >= kRowLanes ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
}

// Samples (i + sx, j + sy) for pixels i in [i0, i0 + width), rows j in [j0, j0 + rows); width, rows <= 64.
struct Block {
    int i0, j0, width, rows;
    double sx, sy;
};

// Which samples of a block a triangle covers.
struct Coverage {
    enum class Kind {
        all,      // every sample (a trivially accepted tile)
        masks,    // given per row in `masks`
        fixed,    // integer edge functions: E at (i0, j0) plus k * dx + r * dy; covered iff all three >= 0
                  // (the tie bias is in E)
        float32,  // float edge a -> b evaluated in T on a sample row y, px = T(i + sx) rounded once:
        float64,  //   E = T(bx - ax) * T(T(y) - ay) - T(by - ay) * (px - ax); covered iff E > 0, or E == 0
                  //   on an inclusive edge. ax, ay, d1 = bx - ax, d3 = by - ay are already in T.
    };
    Kind kind = Kind::all;
    const std::uint64_t* masks = nullptr;
    std::int64_t e[3]{}, dx[3]{}, dy[3]{};
    double ax[3]{}, ay[3]{}, d1[3]{}, d3[3]{};
    bool inclusive[3]{};
};

// The z-buffer test of one triangle: z = z0 + (a * (px - x0) + b * (py - y0)), error bound err. Unless
// DepthRows carries each stored depth's error bound, every depth stored where it is tested has one of at
// most stored_err (the tile's largest so far). Rounding is monotone, so a test against stored_err decided
// nearer or farther is also decided so against the stored depth's own bound, the test the error analysis
// proves (Plane, setup.h). Where err is finite, so is z at every sample of the block (plane_over_box's
// bound is infinite where the magnitudes it sums could overflow; setup.h); and the rows hold no sample of
// triangle `id` before its test (the kernels tell the samples they wrote by it).
struct DepthPlane {
    double z0, a, x0, b, y0, err, stored_err;
    std::int32_t id;
};

// A tile's z-buffer at the block's first sample, rows `stride` apart: depths, their error bounds (or
// nullptr: DepthPlane::stored_err bounds them all) and ids. The kernel loads up to a vector past the end
// of a row (its stores are masked): the buffers need that much padding. An empty slot (id < 0) holds
// z = +infinity, so that every finite depth is decided nearer than it while the margin (depth_block) is
// finite (the gap, +infinity, is not beyond an infinite margin: that decides nothing).
struct DepthRows {
    double* z;
    double* err;
    std::int32_t* ids;  // the framebuffer's type: half the bytes of a lane of the depth test's
    std::ptrdiff_t stride;
};

// call(std::bool_constant<kPerSample>{}): a depth test instantiated for whether rows keeps a bound per
// stored depth.
template <class Call>
auto with_stored_bounds(const DepthRows& rows, Call call) {
    return rows.err ? call(std::true_type{}) : call(std::false_type{});
}

// The integer edge functions of Coverage::Kind::fixed, for a triangle whose values at every sample of
// the block fit in 32 bits: E at (i0, j0), and its steps per column and per row.
struct SmallEdges {
    std::int32_t e[3], dx[3], dy[3];
};

// Integer edge functions along the sample rows of a block, E_k = p[k] i + q[k] at column i, q[k] growing
// by step[k] from row to row: RowSpans' inputs (spans.h), for the fixed path and the wide path's near edges
// (clamped: setup.h), whose values fit in 64 bits.
struct RowEdges {
    std::int64_t p[3], q[3], step[3];
};

// masks[r]: the columns i in [0, width) of row r where all three are >= 0, for r < rows: RowSpans' run
// of the row as bits, several rows walked at once. masks must hold kRowLanes entries (rows past `rows`
// may be written).
void row_masks(const RowEdges& edges, int width, int rows, std::uint64_t* masks);

// masks[r]: the columns of row r that float edges (Coverage::Kind::float32 or float64) cover, each edge's
// crossing found by a search along the row, where it is monotone; masks must hold kRowLanes entries.
void float_row_masks(const Coverage& coverage, const Block& block, std::uint64_t* masks);

// covered[r]: the covered samples of row r.
void coverage_block(const Block& block, const Coverage& coverage, std::uint64_t* covered);

// For every covered sample, with the gap z' - z to the stored depth z' and the margin err + err', err' the
// stored depth's bound: written (z, id, and err where DepthRows keeps bounds) when gap > margin (decided
// nearer); left when gap < -margin (decided farther). Each bound is kSlack times the distance e from the
// exact depth, so either decision, rounding of the gap and margin included, holds for the exact depths:
// a rounded gap g beyond the rounded margin m has |z' - z| >= g / (1 + u) > m / (1 + u) >=
// (e + e') kSlack (1 - u) / (1 + u) > e + e'. undecided[r] gets the rest of row r, for the exact
// comparison; returns whether there are any (callers read undecided only then, and some kernels write it
// only then: most blocks have none).
bool depth_block(const Block& block, const Coverage& coverage, const DepthPlane& plane, const DepthRows& rows,
                 std::uint64_t* undecided);

// depth_block for rows whose covered samples form one run each, given as bits (covered[r]): the depth
// test runs on that run alone.
bool depth_runs(const Block& block, const std::uint64_t* covered, const DepthPlane& plane, const DepthRows& rows,
                std::uint64_t* undecided);

// depth_runs for integer edges that fit in 32 bits, each row's run found first in lanes of 32 bits
// (twice as many per vector as the depth test's). A block up to four depth vectors across is tested by
// whole rows, each lane masked by the run: the result is the same.
bool depth_small(const Block& block, const SmallEdges& edges, const DepthPlane& plane, const DepthRows& rows,
                 std::uint64_t* undecided);

// depth_small on the best target the CPU supports, resolved once: a call through the dispatch costs
// about 30 instructions, nearly 2% of a small triangle's. Valid while the supported targets stay the same.
using DepthSmallKernel = bool (*)(const Block&, const SmallEdges&, const DepthPlane&, const DepthRows&,
                                  std::uint64_t*);
DepthSmallKernel depth_small_kernel();

// One of a run's small triangles for the run kernel: depth_small's block, edges and plane (but for the
// plane's stored_err, the call's), and where the block's first sample is in the tile's rows.
struct SmallRunEntry {
    Block block;
    SmallEdges edges;
    double z0, a, x0, b, y0, err;
    std::int32_t id;
    std::ptrdiff_t at;
};

// The run kernel, kernel(entries, first, count, rows, stored_err, undecided): depth_small on entries[k] for
// k from `first` up to `count`, in order, on the tile's rows (from its first sample), their planes'
// stored_err the call's, the tile's: stops at the first entry whose test left samples undecided, and
// answers its index (undecided holds its rows', as depth_small's), or `count`. The exact order the caller
// then gives that entry may store a depth of a larger bound, which the next call's stored_err takes in. One
// call for a run of triangles: a call each, with the steps around it, had cost 200 of a small triangle's
// 1600 instructions. On the best target the CPU supports, resolved once, as depth_small_kernel().
using DepthSmallRunKernel = std::size_t (*)(const SmallRunEntry*, std::size_t, std::size_t, const DepthRows&,
                                            double, std::uint64_t*);
DepthSmallRunKernel depth_small_run_kernel();

// Hierarchical z's subtiles: squares of kSubtile x kSubtile pixels, kSubtiles each way in a row of
// kRowLanes, counted from its first pixel (a tile's: tile_buffer.h). A subtile's row is one AVX-512
// vector of depths.
inline constexpr int kSubtile = 8;
inline constexpr int kSubtiles = kRowLanes / kSubtile;

// A plane against the far depths of the subtiles its box meets (hierarchical z): z = z0 + (a (px - x0) +
// b (py - y0)), margin = err + stored_err (the plane's and the stored depths' bounds, as in DepthPlane);
// the sample offsets' extremes; the box, pixels [i0, i1] x [j0, j1], in the subtiles from pixel (ti, tj).
struct SubtileTest {
    double z0, a, x0, b, y0, margin;
    double ox_min, ox_max, oy_min, oy_max;
    int ti, tj, i0, i1, j0, j1;
};

// The subtiles of the box where the plane may be in front of a stored depth, as bit kSubtiles by + bx
// for subtile (bx, by): those where its value at the nearest corner of its samples' rectangle in the box
// (the corner by the slopes' signs) minus the subtile's far depth far[kSubtiles by + bx] is not beyond
// the margin. The whole tile's test's arithmetic (behind_tile, tile_buffer.h), lane by lane.
std::uint64_t open_subtiles(const SubtileTest& t, const double* far);

// A big triangle just composed into a tile, against the far depths of the subtiles in [bx0, bx1] x
// [by0, by1] (whole ones, counted from the tile's pixel (ti, tj)): its plane as in SubtileTest and its
// edges. Integer edges: for each, the least value over the samples of subtile (bx0, by0) and its steps
// from one subtile to the next across and down (exact: the edge is linear, least at the corner its signs
// pick). Float edges (floating): each edge's start (ax, ay) and d1 = bx - ax, d3 = by - ay in doubles, and
// the float modes' whole-tile margin (float_margin, setup.h).
struct SubtileCover {
    double z0, a, x0, b, y0;
    double ox_min, ox_max, oy_min, oy_max;
    std::int64_t lowest[3]{}, across[3]{}, down[3]{};
    bool floating = false;
    double ax[3]{}, ay[3]{}, d1[3]{}, d3[3]{}, margin = 0;
    int ti, tj, bx0, bx1, by0, by1;
};

// far[kSubtiles by + bx] lowered to the plane's value at the farthest corner of the samples' rectangle of
// subtile (bx, by) for every subtile whose samples all lie inside the three edges (integer edges: all
// edge values >= 0; float edges: each one's double value at the corner where it is least beyond the margin,
// the test by which classify accepts a whole tile):
// its far depth found without reading the tile, once the triangle is composed (cover_subtiles,
// tile_buffer.h, says why it bounds the subtile). Triangles composed nearest first left the far depths
// found every few of them a quarter more samples to test (the MOC peer's large scene).
void lower_covered_subtiles(const SubtileCover& t, double* far);

// The largest z[k] for k < n (+infinity when any slot is empty). The maximum is exact, so the order the
// lanes take does not matter.
double farthest(const double* z, std::size_t n);

// The largest depth of each subtile column of `rows` rows `stride` apart: far[k] = max z[r * stride + i]
// for r < rows and i in [kSubtile k, min(kSubtile (k + 1), width)), for every k < ceil(width / kSubtile)
// (+infinity where a slot is empty). The maximum is exact, so the order the lanes take does not matter.
// Loads up to a subtile past the last row's width, as the depth tests do: the buffer needs that padding.
void farthest_subtiles(const double* z, std::ptrdiff_t stride, int width, int rows, double* far);

// z[k] = +infinity (an empty sample) for k < n, in the widest stores there are: std::fill_n, compiled for
// the library's baseline, stored 16 bytes at a time, a tenth of the big triangles' time outside the kernels.
void fill_far(double* z, std::size_t n);

// A tile's rows copied out to the framebuffer: for r < rows and k < width, to_z[r * to_stride + k] =
// z[r * stride + k], and the ids alike. The destination's whole cache lines are written by non-temporal
// stores, which do not first read the line into the cache (the tiles' pass writes the framebuffer once
// and does not read it: its 12 MB at 1024 x 1024 were read as well as written); the partial lines at a
// row's ends, which the next tile writes the rest of, by ordinary stores. The streamed stores are fenced
// before it returns, so the tiles' loop's join publishes them as it does the others.
void copy_out(const double* z, const std::int32_t* ids, std::ptrdiff_t stride, double* to_z, std::int32_t* to_ids,
              std::ptrdiff_t to_stride, int width, int rows);

}  // namespace rast::fast::detail
