// Running error analysis in double: a value carried with a rigorous bound on its distance from the exact
// value it approximates. Each operation adds its own rounding to the propagated input errors: u·|result|
// (round to nearest, u = 2^-53), and for a product or quotient also 2^-1074, the absolute error of a
// result that underflows into the subnormal range, where u·|result| no longer bounds it. (A sum or
// difference of doubles that is subnormal is exact.) The bound arithmetic itself rounds, and second-order
// terms are dropped; callers absorb both with kSlack on the final bound.
//
// Each operation's own rounding charge is multiplied by `w`, the weight its caller's Weights policy
// (rast/filters/weights.h) gives that source of error: 1 in the engine, less in the tests that show the
// charge is needed.
#pragma once

#include <rast/filters/weights.h>

#include <cfloat>
#include <cmath>
#include <limits>

namespace rast::fast::detail {

struct Bounded {
    double v;  // the computed value
    double e;  // |v - exact| <= e
};

inline constexpr double kUnitDouble = 0x1p-53;
inline constexpr double kUnitFloat = 0x1p-24;
// Relative margin on a final bound for the rounding of the bound's own computation and dropped u^2
// terms (a few dozen operations contribute far less than 2^-20 relative), and for the rounding of the
// comparison that uses it (a gap rounded against a rounded margin loses at most 2u of either: kernels.h).
inline constexpr double kSlack = 1 + 0x1p-20;

inline Bounded exact(double v) { return {v, 0}; }

// The sources of error of a value rounded to nearest from an exact one: half an ulp, at most u |z| in the
// normal range, and at most half the least subnormal below it.
enum class NearestTerm { rounding, underflow };

// A bound on |z - Z| for z the double nearest the exact Z, rounded up (kSlack), weighed by W
// (rast/filters/weights.h).
template <class W = filters::Sound>
double nearest_error(double z) {
    return (W::weight(NearestTerm::rounding) * kUnitDouble * std::abs(z) +
            W::weight(NearestTerm::underflow) * DBL_TRUE_MIN) * kSlack;
}

inline Bounded add(Bounded x, Bounded y, double w = 1) {
    const double v = x.v + y.v;
    return {v, x.e + y.e + w * kUnitDouble * std::abs(v)};
}

inline Bounded sub(Bounded x, Bounded y, double w = 1) {
    const double v = x.v - y.v;
    return {v, x.e + y.e + w * kUnitDouble * std::abs(v)};
}

inline Bounded mul(Bounded x, Bounded y, double w = 1) {
    const double v = x.v * y.v;
    return {v, std::abs(x.v) * y.e + std::abs(y.v) * x.e + x.e * y.e + w * (kUnitDouble * std::abs(v) + DBL_TRUE_MIN)};
}

// |X/Y - x/y| <= (ex + |x/y| ey) / (|y| - ey) when |Y - y| <= ey < |y|; unbounded otherwise. v is x/y
// rounded: |x/y| <= |v| + u |v| + 2^-1075, taken as |v| + 2^-1074, whose absolute part matters where the
// quotient underflows (a tiny numerator over a denominator known only within most of itself: 2^-1074 / 3
// rounds to 0, yet divided by 3 - 2.9 it is ten times the least subnormal); the relative u is in kSlack.
inline Bounded div(Bounded x, Bounded y, double w = 1) {
    const double v = x.v / y.v;
    if (!(std::abs(y.v) > y.e)) return {v, std::numeric_limits<double>::infinity()};
    return {v, (x.e + (std::abs(v) + DBL_TRUE_MIN) * y.e) / (std::abs(y.v) - y.e) +
                   w * (kUnitDouble * std::abs(v) + DBL_TRUE_MIN)};
}

}  // namespace rast::fast::detail
