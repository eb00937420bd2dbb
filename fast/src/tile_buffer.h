// A thread's tile, one stage of the fast path (engine.h): its z-buffer with the depths' error bounds, its
// hierarchical-z far depth, its exact planes, and the wide path's spans it keeps for a row of tiles.
#pragma once

#include "exact.h"
#include "kernels.h"
#include "setup.h"
#include "spans.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <unordered_map>
#include <vector>

namespace rast::fast::detail {

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
        fill_far(z.data(), size);
        std::fill_n(ids.begin(), size, Framebuffer::kNoTriangle);
        stored_err = 0;
        per_sample = false;
        far = std::numeric_limits<double>::infinity();
        std::fill_n(subtile_far, kSubtiles * kSubtiles, far);
        subtiles_due = false;
        since_far = 0;
    }
    // A triangle whose depths have error bound e is about to be composed. The tile keeps one bound for
    // all its stored depths while they are of one order (the depth test then loads and stores a third
    // less). A bound far above the tile's (a near-degenerate triangle, or depths of a larger magnitude)
    // would make later comparisons exact, and one far below it would be compared with a bound too coarse
    // for it: from the first such triangle on, the tile keeps a bound per sample, the ones stored before
    // with the tile's. An infinite bound decides nothing: such a triangle's depths are all stored by
    // the exact comparison, each with its own bound (stored()).
    [[gnu::always_inline]] void admit(double e) {  // as a call, 1% of a small triangle's instructions
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
    // empty, and subtile_far on the way, band by band of subtiles: read only up to the first band with an
    // empty sample (subtile_far is then due). A tile of big triangles tests their subtiles next, and a
    // second pass for them had cost 3% of a scene of them. Exact stored depths only ever come nearer, so
    // an old far, with stored_err, still bounds them.
    void refresh_far(int samples, int width, int height) {
        since_far = 0;
        refresh_bands(samples, width, height, true);
    }
    // subtile_far, and far with it, brought up to date over the same samples: the whole tile read, for
    // the triangles that test subtiles alone.
    void refresh_subtiles(int samples, int width, int height) { refresh_bands(samples, width, height, false); }
    std::size_t at(int s, int row, int col) const {
        return (static_cast<std::size_t>(s) * rows + row) * cols + col;
    }
    std::uint64_t fitted_for = 0;  // the render fit() last fitted it for (0: none)
    int cols = 0, rows = 0;  // the row stride and rows per sample plane
    std::size_t size = 0;
    Samples<double> z, err;  // err: each depth's bound, kept only while per_sample (admit() allocates it)
    Samples<std::int32_t> ids;
    double stored_err = 0;  // an error bound of every depth stored since clear()
    bool per_sample = false;
    ExactPlanes planes;  // this thread's exact planes, kept from tile to tile for the whole render
    BandSpans wide;
    // Hierarchical z: the largest z of the tile's stored samples (+infinity while any is empty), and of
    // each subtile's (subtile_far[kSubtiles by + bx] for pixels [kSubtile bx, kSubtile (bx + 1)) x
    // [kSubtile by, kSubtile (by + 1)) of the tile), as of their last refresh.
    static_assert(kSubtiles * kSubtile == kTile && kSubtiles * kSubtiles <= 64, "a subtile is a bit of a mask");
    double far = std::numeric_limits<double>::infinity();
    double subtile_far[kSubtiles * kSubtiles];
    bool subtiles_due = false;  // whether refresh_far stopped at an empty band: the later bands' are old
    std::size_t since_far = 0;  // samples of the blocks rasterized since far was computed

private:
    void storing(double e) { stored_err = std::max(stored_err, e); }
    // refresh_subtiles(), or refresh_far()'s pass when stop_at_empty.
    void refresh_bands(int samples, int width, int height, bool stop_at_empty) {
        subtiles_due = false;
        double largest = -std::numeric_limits<double>::infinity();
        for (int y = 0; y < height; y += kSubtile) {
            double* band = subtile_far + y / kSubtile * kSubtiles;
            const int rows = std::min(kSubtile, height - y);
            for (int s = 0; s < samples; ++s) {
                double of_s[kSubtiles];
                farthest_subtiles(&z[at(s, y, 0)], cols, width, rows, s == 0 ? band : of_s);
                if (s > 0)
                    for (int k = 0; k * kSubtile < width; ++k) band[k] = std::max(band[k], of_s[k]);
            }
            for (int k = 0; k * kSubtile < width; ++k) largest = std::max(largest, band[k]);
            if (stop_at_empty && largest == std::numeric_limits<double>::infinity()) {
                subtiles_due = true;
                break;
            }
        }
        far = largest;
    }
};

// A tile's far depth is brought up to date once blocks of this many times its samples were rasterized
// into it (its subtiles' when a triangle next tests them): the refresh reads the tile once, amortized over
// at least as many block samples. Big triangles give the subtiles they cover a far depth of their own
// (cover_subtiles), so the tile is read half as often as before that (4 x): 3% less time on the MOC
// peer's large triangles, the bench's scenes within the noise.
inline constexpr std::size_t kFarRefresh = 8;

