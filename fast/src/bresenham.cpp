// rast — lines by the midpoint (Bresenham) algorithm on snapped endpoints, in integers (rast/fast.h).
//
// Why it is the diamond-exit rule (docs/design.md). For an x-major segment (|dy| <= |dx|), a line of
// slope at most 1 meets pixel (i, j)'s diamond, with its held boundary, exactly when it crosses the
// diamond's vertical diagonal at j <= y(i + 1/2) < j + 1: so each column holds one candidate,
// j = floor(y(i + 1/2)). The segment meets that diamond when it reaches the diagonal (i + 1/2 within
// its x-range) or starts inside the diamond; it lights the pixel unless it ends inside. For a y-major
// segment the same holds across rows, except that the held right corner and unheld left one make the
// candidate i = ceil(x(j + 1/2)) - 1.
#include <rast/fast.h>

#include "line_diamond.h"
#include "snap.h"

#include <rast/scene_limits.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace rast::fast {

namespace {

using Wide = __int128;

// floor(a / b) for b > 0.
Wide floor_div(Wide a, Wide b) {
    const Wide q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

// A point on the grid, in units of 2^-bits pixel, with the axes swapped for a y-major segment so that
// "along" is always the major axis.
struct GridPoint {
    std::int64_t along, across;
};

// Whether the diamond of the pixel (k along, m across) holds p.
bool holds(GridPoint p, std::int64_t k, std::int64_t m, std::int64_t unit, bool y_major) {
    const std::int64_t half = unit / 2;
    return detail::diamond_holds(p.along - (k * unit + half), p.across - (m * unit + half), half, y_major);
}

// The pixel whose diamond holds p, if any: the pixel square containing p, or, for a y-major segment,
// the one left of it when p lies on the square's left side (its right corner).
bool holder(GridPoint p, std::int64_t unit, bool y_major, std::int64_t& k, std::int64_t& m) {
    k = static_cast<std::int64_t>(floor_div(p.along, unit));
    m = static_cast<std::int64_t>(floor_div(p.across, unit));
    if (holds(p, k, m, unit, y_major)) return true;
    if (y_major && p.across == m * unit && holds(p, k, m - 1, unit, y_major)) {
        --m;
        return true;
    }
    return false;
}

}  // namespace

std::vector<std::size_t> bresenham(const Segment& s, Viewport vp, int bits) {
    check_framebuffer(vp, 1, "rast::fast::bresenham");
    if (bits < 1 || bits > 16)
        throw std::invalid_argument("rast::fast::bresenham: subpixel bits " + std::to_string(bits) + " outside 1..16");
    const double scale = std::ldexp(1.0, bits), limit = std::ldexp(1.0, 51 - bits);
    std::int64_t x[2], y[2];
    for (int e = 0; e < 2; ++e) {
        const double sx = detail::snap_coordinate(s.v[e].x, bits), sy = detail::snap_coordinate(s.v[e].y, bits);
        if (!(std::abs(sx) <= limit && std::abs(sy) <= limit))
            throw std::out_of_range("rast::fast::bresenham: endpoint " + std::to_string(e) + " (" +
                                    std::to_string(s.v[e].x) + ", " + std::to_string(s.v[e].y) +
                                    ") lies beyond 2^" + std::to_string(51 - bits) + " pixels");
        x[e] = detail::grid_units(sx, scale);
        y[e] = detail::grid_units(sy, scale);
    }
    std::vector<std::size_t> lit;
    if (x[0] == x[1] && y[0] == y[1]) return lit;
    const std::int64_t unit = std::int64_t{1} << bits;
    const bool y_major = std::abs(y[1] - y[0]) > std::abs(x[1] - x[0]);  // each below 2^52
    const GridPoint start = y_major ? GridPoint{y[0], x[0]} : GridPoint{x[0], y[0]};
    const GridPoint end = y_major ? GridPoint{y[1], x[1]} : GridPoint{x[1], y[1]};
    const std::int64_t n_along = y_major ? vp.height : vp.width, n_across = y_major ? vp.width : vp.height;
    const auto keep = [&](std::int64_t k, std::int64_t m) {
        if (k < 0 || k >= n_along || m < 0 || m >= n_across) return;
        const std::int64_t i = y_major ? m : k, j = y_major ? k : m;
        lit.push_back(static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) + static_cast<std::size_t>(i));
    };
    std::int64_t end_k = 0, end_m = 0, start_k = 0, start_m = 0;
    const bool ends_inside = holder(end, unit, y_major, end_k, end_m);
    const bool starts_inside = holder(start, unit, y_major, start_k, start_m);

    // Walk the major axis left to right over the centres within the segment's span.
    const GridPoint& lo = start.along <= end.along ? start : end;
    const GridPoint& hi = start.along <= end.along ? end : start;
    const Wide d_along = static_cast<Wide>(hi.along) - lo.along, d_across = static_cast<Wide>(hi.across) - lo.across;
    const std::int64_t half = unit / 2;
    // Centres k * unit + half within [lo.along, hi.along], clipped to the viewport.
    const Wide first = std::max<Wide>(-floor_div(-(static_cast<Wide>(lo.along) - half), unit), 0);
    const Wide last = std::min<Wide>(floor_div(static_cast<Wide>(hi.along) - half, unit), n_along - 1);
    if (first <= last) {
        // across(centre) = lo.across + (centre - lo.along) d_across / d_along; the candidate is its
        // floor in pixels (x-major) or its ceiling minus one (y-major): floor((num - 1) / den).
        const Wide den = d_along * unit;
        Wide num = static_cast<Wide>(lo.across) * d_along + (first * unit + half - lo.along) * d_across;
        if (y_major) num -= 1;
        Wide m = floor_div(num, den), r = num - m * den;  // 0 <= r < den
        const Wide step = d_across * unit;                 // |step| <= den: at most one carry a column
        for (Wide k = first; k <= last; ++k) {
            if (!(ends_inside && k == end_k && m == end_m)) keep(static_cast<std::int64_t>(k), static_cast<std::int64_t>(m));
            r += step;
            if (r >= den) r -= den, ++m;
            else if (r < 0) r += den, --m;
        }
    }
    // A start inside a diamond whose diagonal the segment never reaches.
    if (starts_inside && !(ends_inside && start_k == end_k && start_m == end_m)) keep(start_k, start_m);
    std::sort(lit.begin(), lit.end());
    lit.erase(std::unique(lit.begin(), lit.end()), lit.end());
    return lit;
}

}  // namespace rast::fast
