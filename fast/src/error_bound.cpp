// edge_error_bound and edge_error_bound_at (rast/fast.h): the analysis of edge_bound.h, over the
// viewport's samples and at one sample.
#include "edge_bound.h"
#include "exact.h"
#include "snap.h"
#include "validate.h"

#include <rast/fast.h>

#include <algorithm>
#include <array>

namespace rast::fast {
namespace {

const detail::EdgeFormat& format_of(Precision precision) {
    return precision == Precision::float32 ? detail::kFloat32Edges : detail::kFloat64Edges;
}

}  // namespace

double edge_error_bound(const Triangle& t, Precision precision, Viewport vp) {
    detail::validate(precision);
    detail::validate(t, 0);
    detail::validate(vp, 1);
    if (detail::is_fixed(precision)) return 0;
    const detail::EdgeFormat& f = format_of(precision);
    const auto reach = [&](const Vertex& a) { return detail::reach_over(a, vp.width, vp.height, f); };
    double bound = 0;
    for (int k = 0; k < 3; ++k) {
        const Vertex& a = t.v[k];
        const Vertex& b = t.v[(k + 1) % 3];
        // The rasterizer may traverse either direction, depending on the winding.
        bound = std::max({bound, detail::directed_edge_bound(a, b, reach(a), f),
                          detail::directed_edge_bound(b, a, reach(b), f)});
    }
    return bound;
}

std::array<double, 3> edge_error_bound_at(const Triangle& t, Precision precision, double x, double y) {
    detail::validate(precision);
    detail::validate(t, 0);
    detail::validate_sample(x, y);
    std::array<double, 3> bounds{};
    if (detail::is_fixed(precision)) return bounds;
    const detail::EdgeFormat& f = format_of(precision);
    const auto reach = [&](const Vertex& a) { return detail::reach_at(a, x, y, f); };
    // The rasterizer evaluates each edge from its start in counter-clockwise order (a zero-area triangle
    // covers nothing, either way).
    const int orient = detail::orientation(t.v);
    for (int k = 0; k < 3; ++k) {
        const Vertex& a = t.v[k];
        const Vertex& b = t.v[(k + 1) % 3];
        const double forward = orient >= 0 ? detail::directed_edge_bound(a, b, reach(a), f) : 0;
        const double backward = orient <= 0 ? detail::directed_edge_bound(b, a, reach(b), f) : 0;
        bounds[k] = std::max(forward, backward);
    }
    return bounds;
}

}  // namespace rast::fast
