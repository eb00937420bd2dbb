// The rasterizer proper: screen tiles of 64 x 64 pixels, binned triangles composed in id order per tile,
// trivial reject / accept per tile, one SIMD kernel call per triangle, tile and sample index. Templated on the injected
// fault; render.cpp instantiates Fault::none, the testing target the others.
#pragma once

#include "kernels.h"
#include "line_pass.h"
#include "scalar.h"
#include "setup.h"
#include "validate.h"

#include <rast/fast.h>
#include <rast/fast_faults.h>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace rast::fast::detail {

inline std::uint64_t span_bits(int from, int to, int i0) {
    if (from > to) return 0;
    return first_bits(to - from + 1) << (from - i0);
}

// The injected bug of the float modes: E stepped along the row by repeated subtraction, which
// accumulates rounding (the kernels evaluate it afresh at every sample).
template <class T>
std::uint64_t float_row_accumulated(const Setup& t, const Context& c, int j, int s, int i0, int n) {
    const T py = T(j + c.offsets[s].y);
    const T sx = T(c.offsets[s].x);
    std::uint64_t covered = first_bits(n);
    for (const FloatEdge& f : t.flt) {
        const T d3 = T(f.d3);
        T value = T(T(f.d1) * T(py - T(f.ay))) - d3 * (T(i0 + sx) - T(f.ax));
        for (int k = 0; k < n; ++k, value -= d3)
            if (!(value > 0 || (value == 0 && f.inclusive))) covered &= ~(std::uint64_t{1} << k);
    }
    return covered;
}

// The integer edge functions at block b's first sample (index s) and their steps per column and row.
inline void fixed_edges_at(const std::array<FixedEdge, 3>& edges, const Context& c, const Block& b, int s,
                           std::int64_t* e, std::int64_t* dx, std::int64_t* dy) {
    const std::int64_t x = (std::int64_t{b.i0} << c.bits) + c.sx[s];
    const std::int64_t y = (std::int64_t{b.j0} << c.bits) + c.sy[s];
    for (int k = 0; k < 3; ++k) {
        const FixedEdge& f = edges[k];
        e[k] = f.a * x + f.b * y + f.c;
        dx[k] = f.a << c.bits;
        dy[k] = f.b << c.bits;
    }
}

// masks[r]: the samples of row r of block b (sample index s) inside the integer edges, each row's run
// walked from the row before (row_masks, after spans.h) rather than found by evaluating the edges along
// the row. masks holds kTile entries.
inline void fixed_row_masks(const std::array<FixedEdge, 3>& edges, const Context& c, const Block& b, int s,
                            std::uint64_t* masks) {
    RowEdges walk;
    fixed_edges_at(edges, c, b, s, walk.q, walk.p, walk.step);
    row_masks(walk, b.width, b.rows, masks);
}

// How the kernels find the samples of block b (sample index s) that t covers; the paths that compute
// row masks here leave them in `masks`, one per row of the block. wide: on the wide path, t's spans of
// the block's rows (spans_of, from row b.j0).
template <Fault F>
Coverage coverage_of(const Setup& t, const Context& c, const Block& b, int s, std::span<const Span> wide,
                     std::uint64_t* masks) {
    Coverage cov;
    switch (t.p.path) {
        case Path::fixed:
            cov.kind = Coverage::Kind::fixed;
            fixed_edges_at(t.fixed, c, b, s, cov.e, cov.dx, cov.dy);
            return cov;
        case Path::wide: {
            const std::size_t samples = c.offsets.size();
            for (int r = 0; r < b.rows; ++r) {
                const Span& span = wide[static_cast<std::size_t>(r) * samples + s];
                masks[r] = span_bits(std::max(span.lo, b.i0), std::min(span.hi, b.i0 + b.width - 1), b.i0);
            }
            cov.kind = Coverage::Kind::masks;
            cov.masks = masks;
            return cov;
        }
        case Path::floating: {
            const bool single = c.precision == Precision::float32;
            if constexpr (F == Fault::float_row_accumulation) {
                for (int r = 0; r < b.rows; ++r)
                    masks[r] = single ? float_row_accumulated<float>(t, c, b.j0 + r, s, b.i0, b.width)
                                      : float_row_accumulated<double>(t, c, b.j0 + r, s, b.i0, b.width);
                cov.kind = Coverage::Kind::masks;
                cov.masks = masks;
                return cov;
            }
            cov.kind = single ? Coverage::Kind::float32 : Coverage::Kind::float64;
            for (int e = 0; e < 3; ++e) {
                const FloatEdge& f = t.flt[e];
                cov.ax[e] = f.ax;
                cov.ay[e] = f.ay;
                cov.d1[e] = f.d1;
                cov.d3[e] = f.d3;
                cov.inclusive[e] = f.inclusive;
            }
            return cov;
        }
    }
    return cov;
}

enum class TileClass { reject, accept, partial };

