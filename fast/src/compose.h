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

namespace rast::fast::detail {

// Pixels [i0, i1] x [j0, j1] of the viewport: one tile.
struct TileRect {
    int i0, i1, j0, j1;
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

// rasterize_blocks for a small triangle's binned record over its box within the tile; its corners are
// placed again only if the exact order needs them.
template <Fault F, class BlockDepth>
[[gnu::always_inline]] inline void rasterize_record(const SmallFixed& t, const Plane& pl, const TileRect& rect,
                                                    TileBuffer& tile, const SceneView& scene, BlockDepth depth) {
    const int i0 = std::max(rect.i0, t.i_lo), i1 = std::min(rect.i1, t.i_hi);
    const int j0 = std::max(rect.j0, t.j_lo), j1 = std::min(rect.j1, t.j_hi);
    const Context& c = scene.c;
    rasterize_blocks<F>([&] { return placed_of(t, c).v; }, pl, t.id, i0, i1, j0, j1, rect, tile, scene, depth);
}

// A small triangle of the 64-bit fixed path, straight from its binned record and its plane: its edges
// are all else it needs, and a narrow one's edges fit the 32-bit lanes of depth_small.
template <Fault F>
void rasterize_small(const SmallFixed& t, const Plane& pl, bool narrow, const TileRect& rect, TileBuffer& tile,
                     const SceneView& scene) {
    const Context& c = scene.c;
    const std::array<FixedEdge, 3> edges = fixed_edges<F>(t.x, t.y);
    rasterize_record<F>(t, pl, rect, tile, scene,
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

// The largest sample count (sample_pattern, rast/scene.h).
inline constexpr int kMaxSamples = 16;

// The stamps of a run of small triangles in a tile (stamp.h), for every sample index.
struct StampMasks {
    std::uint32_t triangles = 0;  // bit k: run[k] has stamps
    std::uint64_t masks[kMaxSamples][kPlaneBatch];
    void find(const PlaneBatch& batch, std::uint32_t narrow, const TileRect& rect, const Context& c) {
        for (std::size_t s = 0; s < c.offsets.size(); ++s) {
            const StampGrid grid{rect.i0, rect.i1, rect.j0, rect.j1, c.bits, static_cast<std::int32_t>(c.sx[s]),
                                 static_cast<std::int32_t>(c.sy[s])};
            triangles = stamp_masks(batch, narrow, grid, masks[s]);  // the same at every sample index
        }
    }
};

// rasterize_small for triangle k of a run whose stamps were found: the scalar depth test on the mask's bits.
template <Fault F>
void rasterize_stamp(const SmallFixed& t, const Plane& pl, const StampMasks& stamps, std::size_t k,
                     const TileRect& rect, TileBuffer& tile, const SceneView& scene) {
    rasterize_record<F>(t, pl, rect, tile, scene,
                        [&](const Block& b, int s, const DepthPlane& plane, DepthRows rows, std::uint64_t* undecided) {
                            const std::uint64_t mask = stamps.masks[s][k];
                            return depth_rows_scalar(
                                b, [mask](int r) { return mask >> (kStampSide * r) & first_bits(kStampSide); }, plane,
                                rows, undecided);
                        });
}

}  // namespace rast::fast::detail
