// Polygons with exact rational vertices, as the exact area and the visible area cut them.
#pragma once

#include <rast/reference.h>

#include <cstddef>
#include <vector>

namespace rast::reference::detail {

struct RationalPoint {
    Rational x, y;
};
using Polygon = std::vector<RationalPoint>;

// The shoelace formula: positive for a counter-clockwise polygon, 0 for one of no area.
inline Rational signed_area(const Polygon& polygon) {
    Rational twice(0);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const RationalPoint& p = polygon[k];
        const RationalPoint& q = polygon[(k + 1) % polygon.size()];
        twice += p.x * q.y - q.x * p.y;
    }
    return twice / 2;
}

}  // namespace rast::reference::detail