// The Larrabee test on the samples of pixels [i0, i1] x [j0, j1]: an edge function is linear, so its
// extremes over the samples' bounding rectangle are at corners chosen by the signs of its coefficients.
// Exact for the integer path; the wide path reads what its spans lie within per band instead. For the float
// modes the double value at a corner is within margin of the exact one minus the mode's error bound, so
// beyond +-margin the mode's sign is certain.
inline TileClass classify(const Setup& t, const Context& c, int i0, int i1, int j0, int j1) {
    if (!t.classify_tiles) return TileClass::partial;
    bool all_inside = true;
    switch (t.p.path) {
        case Path::fixed: {
            const std::int64_t x_lo = (std::int64_t{i0} << c.bits) + c.sx_min, x_hi = (std::int64_t{i1} << c.bits) + c.sx_max;
            const std::int64_t y_lo = (std::int64_t{j0} << c.bits) + c.sy_min, y_hi = (std::int64_t{j1} << c.bits) + c.sy_max;
            for (const FixedEdge& f : t.fixed) {
                const std::int64_t lowest = f.a * (f.a >= 0 ? x_lo : x_hi) + f.b * (f.b >= 0 ? y_lo : y_hi) + f.c;
                const std::int64_t highest = f.a * (f.a >= 0 ? x_hi : x_lo) + f.b * (f.b >= 0 ? y_hi : y_lo) + f.c;
                if (highest < 0) return TileClass::reject;
                all_inside = all_inside && lowest >= 0;
            }
            break;
        }
        case Path::floating: {
            if (!(t.float_margin < std::numeric_limits<double>::infinity())) return TileClass::partial;
            const double x_lo = i0 + c.ox_min, x_hi = i1 + c.ox_max, y_lo = j0 + c.oy_min, y_hi = j1 + c.oy_max;
            for (int k = 0; k < 3; ++k) {
                const Vertex& a = t.p.v[k];
                const Vertex& b = t.p.v[(k + 1) % 3];
                // E(p) = d1 (py - ay) - d3 (px - ax); a difference of doubles has the exact one's sign.
                const double d1 = b.x - a.x, d3 = b.y - a.y;
                const double lowest = d1 * ((d1 >= 0 ? y_lo : y_hi) - a.y) - d3 * ((d3 >= 0 ? x_hi : x_lo) - a.x);
                const double highest = d1 * ((d1 >= 0 ? y_hi : y_lo) - a.y) - d3 * ((d3 >= 0 ? x_lo : x_hi) - a.x);
                if (highest < -t.float_margin) return TileClass::reject;
                all_inside = all_inside && lowest > t.float_margin;
            }
            break;
        }
        case Path::wide: {
            // [j0, j1] is the triangle's rows in one row of tiles: one band's (SpanBand).
            const SpanBand& band = t.bands[static_cast<std::size_t>(j0 / kTile - t.p.j_lo / kTile)];
            if (band.lo_max <= i0 && band.hi_min >= i1) return TileClass::accept;
            if (band.hi_max < i0 || band.lo_min > i1) return TileClass::reject;
            return TileClass::partial;
        }
    }
    return all_inside ? TileClass::accept : TileClass::partial;
}

// The wide path's spans (spans_of) of the triangles the tiles of one row of screen tiles need them for,
// each found at the first such tile and kept for the others, which need the same rows: a big triangle
// is partial in several tiles of a row. A thread keeps them for the row it is in, and at most `kept`
// of them (more triangles' are found again when needed), so they take memory for one row of tiles,
// not for the whole screen, and not for all of a scene's triangles. Only for the render they were found
// in: Setups are named by their addresses, which a later render's may reuse.
class BandSpans {
public:
    static constexpr std::size_t kKept = std::size_t{1} << 22;  // 32 MB

    explicit BandSpans(std::size_t kept = kKept) : kept_(kept) {}
    // Setup t's spans over the pixel rows [j0, j1], all in one row of tiles (the tiles of a row ask for
    // the same rows of a triangle: its own rows there). Valid until the next call.
    std::span<const Span> of(const Setup& t, const Context& c, int j0, int j1) {
        const std::size_t count = static_cast<std::size_t>(j1 - j0 + 1) * c.offsets.size();
        if (j0 / kTile != band_) {
            clear();
            band_ = j0 / kTile;
        }
        auto [entry, fresh] = at_.try_emplace(&t);  // one lookup, found or not
        if (!fresh && entry->second.j0 == j0 && entry->second.j1 == j1)
            return std::span<const Span>(spans_).subspan(entry->second.at, count);
        if (spans_.size() + count > kept_) {
            forget();
            entry = at_.try_emplace(&t).first;
        }
        const Kept kept{spans_.size(), j0, j1};
        entry->second = kept;
        spans_.resize(spans_.size() + count);
        spans_of(t, c, j0, j1, std::span(spans_).subspan(kept.at, count));
        return std::span<const Span>(spans_).subspan(kept.at, count);
    }
    // Forgets every triangle's spans, keeping the storage.
    void clear() {
        forget();
        band_ = -1;
    }

private:
    void forget() {
        spans_.clear();
        at_.clear();
    }
    std::size_t kept_;
    int band_ = -1;  // the row of tiles, j / kTile
    std::vector<Span> spans_;
    struct Kept {
        std::size_t at;  // where in spans_
        int j0, j1;      // the rows
    };
    std::unordered_map<const Setup*, Kept> at_;
};

