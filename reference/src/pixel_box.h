// The pixels a triangle's bounding box touches, clamped to the viewport.
#pragma once

#include <rast/scene.h>

#include <algorithm>
#include <cmath>

namespace rast::reference::detail {

// Inclusive pixel ranges [i0, i1] x [j0, j1]; empty when i0 > i1 or j0 > j1.
struct PixelBox {
    int i0, i1, j0, j1;
    bool empty() const { return i0 > i1 || j0 > j1; }
};

// Pixel k's closed square [k, k + 1] meets [lo, hi] iff ceil(lo) - 1 <= k <= floor(hi). Every sample
// lies in its pixel's closed square, so these are all pixels that can hold a covered sample or area.
// The clamp happens in double, before the conversion to int: coordinates may be any finite double.
inline void clamped_span(double lo, double hi, int n, int& first, int& last) {
    const double f = std::max(std::ceil(lo) - 1.0, 0.0);
    const double l = std::min(std::floor(hi), n - 1.0);
    if (f > l) {
        first = 0;
        last = -1;
    } else {
        first = static_cast<int>(f);
        last = static_cast<int>(l);
    }
}

inline PixelBox pixel_box(const Triangle& t, Viewport vp) {
    const auto [xmin, xmax] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [ymin, ymax] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    PixelBox box{};
    clamped_span(xmin, xmax, vp.width, box.i0, box.i1);
    clamped_span(ymin, ymax, vp.height, box.j0, box.j1);
    return box;
}

}  // namespace rast::reference::detail
