// rast — lines by the midpoint (Bresenham) algorithm on snapped endpoints, in integers (rast/fast.h).
//
// Why it is the diamond-exit rule (docs/design.md). For an x-major segment (|dy| <= |dx|), a line of
// slope at most 1 meets pixel (i, j)'s diamond, with its held boundary, exactly when it crosses the
// diamond's vertical diagonal at j <= y(i + 1/2) < j + 1: so each column holds one candidate,
// j = floor(y(i + 1/2)). The segment meets that diamond when it reaches the diagonal (i + 1/2 within
// its x-range) or starts inside the diamond; it lights the pixel unless it ends inside. For a y-major
// segment the same holds across rows, except that the held right corner and unheld left one make the
// candidate i = ceil(x(j + 1/2)) - 1.
//
// The walk is the same in any integer type: 128-bit integers where the snapped ends lie within 2^51 grid
// units of the origin (products of two coordinate differences then stay below 2^105), Boost's big ones
// beyond, up to coordinates of +-DBL_MAX. Only the columns (or rows) of the viewport are walked either way.
// Steps are `+= 1`, never `++`: Boost 1.74's cpp_int turns -(2^64 k + 1) into +2^64 k under `++`
// (docs/verification.md), while `+= 1` is right.
#include <rast/fast.h>

#include "line_diamond.h"
#include "snap.h"

#include <rast/scene_limits.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace rast::fast {

namespace {

using Big = boost::multiprecision::cpp_int;

// floor(a / b) for b > 0 (both types divide toward zero).
template <class Int>
Int floor_div(const Int& a, const Int& b) {
    const Int q = a / b;
    return (a % b != 0 && a < 0) ? Int(q - 1) : q;
}

// A point on the grid, in units of 2^-bits pixel, with the axes swapped for a y-major segment so that
// "along" is always the major axis.
template <class Int>
struct GridPoint {
    Int along, across;
};

// Whether the diamond of the pixel (k along, m across) holds p.
template <class Int>
bool holds(const GridPoint<Int>& p, const Int& k, const Int& m, const Int& unit, bool y_major) {
    const Int half = unit / 2;
    return detail::diamond_holds<Int>(p.along - (k * unit + half), p.across - (m * unit + half), half, y_major);
}

// The pixel whose diamond holds p, if any: the pixel square containing p, or, for a y-major segment,
// the one left of it when p lies on the square's left side (its right corner).
template <class Int>
bool holder(const GridPoint<Int>& p, const Int& unit, bool y_major, Int& k, Int& m) {
    k = floor_div<Int>(p.along, unit);
    m = floor_div<Int>(p.across, unit);
    if (holds<Int>(p, k, m, unit, y_major)) return true;
    if (y_major && p.across == m * unit && holds<Int>(p, k, Int(m - 1), unit, y_major)) {
        m -= 1;
        return true;
    }
    return false;
}

// The pixels the segment from (x0, y0) to (x1, y1), in grid units of 2^-bits, lights, in any order and
// possibly repeated.
template <class Int>
std::vector<std::size_t> walk(const Int x[2], const Int y[2], int bits, Viewport vp) {
    std::vector<std::size_t> lit;
    if (x[0] == x[1] && y[0] == y[1]) return lit;
    const Int unit = Int(1) << bits, half = unit / 2;
    const Int ax = x[1] > x[0] ? Int(x[1] - x[0]) : Int(x[0] - x[1]);
    const Int ay = y[1] > y[0] ? Int(y[1] - y[0]) : Int(y[0] - y[1]);
    const bool y_major = ay > ax;
    const GridPoint<Int> start = y_major ? GridPoint<Int>{y[0], x[0]} : GridPoint<Int>{x[0], y[0]};
    const GridPoint<Int> end = y_major ? GridPoint<Int>{y[1], x[1]} : GridPoint<Int>{x[1], y[1]};
    const Int n_along = y_major ? vp.height : vp.width, n_across = y_major ? vp.width : vp.height;
    const auto keep = [&](const Int& k, const Int& m) {
        if (k < 0 || k >= n_along || m < 0 || m >= n_across) return;
        const auto i = static_cast<std::size_t>(y_major ? m : k), j = static_cast<std::size_t>(y_major ? k : m);
        lit.push_back(j * static_cast<std::size_t>(vp.width) + i);
    };
    Int end_k, end_m, start_k, start_m;
    const bool ends_inside = holder<Int>(end, unit, y_major, end_k, end_m);
    const bool starts_inside = holder<Int>(start, unit, y_major, start_k, start_m);

    // Walk the major axis left to right over the centres within the segment's span.
    const GridPoint<Int>& lo = start.along <= end.along ? start : end;
    const GridPoint<Int>& hi = start.along <= end.along ? end : start;
    const Int d_along = hi.along - lo.along, d_across = hi.across - lo.across;
    // Centres k * unit + half within [lo.along, hi.along], clipped to the viewport.
    const Int first = std::max<Int>(Int(-floor_div<Int>(Int(half - lo.along), unit)), Int(0));
    const Int last = std::min<Int>(floor_div<Int>(Int(hi.along - half), unit), Int(n_along - 1));
    if (first <= last) {
        // across(centre) = lo.across + (centre - lo.along) d_across / d_along; the candidate is its
        // floor in pixels (x-major) or its ceiling minus one (y-major): floor((num - 1) / den).
        const Int den = d_along * unit;
        Int num = lo.across * d_along + (first * unit + half - lo.along) * d_across;
        if (y_major) num -= 1;
        Int m = floor_div<Int>(num, den), r = num - m * den;  // 0 <= r < den
        const Int step = d_across * unit;                     // |step| <= den: at most one carry a column
        for (Int k = first; k <= last; k += 1) {
            if (!(ends_inside && k == end_k && m == end_m)) keep(k, m);
            r += step;
            if (r >= den) r -= den, m += 1;
            else if (r < 0) r += den, m -= 1;
        }
    }
    // A start inside a diamond whose diagonal the segment never reaches.
    if (starts_inside && !(ends_inside && start_k == end_k && start_m == end_m)) keep(start_k, start_m);
    return lit;
}

// A snapped coordinate in grid units: exact, for a multiple of 2^-bits (a double of magnitude 2^52 or
// more is an integer, so its units are it shifted left).
Big big_units(double snapped, int bits) {
    return std::abs(snapped) < 0x1p52 ? Big(std::ldexp(snapped, bits)) : Big(Big(snapped) << bits);
}

}  // namespace