// One tile's z-buffer, one plane per sample index so that a sample row is contiguous for the kernels;
// kRowLanes of padding lets the last row's vector loads run past its end. Sized to the viewport's
// largest tile (a small viewport's is small) and reused from tile to tile, and by a Workspace from
// render to render. Each on cache lines of its own: the threads' buffers sit side by side in the
// Workspace, and each thread writes its own bookkeeping for every triangle.
struct alignas(64) TileBuffer {
    // For render number `render` of a Workspace, of this sample count and viewport, unless already fitted
    // for it: storage kept when large enough.
    void fit(std::uint64_t render, int samples, Viewport vp) {
        if (render == fitted_for) return;
        cols = std::min(kTile, vp.width);
        rows = std::min(kTile, vp.height);
        size = static_cast<std::size_t>(samples) * rows * cols;
        z.resize(size + kRowLanes, std::numeric_limits<double>::infinity());
        ids.resize(size + kRowLanes, Framebuffer::kNoTriangle);
        planes = ExactPlanes();  // its planes are named by the ids of the last render's scene
        wide.clear();
        fitted_for = render;
    }
    // Empty again, as DepthRows (kernels.h) defines it: z = +infinity, one bound for the whole tile.
    void clear() {
        std::fill_n(z.begin(), size, std::numeric_limits<double>::infinity());
        std::fill_n(ids.begin(), size, Framebuffer::kNoTriangle);
        stored_err = 0;
        per_sample = false;
        far = std::numeric_limits<double>::infinity();
        since_far = 0;
    }
    // A triangle whose depths have error bound e is about to be composed. The tile keeps one bound for
    // all its stored depths while they are of one order (the depth test then loads and stores a third
    // less). A bound far above the tile's (a near-degenerate triangle, or depths of a larger magnitude)
    // would make later comparisons exact, and one far below it would be compared with a bound too coarse
    // for it: from the first such triangle on, the tile keeps a bound per sample, the ones stored before
    // with the tile's. An infinite bound decides nothing: such a triangle's depths are all stored by
    // the exact comparison, each with its own bound (stored()).
    void admit(double e) {
        constexpr double kSpread = 0x1p20;
        if (!per_sample && stored_err > 0 && !(e <= kSpread * stored_err && stored_err <= kSpread * e)) {
            err.resize(size + kRowLanes);
            for (std::size_t k = 0; k < size; ++k) err[k] = ids[k] < 0 ? 0 : stored_err;
            per_sample = true;
        }
        if (e < std::numeric_limits<double>::infinity()) storing(e);
    }
    // A depth with error bound e is stored at `slot`.
    void stored(std::size_t slot, double e) {
        if (per_sample) err[slot] = e;
        storing(e);
    }
    DepthRows rows_at(std::size_t at) {
        return {z.data() + at, per_sample ? err.data() + at : nullptr, ids.data() + at, cols};
    }
    // far := the largest z over the samples of pixels [0, width) x [0, height), +infinity while any is
    // empty. Exact stored depths only ever come nearer, so an old far, with stored_err, still bounds them.
    void refresh_far(int samples, int width, int height) {
        since_far = 0;
        double largest = -std::numeric_limits<double>::infinity();
        for (int s = 0; s < samples; ++s)
            for (int row = 0; row < height; ++row) {
                largest = std::max(largest, farthest(&z[at(s, row, 0)], static_cast<std::size_t>(width)));
                if (largest == std::numeric_limits<double>::infinity()) return;
            }
        far = largest;
    }
    std::size_t at(int s, int row, int col) const {
        return (static_cast<std::size_t>(s) * rows + row) * cols + col;
    }
    std::uint64_t fitted_for = 0;  // the render fit() last fitted it for (0: none)
    int cols = 0, rows = 0;  // the row stride and rows per sample plane
    std::size_t size = 0;
    std::vector<double> z, err;  // err: each depth's bound, kept only while per_sample (admit() allocates it)
    std::vector<std::int64_t> ids;
    double stored_err = 0;  // an error bound of every depth stored since clear()
    bool per_sample = false;
    ExactPlanes planes;  // this thread's exact planes, kept from tile to tile for the whole render
    BandSpans wide;
    double far = std::numeric_limits<double>::infinity();
    std::size_t since_far = 0;  // samples of the blocks rasterized since far was computed

private:
    void storing(double e) { stored_err = std::max(stored_err, e); }
};

// A tile's far depth is brought up to date once blocks of this many times its samples were rasterized
// into it: the refresh reads the tile once, amortized over at least as many block samples.
inline constexpr std::size_t kFarRefresh = 4;

