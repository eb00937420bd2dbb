// Coverage, one stage of the fast path (engine.h): how the samples of a block that a triangle covers are
// found on each path (integer edges, the wide path's spans, float edges), and the whole-tile test.
#pragma once

#include "kernels.h"
#include "setup.h"
#include "spans.h"

#include <rast/fast_faults.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>

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

// The wide path's edges in pixel steps (WideEdge) at block b's first sample (index s) and their steps,
// as fixed_edges_at gives the fixed path's: exact in 128 bits, then clamped.
inline void wide_edges_at(const std::array<WideEdge, 3>& edges, const Context& c, const Block& b, int s,
                          std::int64_t* e, std::int64_t* dx, std::int64_t* dy) {
    for (int k = 0; k < 3; ++k) {
        const WideEdge& f = edges[k];
        e[k] = clamped(Int128{f.a} * b.i0 + Int128{f.b} * b.j0 + offset_term(f, c.bits, c.sx[s], c.sy[s]));
        dx[k] = f.a;
        dy[k] = f.b;
    }
}

// Whether t's coverage comes from integer edges (the fixed path's, or the wide path's near ones) rather
// than spans or float edges; if so, e, dx and dy are set as fixed_edges_at sets them.
inline bool integer_edges_at(const Setup& t, const Context& c, const Block& b, int s, std::int64_t* e,
                             std::int64_t* dx, std::int64_t* dy) {
    if (t.p.path == Path::fixed) fixed_edges_at(t.fixed, c, b, s, e, dx, dy);
    else if (t.near) wide_edges_at(*t.near, c, b, s, e, dx, dy);
    else return false;
    return true;
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
// row masks here leave them in `masks`, one per row of the block. wide: on the wide path without near
// edges, t's spans of the block's rows (spans_of, from row b.j0).
template <Fault F>
Coverage coverage_of(const Setup& t, const Context& c, const Block& b, int s, std::span<const Span> wide,
                     std::uint64_t* masks) {
    Coverage cov;
    if (integer_edges_at(t, c, b, s, cov.e, cov.dx, cov.dy)) {
        cov.kind = Coverage::Kind::fixed;
        return cov;
    }
    switch (t.p.path) {
        case Path::fixed: return cov;  // integer edges, above
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

// The Larrabee test of integer edges over the samples of a rectangle of pixels (FixedEdge over their
// bounding rectangle, FixedRect; WideEdge over the pixels, TileRect): an edge function is linear, so its
// extremes there are at corners chosen by the signs of its coefficients.
template <class Edges, class Rect>
TileClass classify_integer(const Edges& edges, const Rect& rect) {
    bool all_inside = true;
    for (const auto& f : edges) {
        if (greatest_over(f, rect) < 0) return TileClass::reject;
        all_inside = all_inside && least_over(f, rect) >= 0;
    }
    return all_inside ? TileClass::accept : TileClass::partial;
}

// The Larrabee test on the samples of pixels [i0, i1] x [j0, j1]: exact for the integer path and the wide
// path's near edges (in 128 bits); a wide triangle without them reads what its spans lie within per band
// instead. For the float modes the double value at a corner is within margin of the exact one minus the
// mode's error bound, so beyond +-margin the mode's sign is certain.
inline TileClass classify(const Setup& t, const Context& c, int i0, int i1, int j0, int j1) {
    if (!t.classify_tiles) return TileClass::partial;
    bool all_inside = true;
    switch (t.p.path) {
        case Path::fixed: return classify_integer(t.fixed, samples_rect(c, i0, i1, j0, j1));
        case Path::floating: {
            if (!(t.float_margin < std::numeric_limits<double>::infinity())) return TileClass::partial;
            const double x_lo = i0 + c.ox_min, x_hi = i1 + c.ox_max, y_lo = j0 + c.oy_min, y_hi = j1 + c.oy_max;
            for (int k = 0; k < 3; ++k) {
                const auto [ax, ay, d1, d3] = double_edge(t.p.v, k);
                const double lowest = d1 * ((d1 >= 0 ? y_lo : y_hi) - ay) - d3 * ((d3 >= 0 ? x_hi : x_lo) - ax);
                const double highest = d1 * ((d1 >= 0 ? y_hi : y_lo) - ay) - d3 * ((d3 >= 0 ? x_lo : x_hi) - ax);
                if (highest < -t.float_margin) return TileClass::reject;
                all_inside = all_inside && lowest > t.float_margin;
            }
            break;
        }
        case Path::wide: {
            if (t.near) return classify_integer(*t.near, TileRect{i0, i1, j0, j1});
            // [j0, j1] is the triangle's rows in one row of tiles: one band's (SpanBand).
            const SpanBand& band = t.bands[static_cast<std::size_t>(j0 / kTile - t.p.j_lo / kTile)];
            if (band.lo_max <= i0 && band.hi_min >= i1) return TileClass::accept;
            if (band.hi_max < i0 || band.lo_min > i1) return TileClass::reject;
            return TileClass::partial;
        }
    }
    return all_inside ? TileClass::accept : TileClass::partial;
}

}  // namespace rast::fast::detail