// Hierarchical z: whether the triangle is behind everything stored in the tile at every sample of
// [i0, i1] x [j0, j1]. Its plane's smallest value there is at a corner of the samples' rectangle (inside
// the bounding box its error bound covers). far bounds every depth stored since it was found (they only
// come nearer), and stored_err their distance from the exact depths; so, as in the kernels' depth test
// (the gap beyond the margin, both rounded: kernels.h), the exact depths are strictly ordered, and the
// triangle wins no sample.
// The corner is picked by masking bits, without a branch (the compiler turns a conditional back into
// one): the plane's slopes change sign at random from triangle to triangle, and the branches on them,
// mispredicted half the time, took over a tenth of a tiny triangle's time.
inline bool behind_tile(const Plane& p, const Context& c, const TileBuffer& tile, int i0, int i1, int j0, int j1) {
    // A tile that had an empty sample at its far depth's last refresh hides nothing by it: no test (random
    // small triangles leave most tiles so).
    if (tile.far == std::numeric_limits<double>::infinity()) return false;
    const auto nearer = [](bool low, double lo, double hi) {
        const std::uint64_t pick_lo = std::uint64_t{0} - low;
        return std::bit_cast<double>((std::bit_cast<std::uint64_t>(lo) & pick_lo) |
                                     (std::bit_cast<std::uint64_t>(hi) & ~pick_lo));
    };
    const double px = nearer(p.a >= 0, i0 + c.ox_min, i1 + c.ox_max);
    const double py = nearer(p.b >= 0, j0 + c.oy_min, j1 + c.oy_max);
    const double nearest = p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0));
    return nearest - tile.far > p.err + tile.stored_err;
}

// The subtiles whose part of [i0, i1] x [j0, j1] (pixels of the tile whose corner is pixel (ti, tj)) the
// triangle may be in front in, not behind everything stored there as behind_tile decides it for the whole
// tile, as bit kSubtiles by + bx for subtile (bx, by) (open_subtiles): a big triangle's box meets many
// subtiles, and far behind some while in front in others, it is behind the tile's far depth nowhere.
inline std::uint64_t in_front_subtiles(const Plane& p, const Context& c, const TileBuffer& tile, int ti, int tj,
                                       int i0, int i1, int j0, int j1) {
    const SubtileTest test{p.z0,     p.a,      p.x0,     p.b, p.y0, p.err + tile.stored_err,
                           c.ox_min, c.ox_max, c.oy_min, c.oy_max, ti, tj, i0, i1, j0, j1};
    return open_subtiles(test, tile.subtile_far);
}

// After big triangle t (the fixed path's, the wide path's with near edges, or the float modes' with a
// whole-tile margin) was composed into the tile whose corner is pixel (ti, tj), over pixels [i0, i1] x
// [j0, j1] of its box: the whole subtiles there whose samples it all covers take their far depth from its
// plane (lower_covered_subtiles), and the tile's far depth the largest of its subtiles'.
// A far depth f must keep every exact depth stored under it at most f + stored_err (behind_tile). At
// each such sample the (z, id) order left a depth no farther than the plane's exact one, which is within
// err of its double one, and the tile admitted err (stored_err >= err); rounding is monotone, so the
// double depths are largest at the corner the slopes pick (as open_subtiles' nearest): that is f.
inline void cover_subtiles(const Setup& t, const Context& c, TileBuffer& tile, int ti, int tj, int i0, int i1, int j0,
                           int j1) {
    const Plane& p = t.plane;
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const bool floating = t.p.path == Path::floating;
    if (!(p.err < kInfinity) || (floating && !(t.float_margin < kInfinity)) || (t.p.path == Path::wide && !t.near))
        return;
    const int bx0 = (i0 - ti + kSubtile - 1) / kSubtile, bx1 = (i1 - ti + 1) / kSubtile - 1;
    const int by0 = (j0 - tj + kSubtile - 1) / kSubtile, by1 = (j1 - tj + 1) / kSubtile - 1;
    if (bx0 > bx1 || by0 > by1) return;
    SubtileCover cover{.z0 = p.z0, .a = p.a, .x0 = p.x0, .b = p.b, .y0 = p.y0,
                       .ox_min = c.ox_min, .ox_max = c.ox_max, .oy_min = c.oy_min, .oy_max = c.oy_max,
                       .floating = floating, .ti = ti, .tj = tj, .bx0 = bx0, .bx1 = bx1, .by0 = by0, .by1 = by1};
    if (floating) {
        for (int e = 0; e < 3; ++e) {
            const DoubleEdge edge = double_edge(t.p.v, e);  // as classify takes it
            cover.ax[e] = edge.ax;
            cover.ay[e] = edge.ay;
            cover.d1[e] = edge.d1;
            cover.d3[e] = edge.d3;
        }
        cover.margin = t.float_margin;
    } else {
        const int x = ti + bx0 * kSubtile, y = tj + by0 * kSubtile;
        const TileRect first{x, x + kSubtile - 1, y, y + kSubtile - 1};  // subtile (bx0, by0)
        if (t.near) {
            for (std::size_t e = 0; e < 3; ++e) {  // in pixel steps
                const WideEdge& f = (*t.near)[e];
                cover.lowest[e] = clamped(least_over(f, first));
                cover.across[e] = f.a * kSubtile;
                cover.down[e] = f.b * kSubtile;
            }
        } else {
            const FixedRect samples = samples_rect(c, first.i0, first.i1, first.j0, first.j1);
            const std::int64_t step = std::int64_t{kSubtile} << c.bits;
            for (std::size_t e = 0; e < 3; ++e) {
                cover.lowest[e] = least_over(t.fixed[e], samples);
                cover.across[e] = t.fixed[e].a * step;
                cover.down[e] = t.fixed[e].b * step;
            }
        }
    }
    lower_covered_subtiles(cover, tile.subtile_far);
    tile.far = std::min(tile.far, farthest(tile.subtile_far, kSubtiles * kSubtiles));
}

}  // namespace rast::fast::detail