std::vector<std::size_t> bresenham(const Segment& s, Viewport vp, int bits) {
    check_framebuffer(vp, 1, "rast::fast::bresenham");
    if (bits < 1 || bits > 16)
        throw std::invalid_argument("rast::fast::bresenham: subpixel bits " + std::to_string(bits) + " outside 1..16");
    double sx[2], sy[2];
    for (int e = 0; e < 2; ++e) {
        if (!std::isfinite(s.v[e].x) || !std::isfinite(s.v[e].y))
            throw std::invalid_argument("rast::fast::bresenham: end " + std::to_string(e) + " is not finite");
        sx[e] = detail::snap_coordinate(s.v[e].x, bits);
        sy[e] = detail::snap_coordinate(s.v[e].y, bits);
    }
    const double scale = std::ldexp(1.0, bits), limit = std::ldexp(1.0, 51 - bits);
    const bool narrow = std::abs(sx[0]) <= limit && std::abs(sy[0]) <= limit && std::abs(sx[1]) <= limit &&
                        std::abs(sy[1]) <= limit;
    std::vector<std::size_t> lit;
    if (narrow) {
        using Wide = __int128;
        const Wide x[2] = {detail::grid_units(sx[0], scale), detail::grid_units(sx[1], scale)};
        const Wide y[2] = {detail::grid_units(sy[0], scale), detail::grid_units(sy[1], scale)};
        lit = walk<Wide>(x, y, bits, vp);
    } else {
        const Big x[2] = {big_units(sx[0], bits), big_units(sx[1], bits)};
        const Big y[2] = {big_units(sy[0], bits), big_units(sy[1], bits)};
        lit = walk<Big>(x, y, bits, vp);
    }
    std::sort(lit.begin(), lit.end());
    lit.erase(std::unique(lit.begin(), lit.end()), lit.end());
    return lit;
}

}  // namespace rast::fast
