// The float modes' error bound on an edge function, by standard forward error analysis.
//
// Evaluated: E = (d1 * d2) - (d3 * d4), d1 = bx - ax, d2 = py - ay, d3 = by - ay, d4 = px - ax, every
// operation rounded to nearest in T (unit roundoff u), every input first rounded to T (float32 only:
// relative error u, plus an absolute 2^-150 where it underflows). With D the exact value of a difference
// and delta the bound on its computed value's error, |d| <= M = |D| + delta, and
//   |fl(d1 d2) - D1 D2| <= M1 delta2 + |D2| delta1 + u M1 M2        (and alike for d3 d4),
//   |fl(p1 - p2) - (p1 - p2)| <= u (|p1| + |p2|).
// Each term grows with |px - ax|, |py - ay| and the sample's own magnitudes |px|, |py|: at one sample
// they are its own (edge_error_bound_at, in the direction the rasterizer evaluates); over the viewport's
// samples |py - ay| <= max(|ay|, |H - ay|), |px - ax| <= max(|ax|, |W - ax|), |px| <= W and |py| <= H,
// so their maxima bound the whole viewport (edge_error_bound, in either direction).
#include "bounded.h"
#include "exact.h"
#include "snap.h"
#include "validate.h"

#include <rast/fast.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

namespace rast::fast {
namespace {

struct Format {
    double u;          // unit roundoff of the evaluation type
    double input_u;    // relative rounding of an input converted to it
    double underflow;  // absolute rounding error of a result in its subnormal range
    double max;        // largest finite value
};

// A difference of two inputs: its bound on magnitude and on error, given the exact magnitude range.
struct Difference {
    double exact;  // |D|, the exact difference's magnitude (bounded above)
    double delta;  // error of the computed difference
};

Difference difference(double exact_magnitude, double p, double q, const Format& f) {
    const double input = f.input_u * (std::abs(p) + std::abs(q)) + 2 * f.underflow * (f.input_u > 0);
    const double delta = input + f.u * (exact_magnitude + input) + f.underflow;
    return {exact_magnitude, delta};
}

// Bound for edge a -> b of the products term (d1 d2) with d1 = bx - ax and d2 = p - ay.
double product_error(const Difference& x, const Difference& y, double u, double underflow, double& magnitude) {
    const double mx = x.exact + x.delta, my = y.exact + y.delta;
    magnitude = mx * my;
    return mx * y.delta + y.exact * x.delta + u * magnitude + underflow;
}

// The samples the bound holds for: |px - ax| <= reach_x, |px| <= x, and alike in y.
struct Reach {
    double reach_x, x, reach_y, y;
};

double directed_edge_bound(const Vertex& a, const Vertex& b, const Reach& p, const Format& f) {
    const Difference d1 = difference(std::abs(b.x - a.x), a.x, b.x, f);
    const Difference d2 = difference(p.reach_y, a.y, p.y, f);
    const Difference d3 = difference(std::abs(b.y - a.y), a.y, b.y, f);
    const Difference d4 = difference(p.reach_x, a.x, p.x, f);
    const double largest = std::max({d1.exact + d1.delta, d2.exact + d2.delta, d3.exact + d3.delta,
                                     d4.exact + d4.delta, std::abs(a.x), std::abs(a.y), std::abs(b.x),
                                     std::abs(b.y), p.x, p.y});
    if (!(largest * (1 + 4 * f.u) < f.max)) return std::numeric_limits<double>::infinity();
    double m12 = 0, m34 = 0;
    const double e12 = product_error(d1, d2, f.u, f.underflow, m12);
    const double e34 = product_error(d3, d4, f.u, f.underflow, m34);
    // Any intermediate that may leave the type's range makes the evaluation unbounded: the products, and
    // their difference, which is at most their sum (each product in range, the difference overflowed).
    if (!((m12 + m34) * (1 + 4 * f.u) < f.max)) return std::numeric_limits<double>::infinity();
    return (e12 + e34 + f.u * (m12 + m34) * (1 + f.u) + f.underflow) * detail::kSlack;
}

Format format_of(Precision precision) {
    return precision == Precision::float32 ? Format{detail::kUnitFloat, detail::kUnitFloat, 0x1p-150, FLT_MAX}
                                           : Format{detail::kUnitDouble, 0, DBL_TRUE_MIN, DBL_MAX};
}

}  // namespace

double edge_error_bound(const Triangle& t, Precision precision, Viewport vp) {
    detail::validate(precision);
    detail::validate(t, 0);
    detail::validate(vp, 1);
    if (detail::is_fixed(precision)) return 0;
    const Format f = format_of(precision);
    const double width = vp.width, height = vp.height;
    const auto reach = [&](const Vertex& a) {
        return Reach{std::max(std::abs(a.x), std::abs(width - a.x)), width,
                     std::max(std::abs(a.y), std::abs(height - a.y)), height};
    };
    double bound = 0;
    for (int k = 0; k < 3; ++k) {
        const Vertex& a = t.v[k];
        const Vertex& b = t.v[(k + 1) % 3];
        // The rasterizer may traverse either direction, depending on the winding.
        bound = std::max({bound, directed_edge_bound(a, b, reach(a), f), directed_edge_bound(b, a, reach(b), f)});
    }
    return bound;
}

std::array<double, 3> edge_error_bound_at(const Triangle& t, Precision precision, double x, double y) {
    detail::validate(precision);
    detail::validate(t, 0);
    detail::validate_sample(x, y);
    std::array<double, 3> bounds{};
    if (detail::is_fixed(precision)) return bounds;
    const Format f = format_of(precision);
    const auto reach = [&](const Vertex& a) {
        return Reach{std::abs(x - a.x), std::abs(x), std::abs(y - a.y), std::abs(y)};
    };
    // The rasterizer evaluates each edge from its start in counter-clockwise order (a zero-area triangle
    // covers nothing, either way).
    const int orient = detail::orientation(t.v);
    for (int k = 0; k < 3; ++k) {
        const Vertex& a = t.v[k];
        const Vertex& b = t.v[(k + 1) % 3];
        const double forward = orient >= 0 ? directed_edge_bound(a, b, reach(a), f) : 0;
        const double backward = orient <= 0 ? directed_edge_bound(b, a, reach(b), f) : 0;
        bounds[k] = std::max(forward, backward);
    }
    return bounds;
}

}  // namespace rast::fast
