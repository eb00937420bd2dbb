// The float modes' error bound on an edge function, by standard forward error analysis.
//
// Evaluated: E = (d1 * d2) - (d3 * d4), d1 = bx - ax, d2 = py - ay, d3 = by - ay, d4 = px - ax, every
// operation rounded to nearest in T (unit roundoff u), every input first rounded to T (float32 only:
// relative error u, plus an absolute 2^-150 where it underflows). With D the exact value of a difference
// and delta the bound on its computed value's error, |d| <= M = |D| + delta, and
//   |fl(d1 d2) - D1 D2| <= M1 delta2 + |D2| delta1 + u M1 M2        (and alike for d3 d4),
//   |fl(p1 - p2) - (p1 - p2)| <= u (|p1| + |p2|).
// Over the viewport's samples, |py - ay| <= max(|ay|, |H - ay|) and |px - ax| <= max(|ax|, |W - ax|);
// each term grows with these magnitudes, so the maximum over samples is bounded by their maxima.
#include "bounded.h"
#include "snap.h"

#include <rast/fast.h>

#include <algorithm>
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

// Bound for edge a -> b of the products term (d1 d2) with d1 = bx - ax and d2 = p - ay, p over [0, extent].
double product_error(const Difference& x, const Difference& y, double u, double underflow, double& magnitude) {
    const double mx = x.exact + x.delta, my = y.exact + y.delta;
    magnitude = mx * my;
    return mx * y.delta + y.exact * x.delta + u * magnitude + underflow;
}

double directed_edge_bound(const Vertex& a, const Vertex& b, Viewport vp, const Format& f) {
    const double width = vp.width, height = vp.height;
    const Difference d1 = difference(std::abs(b.x - a.x), a.x, b.x, f);
    const Difference d2 = difference(std::max(std::abs(a.y), std::abs(height - a.y)), a.y, height, f);
    const Difference d3 = difference(std::abs(b.y - a.y), a.y, b.y, f);
    const Difference d4 = difference(std::max(std::abs(a.x), std::abs(width - a.x)), a.x, width, f);
    const double largest = std::max({d1.exact + d1.delta, d2.exact + d2.delta, d3.exact + d3.delta,
                                     d4.exact + d4.delta, std::abs(a.x), std::abs(a.y), std::abs(b.x),
                                     std::abs(b.y), width, height});
    if (!(largest * (1 + 4 * f.u) < f.max)) return std::numeric_limits<double>::infinity();
    double m12 = 0, m34 = 0;
    const double e12 = product_error(d1, d2, f.u, f.underflow, m12);
    const double e34 = product_error(d3, d4, f.u, f.underflow, m34);
    // Any intermediate that may leave the type's range makes the evaluation unbounded.
    if (!(std::max(m12, m34) * (1 + 4 * f.u) < f.max)) return std::numeric_limits<double>::infinity();
    return (e12 + e34 + f.u * (m12 + m34) * (1 + f.u) + f.underflow) * detail::kSlack;
}

}  // namespace

double edge_error_bound(const Triangle& t, Precision precision, Viewport vp) {
    if (detail::is_fixed(precision)) return 0;
    const Format f = precision == Precision::float32
                         ? Format{detail::kUnitFloat, detail::kUnitFloat, 0x1p-150, FLT_MAX}
                         : Format{detail::kUnitDouble, 0, DBL_TRUE_MIN, DBL_MAX};
    double bound = 0;
    for (int k = 0; k < 3; ++k) {
        const Vertex& a = t.v[k];
        const Vertex& b = t.v[(k + 1) % 3];
        // The rasterizer may traverse either direction, depending on the winding.
        bound = std::max({bound, directed_edge_bound(a, b, vp, f), directed_edge_bound(b, a, vp, f)});
    }
    return bound;
}

}  // namespace rast::fast
