// Composing, one stage of the fast path (engine.h): a triangle into a tile's z-buffer, block by block of
// one sample index, behind hierarchical z; the depth test in the kernels, and the exact (z, id) order
// (or an injected bug) for what their bounds leave undecided.
#pragma once

#include "coverage.h"
#include "kernels.h"
#include "scalar.h"
#include "setup.h"
#include "stamp.h"
#include "tile_buffer.h"

#include <rast/fast_faults.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace rast::fast::detail {

// Row r of block b: the samples the filtered test could not order get the exact (z, id) order, or the
// injected bug.
template <Fault F>
void resolve(const Corners& v, const DepthPlane& p, const Block& b, int r, std::uint64_t undecided,
             TileBuffer& tile, std::size_t at, const SceneView& scene) {
    const double py = double(b.j0 + r) + b.sy;
    const double b_dy = p.b * (py - p.y0);
    for (; undecided != 0; undecided &= undecided - 1) {
        const int k = std::countr_zero(undecided);
        const double px = double(b.i0 + k) + b.sx;
        const double z = p.z0 + (p.a * (px - p.x0) + b_dy);
        const std::size_t slot = at + k;
        const std::int32_t other = tile.ids[slot];
        bool replace = other < 0;
        if (!replace) {
            if constexpr (F == Fault::depth_less_equal) {
                replace = z <= tile.z[slot];
            } else {
                // The plane, hence the exact depth, does not depend on the order of the corners.
                const Corners u = snapped(scene.triangles[other], scene.c.precision).v;
                const int order = tile.planes.compare(p.id, v, other, u, px, py);
                const bool wins_tie = F == Fault::no_id_tiebreak || p.id < other;
                replace = order < 0 || (order == 0 && wins_tie);
            }
        }
        if (!replace) continue;
        // Where the plane or its error bound overflows, the exact depth rounded to nearest, with a bound of
        // its own (an infinite one kept in the tile would send its later comparisons to exact arithmetic).
        const bool bounded = std::isfinite(z) && p.err < std::numeric_limits<double>::infinity();
        tile.z[slot] = bounded ? z : tile.planes.depth(p.id, v, px, py);
        tile.stored(slot, bounded ? p.err : nearest_error(tile.z[slot]));
        tile.ids[slot] = p.id;
    }
}

// The rows of block b (its first sample at `at`) that the depth test left undecided, undecided[r] for row
// r, get the exact (z, id) order (or the injected bug).
template <Fault F>
void resolve_rows(const Corners& v, const DepthPlane& p, const Block& b, const std::uint64_t* undecided,
                  TileBuffer& tile, std::size_t at, const SceneView& scene) {
    for (int r = 0; r < b.rows; ++r)
        if (undecided[r] != 0) resolve<F>(v, p, b, r, undecided[r], tile, at + r * tile.cols, scene);
}

// Counts a block of `samples` samples towards the refresh of the tile's far depth, refreshing it when due.
inline void count_block(TileBuffer& tile, std::size_t samples, const TileRect& rect, const Context& c) {
    tile.since_far += samples;
    if (tile.since_far >= kFarRefresh * tile.size)
        tile.refresh_far(static_cast<int>(c.offsets.size()), rect.i1 - rect.i0 + 1, rect.j1 - rect.j0 + 1);
}

// Triangle plane.id (corners() answers its placed corners, which only the exact order reads) into the
// tile's z-buffer over pixels [i0, i1] x [j0, j1], one block per sample index, its bound already
// admitted: depth(b, s, plane, rows, undecided) runs the z-buffer test on block b of sample index s and
// answers whether it left samples undecided; those get the exact order.
template <Fault F, class CornersOf, class BlockDepth>
[[gnu::always_inline]] inline void compose_blocks(CornersOf corners, const DepthPlane plane, int i0, int i1,
                                                  int j0, int j1, const TileRect& rect, TileBuffer& tile,
                                                  const SceneView& scene, BlockDepth depth) {
    const Context& c = scene.c;
    std::uint64_t undecided[kTile];
    const auto block = [&](int s) __attribute__((always_inline)) {
        const Block b{i0, j0, i1 - i0 + 1, j1 - j0 + 1, c.offsets[s].x, c.offsets[s].y};
        const std::size_t at = tile.at(s, j0 - rect.j0, i0 - rect.i0);
        const DepthRows rows = tile.rows_at(at);
        if (!depth(b, s, plane, rows, undecided)) return;
        // The exact order, rare, takes a copy: where the depth test is inlined (the stamps'), the plane then
        // stays in registers rather than going through the stack for every triangle.
        const DepthPlane p = plane;
        resolve_rows<F>(corners(), p, b, undecided, tile, at, scene);
    };
    // One sample a pixel, the common case, without the loop, which took 22 of a tiny triangle's
    // instructions.
    const int samples = static_cast<int>(c.offsets.size());
    if (samples == 1) return block(0);
    for (int s = 0; s < samples; ++s) block(s);
}

