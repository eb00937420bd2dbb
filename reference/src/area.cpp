// rast — exact area coverage: the box-prefiltered ideal that supersampling approximates.
//
// A triangle is clipped (Sutherland–Hodgman, in exact rationals) to the strip of one pixel row; within
// the strip, F(c) = the area of the strip polygon left of x = c, and pixel i's area is F(i + 1) - F(i).
// A pixel square that lies inside the strip polygon adds exactly 1, so F needs a clip only at the
// columns where the triangle's boundary crosses the row.
#include <rast/reference.h>

#include "pixel_box.h"
#include "rational_polygon.h"
#include "validate.h"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace rast::reference {

namespace {

using detail::Polygon;
using detail::RationalPoint;

// One side of a pixel square: the half-plane x >= bound, x <= bound, y >= bound or y <= bound.
struct HalfPlane {
    bool vertical;  // the boundary is the line x = bound (else y = bound)
    Rational bound;
    bool keep_above;

    const Rational& coordinate(const RationalPoint& p) const { return vertical ? p.x : p.y; }
    bool contains(const RationalPoint& p) const {
        return keep_above ? coordinate(p) >= bound : coordinate(p) <= bound;
    }
    // Where segment pq crosses the boundary; p and q lie on opposite sides. Only the other coordinate
    // needs computing: on the boundary line, this one is `bound`.
    RationalPoint crossing(const RationalPoint& p, const RationalPoint& q) const {
        const Rational t = (bound - coordinate(p)) / (coordinate(q) - coordinate(p));
        if (vertical) return {bound, p.y + t * (q.y - p.y)};
        return {p.x + t * (q.x - p.x), bound};
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

// Absolute: winding does not matter, and zero-area triangles give 0.
Rational area(const Polygon& polygon) { return abs(detail::signed_area(polygon)); }

// The triangle clipped to the strip j <= y <= j + 1 of pixel row j: a convex polygon.
Polygon row_strip(const Triangle& t, int j) {
    Polygon polygon;
    for (const Vertex& v : t.v) polygon.push_back({Rational(v.x), Rational(v.y)});
    const Rational bottom(j);
    polygon = clip(polygon, HalfPlane{false, bottom, true});
    return clip(polygon, HalfPlane{false, bottom + 1, false});
}

// F(c): the area of the polygon left of x = c.
Rational area_left_of(const Polygon& polygon, const Rational& c) {
    return area(clip(polygon, HalfPlane{true, c, false}));
}

// The x-extent of a convex polygon's intersection with the line y = y0, when the polygon lies on one
// side of that line: then the intersection is a vertex or an edge, so its ends are vertices.
std::optional<std::pair<Rational, Rational>> extent_on(const Polygon& polygon, const Rational& y0) {
    std::optional<std::pair<Rational, Rational>> extent;
    for (const RationalPoint& p : polygon) {
        if (p.y != y0) continue;
        if (!extent)
            extent.emplace(p.x, p.x);
        else
            extent = std::pair{std::min(extent->first, p.x), std::max(extent->second, p.x)};
    }
    return extent;
}

// Adds the areas of the pixels of row j, columns [i0, i1], that t covers to `row` (indexed by column).
void accumulate_row(const Triangle& t, int j, int i0, int i1, Rational* row) {
    const Polygon strip = row_strip(t, j);
    if (strip.empty()) return;
    // Pixel square i lies inside the strip polygon iff its four corners do, i.e. iff [i, i + 1] lies
    // within the polygon's extent on both the bottom and the top line of the strip (convexity).
    const auto bottom = extent_on(strip, Rational(j));
    const auto top = extent_on(strip, Rational(j + 1));
    const auto inside = [&](int i) {
        return bottom && top && std::max(bottom->first, top->first) <= i &&
               i + 1 <= std::min(bottom->second, top->second);
    };
    Rational left = area_left_of(strip, Rational(i0));
    for (int i = i0; i <= i1; ++i) {
        const Rational right = inside(i) ? left + 1 : area_left_of(strip, Rational(i + 1));
        row[i] += right - left;
        left = right;
    }
}

}  // namespace

Rational pixel_area(const Triangle& t, int i, int j) {
    detail::require_finite(t);
    const Polygon strip = row_strip(t, j);
    return area_left_of(strip, Rational(i) + 1) - area_left_of(strip, Rational(i));
}

std::vector<Rational> coverage_area(const Scene& scene, const Progress& progress) {
    const Viewport vp = scene.viewport;
    detail::require_valid(vp, 1);  // one area per pixel, whatever the samples
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) detail::require_finite(scene.triangles[id], id);
    std::vector<Rational> coverage(static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height));
    report_progress(progress, 0, scene.triangles.size());
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const Triangle& t = scene.triangles[k];
        const detail::PixelBox box = detail::pixel_box(t, vp);
        for (int j = box.j0; j <= box.j1 && !box.empty(); ++j)
            accumulate_row(t, j, box.i0, box.i1,
                           &coverage[static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width)]);
        report_progress(progress, k + 1, scene.triangles.size());
    }
    return coverage;
}

}  // namespace rast::reference
