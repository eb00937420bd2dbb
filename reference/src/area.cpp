// rast — exact area coverage: the box-prefiltered ideal that supersampling approximates.
#include <rast/reference.h>

#include "pixel_box.h"
#include "validate.h"

#include <cstddef>
#include <vector>

namespace rast::reference {

namespace {

struct RationalPoint {
    Rational x, y;
};
using Polygon = std::vector<RationalPoint>;

// One side of the pixel square: the half-plane axis >= bound (keep_above) or axis <= bound.
struct HalfPlane {
    bool vertical;  // the boundary is the line x = bound (else y = bound)
    Rational bound;
    bool keep_above;

    const Rational& coordinate(const RationalPoint& p) const { return vertical ? p.x : p.y; }
    bool contains(const RationalPoint& p) const {
        return keep_above ? coordinate(p) >= bound : coordinate(p) <= bound;
    }
    // Where segment pq crosses the boundary; p and q lie on opposite sides.
    RationalPoint crossing(const RationalPoint& p, const RationalPoint& q) const {
        const Rational t = (bound - coordinate(p)) / (coordinate(q) - coordinate(p));
        return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
    }
};

// Sutherland–Hodgman: walk the polygon's edges, keeping inside vertices and boundary crossings.
Polygon clip(const Polygon& polygon, const HalfPlane& h) {
    Polygon out;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const RationalPoint& p = polygon[k];
        const RationalPoint& q = polygon[(k + 1) % polygon.size()];
        const bool p_in = h.contains(p), q_in = h.contains(q);
        if (p_in) out.push_back(p);
        if (p_in != q_in) out.push_back(h.crossing(p, q));
    }
    return out;
}

// The shoelace formula, absolute: winding does not matter.
Rational area(const Polygon& polygon) {
    Rational twice(0);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const RationalPoint& p = polygon[k];
        const RationalPoint& q = polygon[(k + 1) % polygon.size()];
        twice += p.x * q.y - q.x * p.y;
    }
    return abs(twice) / 2;
}

// The area of t inside pixel square (i, j): t clipped to the square's four sides.
Rational clipped_area(const Triangle& t, int i, int j) {
    Polygon polygon;
    for (const Vertex& v : t.v) polygon.push_back({Rational(v.x), Rational(v.y)});
    const Rational x0(i), y0(j);
    for (const HalfPlane& h : {HalfPlane{true, x0, true}, HalfPlane{true, x0 + 1, false},
                               HalfPlane{false, y0, true}, HalfPlane{false, y0 + 1, false}})
        polygon = clip(polygon, h);
    return area(polygon);
}

}  // namespace

Rational pixel_area(const Triangle& t, int i, int j) {
    detail::require_finite(t);
    return clipped_area(t, i, j);
}

std::vector<Rational> coverage_area(const Scene& scene) {
    const Viewport vp = scene.viewport;
    detail::require_valid(vp);
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) detail::require_finite(scene.triangles[id], id);
    std::vector<Rational> coverage(static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height));
    for (const Triangle& t : scene.triangles) {
        const detail::PixelBox box = detail::pixel_box(t, vp);
        if (box.empty()) continue;
        for (int j = box.j0; j <= box.j1; ++j)
            for (int i = box.i0; i <= box.i1; ++i)
                coverage[static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) +
                         static_cast<std::size_t>(i)] += clipped_area(t, i, j);
    }
    return coverage;
}

}  // namespace rast::reference