// A big triangle's rows of its box in a tile as hierarchical z's subtiles trim them: the rows from the
// first band of subtiles the triangle may be in front in to the last, and keep[r] the columns of row
// j0 + r (bit k: pixel i0 + k) from the first subtile of its band the triangle may be in front in to the
// last, none in a band it is behind in everywhere. One run a row, as the kernels take it: hidden subtiles
// between open ones are tested all the same (the depth test decides them farther).
struct TrimmedRows {
    bool trimmed = false;  // whether any row left lost a column
    std::uint64_t keep[kTile];
    // From the subtiles `open` (in_front_subtiles' bits, not none) of pixels [i0, i1] x [j0, j1] of the
    // tile at rect; j0 and j1 become the rows left.
    void trim(std::uint64_t open, const TileRect& rect, int i0, int i1, int& j0, int& j1) {
        j0 = std::max(j0, rect.j0 + std::countr_zero(open) / kSubtiles * kSubtile);
        j1 = std::min(j1, rect.j0 + ((63 - std::countl_zero(open)) / kSubtiles + 1) * kSubtile - 1);
        const std::uint64_t whole = first_bits(i1 - i0 + 1);
        trimmed = false;
        for (int y = j0; y <= j1;) {
            const int by = (y - rect.j0) / kSubtile, end = std::min(j1 + 1, rect.j0 + (by + 1) * kSubtile);
            const std::uint64_t band = open >> (kSubtiles * by) & first_bits(kSubtiles);
            std::uint64_t row = 0;
            if (band != 0) {
                const int first = std::countr_zero(band), last = 63 - std::countl_zero(band);
                const int x0 = std::max(i0, rect.i0 + first * kSubtile);
                const int x1 = std::min(i1, rect.i0 + (last + 1) * kSubtile - 1);
                row = first_bits(x1 - x0 + 1) << (x0 - i0);
            }
            trimmed = trimmed || row != whole;
            for (; y < end; ++y) keep[y - j0] = row;
        }
    }
};

// What every path shares: triangle `id` (its depth plane) into the tile's z-buffer over pixels
// [i0, i1] x [j0, j1] of its bounding box, behind hierarchical z, by compose_blocks; with `trim`, behind
// its subtiles too, which trim the rows (a big triangle: a small one's box meets a subtile or a few).
// Answers whether it was composed, not hidden whole. Always inlined: as a call of its own, its arguments
// and the plane went through the stack, a tenth of a small triangle's setup.
template <Fault F, class CornersOf, class BlockDepth>
[[gnu::always_inline]] inline bool rasterize_blocks(CornersOf corners, const Plane& pl, std::int32_t id, int i0,
                                                    int i1, int j0, int j1, const TileRect& rect, TileBuffer& tile,
                                                    const SceneView& scene, BlockDepth depth,
                                                    TrimmedRows* trim = nullptr) {
    if constexpr (F == Fault::halved_depth_bound) {
        Plane halved = pl;
        halved.err /= 2;
        return rasterize_blocks<Fault::none>(corners, halved, id, i0, i1, j0, j1, rect, tile, scene, depth, trim);
    }
    const Context& c = scene.c;
    if (behind_tile(pl, c, tile, i0, i1, j0, j1)) return false;
    if (trim) {
        if (tile.subtiles_due)
            tile.refresh_subtiles(static_cast<int>(c.offsets.size()), rect.i1 - rect.i0 + 1, rect.j1 - rect.j0 + 1);
        const std::uint64_t open = in_front_subtiles(pl, c, tile, rect.i0, rect.j0, i0, i1, j0, j1);
        if (open == 0) return false;
        trim->trim(open, rect, i0, i1, j0, j1);
    }
    count_block(tile, static_cast<std::size_t>(i1 - i0 + 1) * (j1 - j0 + 1) * c.offsets.size(), rect, c);
    tile.admit(pl.err);
    const DepthPlane plane{pl.z0, pl.a, pl.x0, pl.b, pl.y0, pl.err, tile.stored_err, id};
    compose_blocks<F>(corners, plane, i0, i1, j0, j1, rect, tile, scene, depth);
    return true;
}