// Hierarchical z: whether the triangle is behind everything stored in the tile at every sample of
// [i0, i1] x [j0, j1]. Its plane's smallest value there is at a corner of the samples' rectangle (inside
// the bounding box its error bound covers). far bounds every depth stored since it was found (they only
// come nearer), and stored_err their distance from the exact depths; so, as in the kernels' depth test
// (the gap beyond the margin, both rounded: kernels.h), the exact depths are strictly ordered, and the
// triangle wins no sample.
inline bool behind_tile(const Plane& p, const Context& c, const TileBuffer& tile, int i0, int i1, int j0, int j1) {
    const double px = p.a >= 0 ? i0 + c.ox_min : i1 + c.ox_max;
    const double py = p.b >= 0 ? j0 + c.oy_min : j1 + c.oy_max;
    const double nearest = p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0));
    return nearest - tile.far > p.err + tile.stored_err;
}

// Pixels [i0, i1] x [j0, j1] of the viewport: one tile.
struct TileRect {
    int i0, i1, j0, j1;
};

// What the tiles need of the whole scene: the input triangles, for the exact depth order.
struct SceneView {
    std::span<const Triangle> triangles;
    const Context& c;
};

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
        const std::int64_t other = tile.ids[slot];
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

// What every path shares: triangle `id` (its depth plane; corners() answers its placed corners, which
// only the exact order reads) into the tile's z-buffer over pixels [i0, i1] x [j0, j1] of its bounding
// box, behind hierarchical z, one block per sample index. depth(b, s, plane, rows, undecided) runs the
// z-buffer test on block b of sample index s and answers whether it left samples undecided; those get
// the exact order. Always inlined: as a call of its own, its eleven arguments and the plane went through
// the stack, a tenth of a small triangle's setup.
template <Fault F, class CornersOf, class BlockDepth>
[[gnu::always_inline]] inline void rasterize_blocks(CornersOf corners, const Plane& pl, std::int32_t id, int i0,
                                                    int i1, int j0, int j1, const TileRect& rect, TileBuffer& tile,
                                                    const SceneView& scene, BlockDepth depth) {
    if constexpr (F == Fault::halved_depth_bound) {
        Plane halved = pl;
        halved.err /= 2;
        return rasterize_blocks<Fault::none>(corners, halved, id, i0, i1, j0, j1, rect, tile, scene, depth);
    }
    const Context& c = scene.c;
    if (behind_tile(pl, c, tile, i0, i1, j0, j1)) return;
    tile.since_far += static_cast<std::size_t>(i1 - i0 + 1) * (j1 - j0 + 1) * c.offsets.size();
    if (tile.since_far >= kFarRefresh * tile.size)
        tile.refresh_far(static_cast<int>(c.offsets.size()), rect.i1 - rect.i0 + 1, rect.j1 - rect.j0 + 1);
    tile.admit(pl.err);
    const DepthPlane plane{pl.z0, pl.a, pl.x0, pl.b, pl.y0, pl.err, tile.stored_err, id};
    std::uint64_t undecided[kTile];
    for (int s = 0; s < static_cast<int>(c.offsets.size()); ++s) {
        const Block b{i0, j0, i1 - i0 + 1, j1 - j0 + 1, c.offsets[s].x, c.offsets[s].y};
        const std::size_t at = tile.at(s, j0 - rect.j0, i0 - rect.i0);
        const DepthRows rows = tile.rows_at(at);
        if (!depth(b, s, plane, rows, undecided)) continue;
        decltype(auto) v = corners();  // once for the block's rows
        for (int r = 0; r < b.rows; ++r)
            if (undecided[r] != 0) resolve<F>(v, plane, b, r, undecided[r], tile, at + r * tile.cols, scene);
    }
}

// Blocks of up to this many samples are rasterized in scalar code (scalar.h).
inline constexpr int kScalarSamples = 16;

// The z-buffer test of block b for integer edges (edges, their steps) straight from a fixed setup,
// without a Coverage.
inline bool fixed_block_depth(const std::array<FixedEdge, 3>& edges, const Context& c, const Block& b, int s,
                              const DepthPlane& plane, DepthRows rows, std::uint64_t* undecided) {
    std::int64_t e[3], dx[3], dy[3];
    fixed_edges_at(edges, c, b, s, e, dx, dy);
    return depth_rows_scalar(b, [&](int r) { return fixed_row_coverage(e, dx, dy, b.width, r); }, plane, rows,
                             undecided);
}

