// The pixels a triangle's bounding box touches, clamped to the viewport.
#pragma once

#include <rast/scene.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace rast::reference::detail {

// Inclusive pixel ranges [i0, i1] x [j0, j1]; empty when i0 > i1 or j0 > j1.
struct PixelBox {
    int i0, i1, j0, j1;
    bool empty() const { return i0 > i1 || j0 > j1; }
};

// Pixel k's closed square [k, k + 1] meets [lo, hi] iff ceil(lo) - 1 <= k <= floor(hi). Every sample
// lies in its pixel's closed square, so these are all pixels that can hold a covered sample or area.
// The clamp to [0, n - 1] happens in double, before the conversion to int: coordinates may be any
// finite double. Returns {first, last}, empty when first > last.
inline std::pair<int, int> clamped_span(double lo, double hi, int n) {
    const double first = std::max(std::ceil(lo) - 1.0, 0.0);
    const double last = std::min(std::floor(hi), n - 1.0);
    if (first > last) return {0, -1};
    return {static_cast<int>(first), static_cast<int>(last)};
}

inline PixelBox pixel_box(const Triangle& t, Viewport vp) {
    const auto [xmin, xmax] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [ymin, ymax] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    const auto [i0, i1] = clamped_span(xmin, xmax, vp.width);
    const auto [j0, j1] = clamped_span(ymin, ymax, vp.height);
    return PixelBox{i0, i1, j0, j1};
}

}  // namespace rast::reference::detail