// The z-buffer test of block b for integer edges at its first sample and their steps (fixed_edges_at's),
// without a Coverage.
inline bool integer_block_depth(const RowEdges& edges, const Block& b, const DepthPlane& plane, const DepthRows& rows,
                                std::uint64_t* undecided) {
    return depth_rows_scalar(
        b, [&](int r) { return fixed_row_coverage(edges.q, edges.p, edges.step, b.width, r); }, plane, rows,
        undecided);
}
inline bool fixed_block_depth(const std::array<FixedEdge, 3>& edges, const Context& c, const Block& b, int s,
                              const DepthPlane& plane, const DepthRows& rows, std::uint64_t* undecided) {
    RowEdges at;
    fixed_edges_at(edges, c, b, s, at.q, at.p, at.step);
    return integer_block_depth(at, b, plane, rows, undecided);
}

// A big triangle's box in a tile is tested subtile by subtile from this many pixels on: the test and the
// trimming cost a few hundred instructions a tile, about as many as the depth test of the samples a
// medium-sized triangle (64 pixels across) has in a tile.
inline constexpr int kSubtileBox = 2048;

// Triangle t, named id, into the tile's z-buffer.
template <Fault F>
void rasterize(const Setup& t, std::int32_t id, const TileRect& rect, TileBuffer& tile, const SceneView& scene) {
    const Context& c = scene.c;
    const int i0 = std::max(rect.i0, t.p.i_lo), i1 = std::min(rect.i1, t.p.i_hi);
    const int j0 = std::max(rect.j0, t.p.j_lo), j1 = std::min(rect.j1, t.p.j_hi);
    // Hierarchical z before the edges' whole-tile test, which costs more: 3-4% less time on a scene of big
    // triangles composed nearest first (rasterize_blocks asks it again of those that pass, a few operations).
    if (behind_tile(t.plane, c, tile, i0, i1, j0, j1)) return;
    const TileClass cls = classify(t, c, i0, i1, j0, j1);
    if (cls == TileClass::reject) return;
    std::span<const Span> wide;  // a partial tile's, found at the first sample index, past hierarchical z
    std::uint64_t masks[kTile];
    TrimmedRows trim;
    const bool subtiles = t.subtiles && (i1 - i0 + 1) * (j1 - j0 + 1) >= kSubtileBox;
    const bool composed = rasterize_blocks<F>(
        [&t]() -> const Corners& { return t.p.v; }, t.plane, id, i0, i1, j0, j1, rect, tile, scene,
        // Inlined (GCC's spelling for a lambda): out of line, medium triangles took 1% more instructions.
        [&](const Block& b, int s, const DepthPlane& plane, const DepthRows& rows, std::uint64_t* undecided)
            __attribute__((always_inline)) {
            const bool scalar = b.width * b.rows <= kScalarSamples;
            const bool partial = cls == TileClass::partial;
            RowEdges edges;
            const bool integer = partial && integer_edges_at(t, c, b, s, edges.q, edges.p, edges.step);
            if (integer && scalar) return integer_block_depth(edges, b, plane, rows, undecided);
            if (partial && t.p.path == Path::wide && !integer && wide.empty()) wide = tile.wide.of(t, c, j0, j1);
            // The spans of the block's own rows: hidden bands trimmed off its top start it below j0.
            const std::span<const Span> spans =
                wide.empty() ? wide : wide.subspan(static_cast<std::size_t>(b.j0 - j0) * c.offsets.size());
            if (partial && t.p.path != Path::floating && !scalar) {
                // Exact rows, one run each: walked from row to row from integer edges, or the wide path's
                // spans where it has none; each trimmed to its subtiles (still one run).
                if (integer) row_masks(edges, b.width, b.rows, masks);
                else coverage_of<F>(t, c, b, s, spans, masks);
                if (trim.trimmed)
                    for (int r = 0; r < b.rows; ++r) masks[r] &= trim.keep[r];
                return depth_runs(b, masks, plane, rows, undecided);
            }
            if (!partial && !scalar && trim.trimmed) return depth_runs(b, trim.keep, plane, rows, undecided);
            const Coverage cov = partial ? coverage_of<F>(t, c, b, s, spans, masks) : Coverage{};
            return scalar ? depth_block_scalar(b, cov, plane, rows, undecided)
                          : depth_block(b, cov, plane, rows, undecided);
        },
        subtiles ? &trim : nullptr);
    if (composed && subtiles) cover_subtiles(t, c, tile, rect.i0, rect.j0, i0, i1, j0, j1);
}

