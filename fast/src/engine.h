// The rasterizer proper: screen tiles of 64 x 64 pixels, binned triangles composed in id order per tile,
// trivial reject / accept per tile for the integer path, SIMD rows inside. Templated on the injected
// fault; render.cpp instantiates Fault::none, the testing target the others.
#pragma once

#include "kernels.h"
#include "setup.h"

#include <rast/fast.h>
#include <rast/fast_faults.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace rast::fast::detail {

inline constexpr int kTile = kRowLanes;  // a tile row is one kernel row

inline void validate(Viewport vp, int samples) {
    constexpr int kMaxSide = 1 << 24;  // pixel indices convert exactly to float in the float32 kernel
    if (vp.width < 1 || vp.height < 1 || vp.width > kMaxSide || vp.height > kMaxSide)
        throw std::invalid_argument("rast::fast: viewport " + std::to_string(vp.width) + "x" +
                                    std::to_string(vp.height) + " is not 1..2^24 pixels on each side");
    if (!is_supported_sample_count(samples))
        throw std::invalid_argument("rast::fast: unsupported sample count " + std::to_string(samples) +
                                    " (expected 1, 4, 8 or 16)");
}

inline void validate(const Triangle& t, std::size_t id) {
    for (int k = 0; k < 3; ++k) {
        const Vertex& p = t.v[k];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("rast::fast: triangle " + std::to_string(id) + ", vertex " +
                                        std::to_string(k) + ": coordinate is not a finite number");
    }
}

inline std::uint64_t span_bits(int from, int to, int i0) {
    if (from > to) return 0;
    const int n = to - from + 1;
    const std::uint64_t run = n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
    return run << (from - i0);
}

template <class T>
std::uint64_t float_row_accumulated(const FloatEdgeRow<T>* edges, int i0, T sx, int n) {
    std::uint64_t covered = n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
    for (int e = 0; e < 3; ++e) {
        const FloatEdgeRow<T>& edge = edges[e];
        T value = edge.t1 - edge.d3 * (T(i0 + sx) - edge.ax);
        for (int k = 0; k < n; ++k, value -= edge.d3)
            if (!(value > 0 || (value == 0 && edge.inclusive))) covered &= ~(std::uint64_t{1} << k);
    }
    return covered;
}

template <Fault F, class T>
std::uint64_t float_row(const Setup& t, const Context& c, int j, int s, int i0, int n) {
    const T py = T(j + c.offsets[s].y);
    const T sx = T(c.offsets[s].x);
    FloatEdgeRow<T> rows[3];
    for (int e = 0; e < 3; ++e) {
        const FloatEdge& f = t.flt[e];
        rows[e] = {T(f.ax), T(f.d3), T(T(f.d1) * T(py - T(f.ay))), f.inclusive};
    }
    if constexpr (F == Fault::float_row_accumulation) return float_row_accumulated<T>(rows, i0, sx, n);
    else if constexpr (std::is_same_v<T, float>) return coverage_float32(rows, i0, sx, n);
    else return coverage_float64(rows, i0, sx, n);
}

// Bit k: triangle t covers sample s of pixel (i0 + k, j); n <= 64 pixels, all inside the bounding box.
template <Fault F>
std::uint64_t row_mask(const Setup& t, const Context& c, int j, int s, int i0, int n) {
    switch (t.path) {
        case Path::fixed: {
            const std::int64_t x = (std::int64_t{i0} << c.bits) + c.sx[s];
            const std::int64_t y = (std::int64_t{j} << c.bits) + c.sy[s];
            std::int64_t base[3], step[3];
            for (int e = 0; e < 3; ++e) {
                const FixedEdge& f = t.fixed[e];
                base[e] = f.a * x + f.b * y + f.c;
                step[e] = f.a << c.bits;
            }
            return coverage_fixed(base, step, n);
        }
        case Path::wide: {
            const Span& span = t.spans[static_cast<std::size_t>(j - t.j_lo) * c.offsets.size() + s];
            return span_bits(std::max(span.lo, i0), std::min(span.hi, i0 + n - 1), i0);
        }
        case Path::floating:
            return c.precision == Precision::float32 ? float_row<F, float>(t, c, j, s, i0, n)
                                                     : float_row<F, double>(t, c, j, s, i0, n);
    }
    return 0;
}

enum class TileClass { reject, accept, partial };