// Triangle t, named id, into the tile's z-buffer.
template <Fault F>
void rasterize(const Setup& t, std::int32_t id, const TileRect& rect, TileBuffer& tile, const SceneView& scene) {
    const Context& c = scene.c;
    const int i0 = std::max(rect.i0, t.p.i_lo), i1 = std::min(rect.i1, t.p.i_hi);
    const int j0 = std::max(rect.j0, t.p.j_lo), j1 = std::min(rect.j1, t.p.j_hi);
    const TileClass cls = classify(t, c, i0, i1, j0, j1);
    if (cls == TileClass::reject) return;
    std::span<const Span> wide;  // a partial tile's, found at the first sample index, past hierarchical z
    std::uint64_t masks[kTile];
    rasterize_blocks<F>([&t]() -> const Corners& { return t.p.v; }, t.plane, id, i0, i1, j0, j1, rect, tile, scene,
                        [&](const Block& b, int s, const DepthPlane& plane, DepthRows rows, std::uint64_t* undecided) {
                            const bool scalar = b.width * b.rows <= kScalarSamples;
                            const bool partial = cls == TileClass::partial;
                            if (partial && t.p.path == Path::wide && wide.empty()) wide = tile.wide.of(t, c, j0, j1);
                            if (partial && t.p.path == Path::fixed && scalar)
                                return fixed_block_depth(t.fixed, c, b, s, plane, rows, undecided);
                            if (partial && t.p.path != Path::floating && !scalar) {
                                // Exact rows, one run each: the fixed path's walked from row to row, the
                                // wide path's from its spans.
                                if (t.p.path == Path::fixed) fixed_row_masks(t.fixed, c, b, s, masks);
                                else coverage_of<F>(t, c, b, s, wide, masks);
                                return depth_runs(b, masks, plane, rows, undecided);
                            }
                            const Coverage cov = partial ? coverage_of<F>(t, c, b, s, wide, masks) : Coverage{};
                            return scalar ? depth_block_scalar(b, cov, plane, rows, undecided)
                                          : depth_block(b, cov, plane, rows, undecided);
                        });
}

// A small triangle of the 64-bit fixed path, straight from its binned record and its plane: its edges
// are all else it needs, and a narrow one's edges fit the 32-bit lanes of depth_small.
template <Fault F>
void rasterize_small(const SmallFixed& t, const Plane& pl, bool narrow, const TileRect& rect, TileBuffer& tile,
                     const SceneView& scene) {
    const Context& c = scene.c;
    const int i0 = std::max(rect.i0, t.i_lo), i1 = std::min(rect.i1, t.i_hi);
    const int j0 = std::max(rect.j0, t.j_lo), j1 = std::min(rect.j1, t.j_hi);
    const std::array<FixedEdge, 3> edges = fixed_edges<F>(t.x, t.y);
    rasterize_blocks<F>([&] { return placed_of(t, c).v; }, pl, t.id, i0, i1, j0, j1, rect, tile, scene,
                        [&](const Block& b, int s, const DepthPlane& plane, DepthRows rows, std::uint64_t* undecided) {
                            if (b.width * b.rows <= kScalarSamples)
                                return fixed_block_depth(edges, c, b, s, plane, rows, undecided);
                            if (!narrow) {
                                std::uint64_t masks[kTile];
                                fixed_row_masks(edges, c, b, s, masks);
                                return depth_runs(b, masks, plane, rows, undecided);
                            }
                            std::int64_t e[3], dx[3], dy[3];
                            fixed_edges_at(edges, c, b, s, e, dx, dy);
                            SmallEdges narrow;
                            for (int k = 0; k < 3; ++k) {
                                narrow.e[k] = static_cast<std::int32_t>(e[k]);
                                narrow.dx[k] = static_cast<std::int32_t>(dx[k]);
                                narrow.dy[k] = static_cast<std::int32_t>(dy[k]);
                            }
                            return depth_small(b, narrow, plane, rows, undecided);
                        });
}

inline bool is_small(const Placed& p) { return p.path != Path::wide && is_small(p.i_lo, p.i_hi, p.j_lo, p.j_hi); }

struct SmallTriangle {
    Placed p;
    std::int32_t id;
};

// A big triangle's entry in a tile's bin: its id beside the index of its setup, so that merging the
// bins by id reads no setup it does not rasterize yet.
struct BigEntry {
    std::int32_t id;
    std::uint32_t setup;  // index into Chunk::big
};

// The triangles of one contiguous id range, binned per tile in id order.
struct Chunk {
    std::optional<std::size_t> non_finite;  // the first triangle with a non-finite coordinate: binning stopped there
    std::vector<Setup> big;
    std::vector<std::vector<SmallFixed>> fixed_bins;
    std::vector<std::vector<SmallTriangle>> small_bins;
    std::vector<std::vector<BigEntry>> big_bins;
};

// Appends to a tile's bin. The bins are written at as many places as there are tiles, each cache line
// for the first time: the line that will hold the end of the bin's next record (it starts where this one
// ended) is fetched now, for writing, rather than when that record comes (binning small triangles spent
// twice its share of instructions in time). An address, not a pointer: it may lie past the bin's
// storage, and a prefetch never faults.
template <class Record>
void append(std::vector<Record>& bin, const Record& record) {
    bin.push_back(record);
    const std::uintptr_t next_end = reinterpret_cast<std::uintptr_t>(bin.data() + bin.size()) + sizeof(Record) - 1;
    __builtin_prefetch(reinterpret_cast<const void*>(next_end), 1);
}