// A small triangle's binned record: its box within the tile.
inline TileRect box_in(const SmallFixed& t, const TileRect& rect) {
    return {std::max(rect.i0, t.i_lo), std::min(rect.i1, t.i_hi), std::max(rect.j0, t.j_lo), std::min(rect.j1, t.j_hi)};
}

// The samples of a box (at one sample index), and whether its block takes the scalar depth test (scalar.h)
// rather than a kernel.
inline std::size_t samples_in(const TileRect& box) {
    return static_cast<std::size_t>(box.i1 - box.i0 + 1) * static_cast<std::size_t>(box.j1 - box.j0 + 1);
}
inline bool scalar_block(const TileRect& box) { return samples_in(box) <= kScalarSamples; }

// Lane k of a stamp setup's edges, in depth_small's form.
inline SmallEdges small_edges(const StampEdges& set_up, int k) {
    SmallEdges out;
    for (int e = 0; e < 3; ++e) {
        out.e[e] = set_up.e[e][k];
        out.dx[e] = set_up.dx[e][k];
        out.dy[e] = set_up.dy[e][k];
    }
    return out;
}

// A small triangle of the 64-bit fixed path, straight from its binned record and its plane: its edges
// are all else it needs, and a narrow one's edges fit the 32-bit lanes of depth_small. set_up: a narrow
// one's edges at each sample index, lane `lane` of its run's stamp setup (StampMasks), which computed them
// for the batch in SIMD (the same values: stamp.h); or nullptr, and they are found here.
template <Fault F>
void rasterize_small(const SmallFixed& t, const Plane& pl, bool narrow, const StampEdges* set_up, int lane,
                     const TileRect& rect, TileBuffer& tile, const SceneView& scene) {
    const Context& c = scene.c;
    const TileRect box = box_in(t, rect);
    const auto corners = [&] { return placed_of(t, c).v; };
    const bool scalar = scalar_block(box);
    if (narrow && set_up && !scalar) {  // the block is the same at every sample index
        rasterize_blocks<F>(corners, pl, t.id, box.i0, box.i1, box.j0, box.j1, rect, tile, scene,
                            [&](const Block& b, int s, const DepthPlane& plane, const DepthRows& rows,
                                std::uint64_t* undecided) {
                                return c.depth_small(b, small_edges(set_up[s], lane), plane, rows, undecided);
                            });
        return;
    }
    const std::array<FixedEdge, 3> edges = fixed_edges<F>(t.x, t.y);
    rasterize_blocks<F>(corners, pl, t.id, box.i0, box.i1, box.j0, box.j1, rect, tile, scene,
                        [&](const Block& b, int s, const DepthPlane& plane, const DepthRows& rows,
                            std::uint64_t* undecided) {
                            if (scalar) return fixed_block_depth(edges, c, b, s, plane, rows, undecided);
                            if (!narrow) {
                                std::uint64_t masks[kTile];
                                fixed_row_masks(edges, c, b, s, masks);
                                return depth_runs(b, masks, plane, rows, undecided);
                            }
                            std::int64_t e[3], dx[3], dy[3];
                            fixed_edges_at(edges, c, b, s, e, dx, dy);
                            SmallEdges small;
                            for (int k = 0; k < 3; ++k) {
                                small.e[k] = static_cast<std::int32_t>(e[k]);
                                small.dx[k] = static_cast<std::int32_t>(dx[k]);
                                small.dy[k] = static_cast<std::int32_t>(dy[k]);
                            }
                            return c.depth_small(b, small, plane, rows, undecided);
                        });
}

