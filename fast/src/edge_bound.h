// The float modes' error bound on an edge function, by standard forward error analysis, written as a sum
// of terms a Weights policy (rast/filters/weights.h) weighs, so that tests can show each one is needed.
//
// Evaluated: E = (d1 * d2) - (d3 * d4), d1 = bx - ax, d2 = py - ay, d3 = by - ay, d4 = px - ax, every
// operation rounded to nearest in T (unit roundoff u), every input first rounded to T (float32 only; a
// vertex's rounding is computed exactly, a sample's too where it is known). With D the exact value of a
// difference and delta the bound on its computed value's error, |d| <= M = |D| + delta, and
//   |fl(d1 d2) - D1 D2| <= M1 delta2 + |D2| delta1 + u M1 M2        (and alike for d3 d4),
//   |fl(p' - q') - (p - q)| <= r + u (|p - q| + r), r the inputs' rounding |p' - p| + |q' - q|.
// The bound is on fl(d1 d2) - fl(d3 d4) before its last rounding: rounding to nearest is monotone, keeps
// the sign (gradual underflow: a difference of unequal values is never 0) and keeps any comparison with a
// value of T, so a sample's classification, and a comparison with a margin, are what they would be
// without it. (Shewchuk's orientation filter leaves it out for the same reason.)
//
// Each term grows with |px - ax|, |py - ay| and the sample's own magnitudes |px|, |py|: at one sample
// they are its own; over the viewport's samples |py - ay| <= max(|ay|, |H - ay|), |px - ax| <=
// max(|ax|, |W - ax|), |px| <= W and |py| <= H, so their maxima bound the whole viewport.
#pragma once

#include "bounded.h"

#include <rast/filters/weights.h>
#include <rast/scene.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace rast::fast::detail {

// The sources of error: inputs rounded to the mode's type (float32), the rounded differences, the rounded
// products, and the absolute error of a result below the normal range.
enum class EdgeTerm { input, difference, product, underflow };

struct EdgeFormat {
    double u;          // unit roundoff of the evaluation type
    double input_u;    // relative rounding of an input converted to it
    double underflow;  // absolute rounding error of a result in its subnormal range
    double max;        // largest finite value
};

inline constexpr EdgeFormat kFloat32Edges{kUnitFloat, kUnitFloat, 0x1p-150, FLT_MAX};
inline constexpr EdgeFormat kFloat64Edges{kUnitDouble, 0, DBL_TRUE_MIN, DBL_MAX};

// |x - x rounded to the evaluation type|, exactly: the difference of two doubles within a factor of two
// of each other (or of x and 0) is exact. Zero in float64, which rounds no input.
inline double input_rounding(double x, const EdgeFormat& f) {
    return f.input_u > 0 ? std::abs(double(static_cast<float>(x)) - x) : 0;
}

// The samples a bound holds for: |px - ax| <= reach_x, |px| <= x, px's own rounding to the evaluation
// type at most x_rounding, and alike in y.
struct Reach {
    double reach_x, x, x_rounding, reach_y, y, y_rounding;
};

// The one sample (x, y), for the edge from a.
inline Reach reach_at(const Vertex& a, double x, double y, const EdgeFormat& f) {
    return {std::abs(x - a.x), std::abs(x), input_rounding(x, f), std::abs(y - a.y), std::abs(y), input_rounding(y, f)};
}

// Every sample of a width x height viewport, for the edge from a: a sample's rounding to float is not
// known in advance (positions need not be floats beyond 2^20), so it is bounded by input_u |p|.
inline Reach reach_over(const Vertex& a, double width, double height, const EdgeFormat& f) {
    return {std::max(std::abs(a.x), std::abs(width - a.x)), width, f.input_u * width,
            std::max(std::abs(a.y), std::abs(height - a.y)), height, f.input_u * height};
}

namespace edge_bound {

// A difference of two inputs: its exact magnitude (bounded above) and the error of its computed value,
// given the inputs' own rounding to the evaluation type.
struct Difference {
    double exact, delta;
};

template <class W>
Difference difference(double exact_magnitude, double input_error, const EdgeFormat& f) {
    const double input = W::weight(EdgeTerm::input) * input_error;
    const double delta = input + W::weight(EdgeTerm::difference) * f.u * (exact_magnitude + input) +
                         W::weight(EdgeTerm::underflow) * f.underflow;
    return {exact_magnitude, delta};
}

// The error of fl(x y); magnitude gets a bound on |fl(x y)|'s exact counterpart's inputs' product.
template <class W>
double product_error(const Difference& x, const Difference& y, const EdgeFormat& f, double& magnitude) {
    const double mx = x.exact + x.delta, my = y.exact + y.delta;
    magnitude = mx * my;
    return mx * y.delta + y.exact * x.delta + W::weight(EdgeTerm::product) * f.u * magnitude +
           W::weight(EdgeTerm::underflow) * f.underflow;
}

}  // namespace edge_bound

// The bound on edge a -> b evaluated at the samples `p` reaches; +infinity where an intermediate may
// leave the type's range.
template <class W = filters::Sound>
double directed_edge_bound(const Vertex& a, const Vertex& b, const Reach& p, const EdgeFormat& f) {
    using namespace edge_bound;
    const double ax = input_rounding(a.x, f), ay = input_rounding(a.y, f);
    const Difference d1 = difference<W>(std::abs(b.x - a.x), ax + input_rounding(b.x, f), f);
    const Difference d2 = difference<W>(p.reach_y, ay + p.y_rounding, f);
    const Difference d3 = difference<W>(std::abs(b.y - a.y), ay + input_rounding(b.y, f), f);
    const Difference d4 = difference<W>(p.reach_x, ax + p.x_rounding, f);
    const double largest = std::max({d1.exact + d1.delta, d2.exact + d2.delta, d3.exact + d3.delta,
                                     d4.exact + d4.delta, std::abs(a.x), std::abs(a.y), std::abs(b.x),
                                     std::abs(b.y), p.x, p.y});
    if (!(largest * (1 + 4 * f.u) < f.max)) return std::numeric_limits<double>::infinity();
    double m12 = 0, m34 = 0;
    const double e12 = product_error<W>(d1, d2, f, m12);
    const double e34 = product_error<W>(d3, d4, f, m34);
    // The products, and their difference (at most their sum), must stay in range.
    if (!((m12 + m34) * (1 + 4 * f.u) < f.max)) return std::numeric_limits<double>::infinity();
    return (e12 + e34) * kSlack;
}

}  // namespace rast::fast::detail