template <Fault F>
void bin_chunk(Chunk& chunk, std::size_t begin, std::size_t end, const SceneView& scene, std::size_t tiles_x,
               std::size_t tiles) {
    // Emptied, keeping the bins' storage of the last render (Workspace).
    chunk.non_finite.reset();
    chunk.big.clear();
    const auto empty_bins = [tiles](auto& bins) {
        bins.resize(tiles);
        for (auto& bin : bins) bin.clear();
    };
    empty_bins(chunk.fixed_bins);
    empty_bins(chunk.small_bins);
    empty_bins(chunk.big_bins);
    const bool lean = is_fixed(scene.c.precision) && scene.c.fixed_fits;
    if (lean) {
        // Room for a uniform spread with some slack, so that most bins never reallocate and copy; pages
        // of it never written are never touched.
        const std::size_t expected = (end - begin) / tiles;
        for (std::vector<SmallFixed>& bin : chunk.fixed_bins) bin.reserve(expected + expected / 2 + 8);
    }
    // Pixel indices inside the viewport are not negative: unsigned division is a shift.
    const auto tile_of = [](int pixel) { return static_cast<int>(static_cast<unsigned>(pixel) / kTile); };
    for (std::size_t id = begin; id != end; ++id) {
        const Triangle& triangle = scene.triangles[id];
        SmallFixed record;
        const Lane lane = lean ? place_small_fixed<F>(triangle, static_cast<std::int32_t>(id), scene.c, record)
                               : Lane::general;
        // Checked here rather than in a pass of its own: the triangles are read once. The small lane
        // only takes corners whose x and y are within the fixed range, hence finite.
        const bool finite = lane == Lane::general ? is_finite(triangle)
                                                  : std::isfinite(triangle.v[0].z) && std::isfinite(triangle.v[1].z) &&
                                                        std::isfinite(triangle.v[2].z);
        if (!finite) {
            chunk.non_finite = id;
            return;
        }
        if (lane == Lane::culled) continue;
        if (lane == Lane::small_fixed) {
            for (int ty = tile_of(record.j_lo); ty <= tile_of(record.j_hi); ++ty)
                for (int tx = tile_of(record.i_lo); tx <= tile_of(record.i_hi); ++tx)
                    append(chunk.fixed_bins[static_cast<std::size_t>(ty) * tiles_x + tx], record);
            continue;
        }
        const std::optional<Placed> placed = place<F>(triangle, scene.c);
        if (!placed) continue;
        const bool small = is_small(*placed);
        if (!small) chunk.big.push_back(setup_triangle<F>(*placed, scene.c, true));
        for (int ty = tile_of(placed->j_lo); ty <= tile_of(placed->j_hi); ++ty)
            for (int tx = tile_of(placed->i_lo); tx <= tile_of(placed->i_hi); ++tx) {
                const std::size_t tile = static_cast<std::size_t>(ty) * tiles_x + tx;
                if (small) append(chunk.small_bins[tile], {*placed, static_cast<std::int32_t>(id)});
                else append(chunk.big_bins[tile], {static_cast<std::int32_t>(id), static_cast<std::uint32_t>(chunk.big.size() - 1)});
            }
    }
}

// Starts loading what rasterize reads of a big triangle's setup (the fixed path's part comes first) one
// triangle ahead: the setups of a tile's triangles are scattered over the chunk, and each was a cache
// miss on first touch.
inline void prefetch(const Setup& s) {
    constexpr std::uintptr_t kLine = 64;
    const auto line_of = [](const void* p) { return reinterpret_cast<std::uintptr_t>(p) & ~(kLine - 1); };
    for (std::uintptr_t line = line_of(&s); line <= line_of(&s.classify_tiles); line += kLine)
        __builtin_prefetch(reinterpret_cast<const void*>(line));
}