// The largest sample count (sample_pattern, rast/scene.h).
inline constexpr int kMaxSamples = 16;

// The stamps of a run of small triangles in a tile (stamp.h), for every sample index, and the edges of
// the run's blocks they were found from.
struct StampMasks {
    std::uint32_t triangles = 0;  // bit k: run[k] has stamps
    std::size_t samples = 0;      // their blocks' samples, at every sample index
    bool set_up = false;          // whether find() ran: edges holds the run's
    std::uint64_t masks[kMaxSamples][kPlaneBatch];
    StampEdges edges[kMaxSamples];
    void find(const PlaneBatch& batch, std::uint32_t narrow, const TileRect& rect, const Context& c) {
        for (std::size_t s = 0; s < c.offsets.size(); ++s) {
            const StampGrid grid{rect.i0, rect.i1, rect.j0, rect.j1, c.bits, static_cast<std::int32_t>(c.sx[s]),
                                 static_cast<std::int32_t>(c.sy[s])};
            // The same blocks at every index.
            const Stamped stamped = stamp_masks(batch, narrow, grid, edges[s], masks[s]);
            triangles = stamped.triangles;
            samples = stamped.samples * c.offsets.size();
        }
        set_up = true;
    }
};

// depth_rows_scalar (scalar.h) for a stamp's coverage, bit kStampSide r + c for column c of row r: one
// loop over the mask's bits, not one per row (a tiny triangle's stamp has two or three samples on as
// many rows). The same test sample by sample (depth_sample), so the same result.
template <bool kPerSample>
[[gnu::always_inline]] inline bool depth_stamp(const Block& b, std::uint64_t mask, const DepthPlane& p,
                                               const DepthRows& rows, std::uint64_t* undecided) {
    std::uint64_t open = 0;
    for (; mask != 0; mask &= mask - 1) {
        const int k = std::countr_zero(mask), r = k / kStampSide, col = k % kStampSide;
        const double px = double(b.i0 + col) + b.sx, py = double(b.j0 + r) + b.sy;
        if (depth_sample<kPerSample>(p, rows, r * rows.stride + col, px, p.b * (py - p.y0)))
            open |= std::uint64_t{1} << k;
    }
    if (open == 0) return false;
    for (int r = 0; r < b.rows; ++r) undecided[r] = open >> (kStampSide * r) & first_bits(kStampSide);
    return true;
}

// The narrow small triangles of a run without stamps whose edges the stamps' setup found (stamps.edges,
// lane k for run[k]) and whose block is not the scalar test's (those rasterize_small would give
// depth_small), with one sample a pixel: one call of the run kernel (depth_small_run_kernel) composes
// them (`triangles`: bit k for run[k], boxes[k] its box), their bookkeeping done with the stamps'. With
// more samples a triangle has a block at each sample index, and goes to rasterize_small.
struct DirectRun {
    std::uint32_t triangles = 0;
    std::size_t samples = 0;
    TileRect boxes[kPlaneBatch];
    template <class Run>
    DirectRun(const Run& run, std::uint32_t narrow, const StampMasks& stamps, const TileRect& rect,
              const Context& c) {
        if (!stamps.set_up || c.offsets.size() != 1) return;
        for (std::uint32_t m = narrow & ~stamps.triangles; m != 0; m &= m - 1) {
            const int k = std::countr_zero(m);
            const TileRect box = box_in(run[k], rect);
            if (scalar_block(box)) continue;
            triangles |= std::uint32_t{1} << k;
            samples += samples_in(box);
            boxes[k] = box;
        }
    }
};