// The Larrabee test on the samples of pixels [i0, i1] x [j0, j1]: an edge function is linear, so its
// extremes over the samples' bounding rectangle are at corners chosen by the signs of a and b.
inline TileClass classify(const Setup& t, const Context& c, int i0, int i1, int j0, int j1) {
    if (t.path != Path::fixed) return TileClass::partial;
    const std::int64_t x_lo = (std::int64_t{i0} << c.bits) + c.sx_min, x_hi = (std::int64_t{i1} << c.bits) + c.sx_max;
    const std::int64_t y_lo = (std::int64_t{j0} << c.bits) + c.sy_min, y_hi = (std::int64_t{j1} << c.bits) + c.sy_max;
    bool all_inside = true;
    for (const FixedEdge& f : t.fixed) {
        const std::int64_t lowest = f.a * (f.a >= 0 ? x_lo : x_hi) + f.b * (f.b >= 0 ? y_lo : y_hi) + f.c;
        const std::int64_t highest = f.a * (f.a >= 0 ? x_hi : x_lo) + f.b * (f.b >= 0 ? y_hi : y_lo) + f.c;
        if (highest < 0) return TileClass::reject;
        all_inside = all_inside && lowest >= 0;
    }
    return all_inside ? TileClass::accept : TileClass::partial;
}

// One tile's z-buffer, one plane per sample index so that a sample row is contiguous for the kernels;
// kRowLanes of padding lets the last row's vector loads run past its end.
struct TileBuffer {
    explicit TileBuffer(int samples)
        : size(static_cast<std::size_t>(samples) * kTile * kTile),
          z(size + kRowLanes, std::numeric_limits<double>::infinity()),
          err(size + kRowLanes, 0.0),
          ids(size + kRowLanes, Framebuffer::kNoTriangle) {}
    std::size_t at(int s, int row, int col) const {
        return (static_cast<std::size_t>(s) * kTile + row) * kTile + col;
    }
    std::size_t size;
    std::vector<double> z, err;
    std::vector<std::int64_t> ids;
};

// The samples the filtered test could not order: the exact (z, id) order, or the injected bug.
template <Fault F>
void resolve(std::span<const Setup> setups, std::int32_t id, const DepthRow& row, double py,
             std::uint64_t undecided, TileBuffer& tile, std::size_t at) {
    const Setup& t = setups[id];
    for (; undecided != 0; undecided &= undecided - 1) {
        const int k = std::countr_zero(undecided);
        const double px = double(row.i0 + k) + row.sx;
        const double z = row.z0 + (row.a * (px - row.x0) + row.b_dy);
        const std::size_t slot = at + k;
        const std::int64_t other = tile.ids[slot];
        bool replace = other < 0;
        if (!replace) {
            if constexpr (F == Fault::depth_less_equal) {
                replace = z <= tile.z[slot];
            } else {
                const int order = compare_depth(t.v, setups[other].v, px, py);
                const bool wins_tie = F == Fault::no_id_tiebreak || id < other;
                replace = order < 0 || (order == 0 && wins_tie);
            }
        }
        if (!replace) continue;
        const bool finite = std::isfinite(z);
        tile.z[slot] = finite ? z : exact_depth(t.v, px, py);
        tile.err[slot] = finite ? row.err : 4 * kUnitDouble * kSlack * std::abs(tile.z[slot]) + 4 * DBL_TRUE_MIN;
        tile.ids[slot] = id;
    }
}