template <Fault F>
void render_tile(std::span<const Chunk> chunks, std::size_t index, const TileRect& rect, TileBuffer& tile,
                 const SceneView& scene, Framebuffer& fb) {
    const int samples = static_cast<int>(scene.c.offsets.size());
    const int width = rect.i1 - rect.i0 + 1;
    // A tile no triangle reaches is written empty straight into the framebuffer, where its pixels' samples
    // are contiguous row by row: clearing the tile buffer and copying it out moves its bytes twice more
    // (2.5 ms for a 1024 x 1024 screen on one thread, half the time of a mesh that leaves most tiles empty).
    const bool empty = std::all_of(chunks.begin(), chunks.end(), [index](const Chunk& chunk) {
        return chunk.fixed_bins[index].empty() && chunk.small_bins[index].empty() && chunk.big_bins[index].empty();
    });
    if (empty) {
        const std::size_t row = static_cast<std::size_t>(width) * samples;
        for (int j = rect.j0; j <= rect.j1; ++j) {
            std::fill_n(fb.ids.begin() + fb.index(rect.i0, j), row, Framebuffer::kNoTriangle);
            std::fill_n(fb.depth.begin() + fb.index(rect.i0, j), row, std::numeric_limits<double>::infinity());
        }
        return;
    }
    tile.clear();
    constexpr std::int32_t kEnd = std::numeric_limits<std::int32_t>::max();  // above every id (render checks)
    for (const Chunk& chunk : chunks) {
        const std::vector<SmallFixed>& fixed = chunk.fixed_bins[index];
        const std::vector<SmallTriangle>& small = chunk.small_bins[index];
        const std::vector<BigEntry>& big = chunk.big_bins[index];
        // The three lists are in id order; merged, the tile composes all its triangles in id order. The
        // common lane's triangles before the next of the other two go in one tight loop, their planes set
        // up kPlaneBatch at a time.
        for (std::size_t f = 0, a = 0, b = 0;;) {
            const std::int32_t next_small = a < small.size() ? small[a].id : kEnd;
            const std::int32_t next_big = b < big.size() ? big[b].id : kEnd;
            const std::int32_t next_other = std::min(next_small, next_big);
            while (f < fixed.size() && fixed[f].id < next_other) {
                std::size_t n = 1;
                while (n < kPlaneBatch && f + n < fixed.size() && fixed[f + n].id < next_other) ++n;
                Plane planes[kPlaneBatch];
                bool narrow[kPlaneBatch];
                small_planes({fixed.data() + f, n}, scene.c, planes, narrow);
                for (std::size_t k = 0; k < n; ++k)
                    rasterize_small<F>(fixed[f + k], planes[k], narrow[k], rect, tile, scene);
                f += n;
            }
            if (next_other == kEnd) break;
            if (next_small < next_big) {
                rasterize<F>(setup_triangle<F>(small[a].p, scene.c, false), small[a].id, rect, tile, scene);
                ++a;
            } else {
                if (b + 1 < big.size()) prefetch(chunk.big[big[b + 1].setup]);
                rasterize<F>(chunk.big[big[b].setup], big[b].id, rect, tile, scene);
                ++b;
            }
        }
    }
    for (int j = rect.j0; j <= rect.j1; ++j)
        for (int s = 0; s < samples; ++s) {
            const std::int64_t* ids = tile.ids.data() + tile.at(s, j - rect.j0, 0);
            const double* z = tile.z.data() + tile.at(s, j - rect.j0, 0);
            std::int32_t* to_ids = fb.ids.data() + fb.index(rect.i0, j, s);
            double* to_depth = fb.depth.data() + fb.index(rect.i0, j, s);
            if (samples == 1) {  // contiguous on both sides: copies the compiler vectorizes
                std::transform(ids, ids + width, to_ids, [](std::int64_t id) { return static_cast<std::int32_t>(id); });
                std::copy(z, z + width, to_depth);
                continue;
            }
            for (int k = 0; k < width; ++k) {
                to_ids[k * samples] = static_cast<std::int32_t>(ids[k]);
                to_depth[k * samples] = z[k];
            }
        }
}

// Storage for the scene's samples, kept when fb already has the size: every sample is written anyway
// (render_tile copies whole tiles).
inline void fit(Framebuffer& fb, Viewport vp, int samples) {
    const std::size_t size = static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height) *
                             static_cast<std::size_t>(samples);
    fb.viewport = vp;
    fb.samples = samples;
    fb.ids.resize(size);
    fb.depth.resize(size);
}

// What a render allocates, kept by a Renderer for the next one: the chunks' bins, a tile buffer per
// thread and the threads' arena (Renderer, fast.h, says why).
struct Workspace {
    std::vector<Chunk> chunks;
    // One per thread of the arena, by its index there, fitted by the thread's first tile of a render (a
    // thread that gets no tile costs nothing).
    std::vector<TileBuffer> tiles;
    std::uint64_t renders = 0;
    std::unique_ptr<tbb::task_arena> arena;
    int arena_threads = -1;  // Options::threads the arena was made for
};

