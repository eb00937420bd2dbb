// Double-double arithmetic: a value hi + lo carried in two doubles, built from the error-free
// transformations (Knuth's two-sum, the FMA two-product). Round to nearest, and no underflow or
// overflow: the callers (bounded_depth.h) guarantee both by the range of their inputs.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

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

// The sign of the exact sum of the doubles xs. Grows a nonoverlapping expansion one double at a time
// (Shewchuk's Grow-Expansion: two-sums only, nothing rounded); the sign of such an expansion is that of its
// largest non-zero component, the last one. No underflow or overflow (the callers' safe range).
template <std::size_t N>
int exact_sign_of_sum(const std::array<double, N>& xs) {
    std::array<double, N> e{};  // e[0..n) the expansion, increasing magnitude
    std::size_t n = 0;
    for (const double x : xs) {
        double q = x;
        for (std::size_t k = 0; k < n; ++k) {
            const DoubleDouble s = two_sum(q, e[k]);
            e[k] = s.lo;
            q = s.hi;
        }
        e[n++] = q;
    }
    for (std::size_t k = n; k-- > 0;)
        if (e[k] != 0) return e[k] > 0 ? 1 : -1;
    return 0;
}

}  // namespace rast::reference::detail
