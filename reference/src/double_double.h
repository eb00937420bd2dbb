// Double-double arithmetic: a value hi + lo carried in two doubles, built from the error-free
// transformations (Knuth's two-sum, the FMA two-product). Round to nearest, and no underflow or
// overflow: the callers (bounded_depth.h) guarantee both by the range of their inputs.
#pragma once

#include <cmath>

namespace rast::reference::detail {

// The unit roundoff of double: every round-to-nearest result is within u of the exact one (relative).
inline constexpr double kUnitRoundoff = 0x1p-53;

// hi + lo with |lo| <= ulp(hi) / 2, i.e. hi is the nearest double to hi + lo.
struct DoubleDouble {
    double hi = 0, lo = 0;
};

// a + b exactly, as the rounded sum and its error (Knuth; no precondition on the magnitudes).
inline DoubleDouble two_sum(double a, double b) {
    const double s = a + b;
    const double b_virtual = s - a;
    const double a_virtual = s - b_virtual;
    return {s, (a - a_virtual) + (b - b_virtual)};
}

// a * b exactly, as the rounded product and its error (the FMA computes the error exactly).
inline DoubleDouble two_prod(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}

// x + y (Joldes, Muller, Popescu 2017, "DWPlusFP"). The only rounded operation is the sum of the two
// low parts, whose error is at most u (|x.lo| + |s.lo|) <= u^2 (|x.hi| + |s.hi|).
inline DoubleDouble add(DoubleDouble x, double y) {
    const DoubleDouble s = two_sum(x.hi, y);
    return two_sum(s.hi, x.lo + s.lo);
}

}  // namespace rast::reference::detail