// max_threads (fast.h).
inline int thread_limit() {
    return static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

template <Fault F>
void render_scene(const Scene& scene, const Options& options, Framebuffer& fb, Workspace& ws) {
    validate(scene.viewport, scene.samples);
    validate(options.precision);
    validate_threads(options.threads);
    if (scene.triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw std::invalid_argument("rast::fast: more triangles than 32-bit ids can name");
    const std::vector<std::int32_t> ids = scene.lines.empty() ? std::vector<std::int32_t>{} : checked_lines(scene);

    const Context c = make_context<F>(scene.viewport, scene.samples, options.precision);
    const SceneView view{scene.triangles, c};
    // Up to 2^18 tiles each way: their count needs 64 bits.
    const std::size_t tiles_x = static_cast<std::size_t>(c.vp.width + kTile - 1) / kTile;
    const std::size_t tiles = tiles_x * static_cast<std::size_t>((c.vp.height + kTile - 1) / kTile);

    if (!ws.arena || ws.arena_threads != options.threads) {
        const int concurrency = options.threads == 0 ? int{tbb::task_arena::automatic}
                                                     : std::min(options.threads, thread_limit());
        ws.arena = std::make_unique<tbb::task_arena>(concurrency);
        ws.arena_threads = options.threads;
    }
    tbb::task_arena& arena = *ws.arena;
    // Contiguous id ranges, binned in parallel; every tile visits them in order, so it still composes
    // its triangles in id order, whatever the number of chunks. Binning sets up the big triangles, so
    // a scene of a few thousand of them already needs it shared out: rast bench's 2000 huge ones (wide
    // path, exact spans) spend half their instructions there. The count is a multiple of the workers,
    // so that chunks of equal size share out evenly (2000 huge triangles in 7 chunks kept one of two
    // threads binning 4/7 of the time): one per worker, up to four where each still gets
    // kChunkTriangles. A chunk costs about 10^5 instructions of its own (a bin per tile, merged per
    // tile), which the bunny's 3674 triangles in 8 chunks did not earn back. A scene too small to give
    // every worker kMinChunkTriangles is binned in as many chunks as it fills.
    const std::size_t n = scene.triangles.size();
    constexpr std::size_t kChunkTriangles = 1024, kMinChunkTriangles = 128;
    const std::size_t workers = static_cast<std::size_t>(arena.max_concurrency());
    const std::size_t chunk_count =
        workers == 1 ? 1
                     : std::min(workers * std::clamp<std::size_t>(n / (kChunkTriangles * workers), 1, 4),
                                std::max<std::size_t>(1, n / kMinChunkTriangles));
    std::vector<Chunk>& chunks = ws.chunks;
    chunks.resize(chunk_count);
    ws.tiles.resize(workers);
    const std::uint64_t render = ++ws.renders;
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunk_count, 1), [&](const auto& r) {
            for (std::size_t k = r.begin(); k != r.end(); ++k)
                bin_chunk<F>(chunks[k], k * n / chunk_count, (k + 1) * n / chunk_count, view, tiles_x, tiles);
        });
    });
    // The chunks are in id order, so the first one that stopped holds the first bad triangle. The
    // framebuffer is untouched until the scene is known to be valid.
    for (const Chunk& chunk : chunks)
        if (chunk.non_finite) validate(scene.triangles[*chunk.non_finite], *chunk.non_finite);
    fit(fb, c.vp, scene.samples);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles, 1), [&](const auto& r) {
            TileBuffer& tile = ws.tiles.at(static_cast<std::size_t>(tbb::this_task_arena::current_thread_index()));
            tile.fit(render, scene.samples, c.vp);
            for (std::size_t index = r.begin(); index != r.end(); ++index) {
                const int i0 = static_cast<int>(index % tiles_x) * kTile, j0 = static_cast<int>(index / tiles_x) * kTile;
                const TileRect rect{i0, std::min(i0 + kTile, c.vp.width) - 1, j0, std::min(j0 + kTile, c.vp.height) - 1};
                render_tile<F>(chunks, index, rect, tile, view, fb);
            }
        });
    });
    if (!scene.lines.empty()) draw_lines(scene, c, ids, fb);
}

template <Fault F>
std::vector<std::size_t> covered_by(const Triangle& triangle, Viewport vp, int samples, Precision precision) {
    validate(vp, samples);
    validate(precision);
    validate(triangle, 0);
    const Context c = make_context<F>(vp, samples, precision);
    std::vector<std::size_t> out;
    const std::optional<Placed> placed = place<F>(triangle, c);
    if (!placed) return out;
    const Setup t = setup_triangle<F>(*placed, c, false);
    std::uint64_t masks[kTile], covered[kTile];
    std::vector<Span> wide;
    for (int j0 = t.p.j_lo; j0 <= t.p.j_hi; j0 += kTile) {
        const int rows = std::min(kTile, t.p.j_hi - j0 + 1);
        if (t.p.path == Path::wide) {
            wide.resize(static_cast<std::size_t>(rows) * samples);
            spans_of(t, c, j0, j0 + rows - 1, wide);
        }
        for (int s = 0; s < samples; ++s)
            for (int i0 = t.p.i_lo; i0 <= t.p.i_hi; i0 += kTile) {
                const Block b{i0, j0, std::min(kTile, t.p.i_hi - i0 + 1), rows, c.offsets[s].x, c.offsets[s].y};
                coverage_block(b, coverage_of<F>(t, c, b, s, wide, masks), covered);
                for (int r = 0; r < b.rows; ++r)
                    for (std::uint64_t m = covered[r]; m != 0; m &= m - 1) {
                        const std::size_t i = static_cast<std::size_t>(i0 + std::countr_zero(m));
                        out.push_back((static_cast<std::size_t>(j0 + r) * vp.width + i) * samples + s);
                    }
            }
    }
    std::sort(out.begin(), out.end());
    return out;
}
}  // namespace rast::fast::detail