// The small triangles run[k] (their planes[k]; narrow: bit k for a narrow one): those whose stamps were
// found (stamps.triangles) test depth on the masks' bits, the direct ones (DirectRun) go to the run kernel
// together, the others to rasterize_small; the (z, id) order is total, so the order they are composed in
// does not matter. The bookkeeping of the stamps and the direct ones is done once for the run, before any
// is composed (also for those hierarchical z then skips): their blocks are counted for the far depth, and
// of their finite bounds the largest and the smallest admitted, which leaves the tile's bound above each
// and switches it to a bound per sample if one of them is far from it (an infinite one is admitted apart:
// admitted in their place it would raise the tile's bound not at all). Their planes may then carry a larger
// tile bound than one at a time would: still a bound.
template <Fault F>
void rasterize_run(std::span<const SmallFixed> run, const Plane* planes, std::uint32_t narrow,
                   const StampMasks& stamps, const TileRect& rect, TileBuffer& tile, const SceneView& scene) {
    const Context& c = scene.c;
    const DirectRun direct(run, narrow, stamps, rect, c);
    if (const std::uint32_t together = stamps.triangles | direct.triangles; together != 0) {
        constexpr double kInfinity = std::numeric_limits<double>::infinity();
        double smallest = kInfinity, largest = 0;
        bool unbounded = false;  // a plane whose bound overflowed (narrow_planes makes it +infinity)
        for (std::uint32_t m = together; m != 0; m &= m - 1) {
            const double e = planes[std::countr_zero(m)].err;
            if (e < kInfinity) {
                smallest = std::min(smallest, e);
                largest = std::max(largest, e);
            } else {
                unbounded = true;
            }
        }
        count_block(tile, stamps.samples + direct.samples, rect, c);
        // An infinite bound raises no other, but switches a tile that holds depths to a bound per sample.
        if (unbounded) tile.admit(kInfinity);
        if (smallest <= largest) {
            tile.admit(largest);
            tile.admit(smallest);
        }
    }
    for (std::size_t k = 0; k < run.size(); ++k) {
        const SmallFixed& t = run[k];
        const Plane& pl = planes[k];
        if (direct.triangles >> k & 1) continue;
        if (!(stamps.triangles >> k & 1)) {
            rasterize_small<F>(t, pl, narrow >> k & 1, stamps.set_up ? stamps.edges : nullptr, static_cast<int>(k),
                               rect, tile, scene);
            continue;
        }
        const TileRect box = box_in(t, rect);
        if (behind_tile(pl, c, tile, box.i0, box.i1, box.j0, box.j1)) continue;
        const DepthPlane plane{pl.z0, pl.a, pl.x0, pl.b, pl.y0, pl.err, tile.stored_err, t.id};
        const auto depth = [&](const Block& b, int s, const DepthPlane& p, const DepthRows& rows,
                               std::uint64_t* undecided) {
            return with_stored_bounds(rows, [&](auto per_sample) {
                return depth_stamp<per_sample>(b, stamps.masks[s][k], p, rows, undecided);
            });
        };
        compose_blocks<F>([&] { return placed_of(t, c).v; }, plane, box.i0, box.i1, box.j0, box.j1, rect, tile, scene,
                          depth);
    }
    if (direct.triangles == 0) return;
    SmallRunEntry entries[kPlaneBatch];
    int which[kPlaneBatch];  // entries[n] is run[which[n]]
    std::size_t n = 0;
    for (std::uint32_t m = direct.triangles; m != 0; m &= m - 1) {
        const int k = std::countr_zero(m);
        const SmallFixed& t = run[k];
        const Plane& pl = planes[k];
        const TileRect& box = direct.boxes[k];
        if (behind_tile(pl, c, tile, box.i0, box.i1, box.j0, box.j1)) continue;
        entries[n] = {{box.i0, box.j0, box.i1 - box.i0 + 1, box.j1 - box.j0 + 1, c.offsets[0].x, c.offsets[0].y},
                      small_edges(stamps.edges[0], k),
                      pl.z0, pl.a, pl.x0, pl.b, pl.y0, pl.err, t.id,
                      static_cast<std::ptrdiff_t>(tile.at(0, box.j0 - rect.j0, box.i0 - rect.i0))};
        which[n++] = k;
    }
    std::uint64_t undecided[kTile];
    const DepthRows rows = tile.rows_at(0);
    // No call where hierarchical z left no entry.
    for (std::size_t k = 0; k < n && (k = c.depth_small_run(entries, k, n, rows, tile.stored_err, undecided)) < n;
         ++k) {
        const SmallRunEntry& e = entries[k];
        const DepthPlane p{e.z0, e.a, e.x0, e.b, e.y0, e.err, tile.stored_err, e.id};
        resolve_rows<F>(placed_of(run[which[k]], c).v, p, e.block, undecided, tile, static_cast<std::size_t>(e.at),
                        scene);
    }
}

}  // namespace rast::fast::detail