template <Fault F>
void render_tile(std::span<const Setup> setups, std::span<const std::int32_t> bin, const Context& c,
                 int tx, int ty, Framebuffer& fb) {
    const int samples = static_cast<int>(c.offsets.size());
    const int ti0 = tx * kTile, tj0 = ty * kTile;
    const int ti1 = std::min(ti0 + kTile, c.vp.width) - 1, tj1 = std::min(tj0 + kTile, c.vp.height) - 1;
    TileBuffer tile(samples);
    for (const std::int32_t id : bin) {
        const Setup& t = setups[id];
        const int i0 = std::max(ti0, t.i_lo), i1 = std::min(ti1, t.i_hi);
        const int j0 = std::max(tj0, t.j_lo), j1 = std::min(tj1, t.j_hi);
        const TileClass cls = classify(t, c, i0, i1, j0, j1);
        if (cls == TileClass::reject) continue;
        const int n = i1 - i0 + 1;
        const std::uint64_t full = span_bits(i0, i1, i0);
        for (int s = 0; s < samples; ++s) {
            for (int j = j0; j <= j1; ++j) {
                const std::uint64_t covered = cls == TileClass::accept ? full : row_mask<F>(t, c, j, s, i0, n);
                if (covered == 0) continue;
                const double py = j + c.offsets[s].y;
                const DepthRow row{t.plane.z0, t.plane.a, t.plane.b * (py - t.plane.y0), t.plane.x0,
                                   t.plane.err, id, i0, c.offsets[s].x};
                const std::size_t at = tile.at(s, j - tj0, i0 - ti0);
                const std::uint64_t undecided =
                    depth_row(row, covered, tile.z.data() + at, tile.err.data() + at, tile.ids.data() + at);
                if (undecided != 0) resolve<F>(setups, id, row, py, undecided, tile, at);
            }
        }
    }
    for (int j = tj0; j <= tj1; ++j)
        for (int i = ti0; i <= ti1; ++i)
            for (int s = 0; s < samples; ++s) {
                const std::size_t from = tile.at(s, j - tj0, i - ti0), to = fb.index(i, j, s);
                fb.ids[to] = static_cast<std::int32_t>(tile.ids[from]);
                fb.depth[to] = tile.z[from];
            }
}

template <Fault F>
Framebuffer render_scene(const Scene& scene, const Options& options) {
    validate(scene.viewport, scene.samples);
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) validate(scene.triangles[id], id);
    if (options.threads < 0)
        throw std::invalid_argument("rast::fast: thread count " + std::to_string(options.threads) +
                                    " is negative");
    if (scene.triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw std::invalid_argument("rast::fast: more triangles than 32-bit ids can name");

    const Context c = make_context<F>(scene.viewport, scene.samples, options.precision);
    const int tiles_x = (c.vp.width + kTile - 1) / kTile, tiles_y = (c.vp.height + kTile - 1) / kTile;
    std::vector<Setup> setups(scene.triangles.size());
    std::vector<std::vector<std::int32_t>> bins(static_cast<std::size_t>(tiles_x) * tiles_y);
    Framebuffer fb(c.vp, scene.samples);

    tbb::task_arena arena(options.threads == 0 ? tbb::task_arena::automatic : options.threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, setups.size(), 256), [&](const auto& r) {
            for (std::size_t id = r.begin(); id != r.end(); ++id)
                setups[id] = setup_triangle<F>(scene.triangles[id], c);
        });
        // Binning in id order is what makes every tile compose its triangles in id order.
        for (std::size_t id = 0; id < setups.size(); ++id) {
            const Setup& t = setups[id];
            if (t.empty) continue;
            for (int ty = t.j_lo / kTile; ty <= t.j_hi / kTile; ++ty)
                for (int tx = t.i_lo / kTile; tx <= t.i_hi / kTile; ++tx)
                    bins[static_cast<std::size_t>(ty) * tiles_x + tx].push_back(static_cast<std::int32_t>(id));
        }
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y, 1), [&](const auto& r) {
            for (int tile = r.begin(); tile != r.end(); ++tile)
                render_tile<F>(setups, bins[tile], c, tile % tiles_x, tile / tiles_x, fb);
        });
    });
    return fb;
}

template <Fault F>
std::vector<std::size_t> covered_by(const Triangle& triangle, Viewport vp, int samples, Precision precision) {
    validate(vp, samples);
    validate(triangle, 0);
    const Context c = make_context<F>(vp, samples, precision);
    const Setup t = setup_triangle<F>(triangle, c);
    std::vector<std::size_t> out;
    if (t.empty) return out;
    for (int s = 0; s < samples; ++s)
        for (int j = t.j_lo; j <= t.j_hi; ++j)
            for (int i0 = t.i_lo; i0 <= t.i_hi; i0 += kRowLanes) {
                const int n = std::min(kRowLanes, t.i_hi - i0 + 1);
                for (std::uint64_t m = row_mask<F>(t, c, j, s, i0, n); m != 0; m &= m - 1) {
                    const std::size_t i = static_cast<std::size_t>(i0 + std::countr_zero(m));
                    out.push_back((static_cast<std::size_t>(j) * vp.width + i) * samples + s);
                }
            }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace rast::fast::detail
