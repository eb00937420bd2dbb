// Running error analysis: a floating-point value carried with a rigorous bound on its distance from
// the exact value it approximates. Each operation adds its own rounding (u·|result| for round to
// nearest with unit roundoff u) to the propagated input errors. The bound arithmetic itself rounds,
// and second-order terms are dropped; callers absorb both with kSlack on the final bound.
#pragma once

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
// terms: a few dozen operations contribute far less than 2^-20 relative.
inline constexpr double kSlack = 1 + 0x1p-20;

inline Bounded exact(double v) { return {v, 0}; }

inline Bounded add(Bounded x, Bounded y, double u) {
    const double v = x.v + y.v;
    return {v, x.e + y.e + u * std::abs(v)};
}

inline Bounded sub(Bounded x, Bounded y, double u) {
    const double v = x.v - y.v;
    return {v, x.e + y.e + u * std::abs(v)};
}

inline Bounded mul(Bounded x, Bounded y, double u) {
    const double v = x.v * y.v;
    return {v, std::abs(x.v) * y.e + std::abs(y.v) * x.e + x.e * y.e + u * std::abs(v)};
}

// |X/Y - x/y| <= (ex + |x/y| ey) / (|y| - ey) when |Y - y| <= ey < |y|; unbounded otherwise.
inline Bounded div(Bounded x, Bounded y, double u) {
    const double v = x.v / y.v;
    if (!(std::abs(y.v) > y.e)) return {v, std::numeric_limits<double>::infinity()};
    return {v, (x.e + std::abs(v) * (1 + u) * y.e) / (std::abs(y.v) - y.e) + u * std::abs(v)};
}

}  // namespace rast::fast::detail
