#include "exact_depth.h"

#include "nearest_double.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace rast::reference::detail {

using boost::multiprecision::mpz_int;

namespace {

// v = m * 2^e with m an integer of at most 53 bits.
std::pair<std::int64_t, int> integer_times_power_of_two(double v) {
    int e = 0;
    const double f = std::frexp(v, &e);  // v = f * 2^e, 1/2 <= |f| < 1
    return {static_cast<std::int64_t>(std::ldexp(f, 53)), e - 53};
}

// The least k >= 0 that makes v * 2^k an integer.
int scale_for(double v) {
    if (v == 0) return 0;
    const auto [m, e] = integer_times_power_of_two(v);
    const int trailing_zeros = std::countr_zero(static_cast<std::uint64_t>(m < 0 ? -m : m));
    return std::max(0, -(e + trailing_zeros));
}

// v * 2^k, exactly; v * 2^k must be an integer.
mpz_int scaled(double v, int k) {
    if (v == 0) return 0;
    const auto [m, e] = integer_times_power_of_two(v);
    mpz_int r(m < 0 ? -m : m);
    if (e + k >= 0)
        r <<= static_cast<unsigned>(e + k);
    else
        r >>= static_cast<unsigned>(-(e + k));
    return m < 0 ? mpz_int(-r) : r;
}

// Sample offsets are multiples of 1/16, so s >= 4 makes every sample position an integer too.
constexpr int kSampleScale = 4;

}  // namespace

ExactDepth::ExactDepth(const Triangle& t) : s_(kSampleScale) {
    for (const Vertex& v : t.v) {
        s_ = std::max({s_, scale_for(v.x), scale_for(v.y)});
        t_ = std::max(t_, scale_for(v.z));
    }
    plane_ = depth_plane<mpz_int>(
        t, [this](double v) { return scaled(v, s_); }, [this](double v) { return scaled(v, t_); });
}

// With x, y scaled by 2^s and z by 2^t, a and b carry 2^(t+s), c carries 2^(t+2s) and w 2^(2s). A point
// that needs a finer scale s + d (only depth_at's arbitrary points can) lifts every term to 2^(t+2s+2d).
std::pair<mpz_int, mpz_int> ExactDepth::fraction(double x, double y) const {
    const int d = std::max({0, scale_for(x) - s_, scale_for(y) - s_});
    const auto ud = static_cast<unsigned>(d);
    mpz_int numerator = plane_.a * scaled(x, s_ + d) + plane_.b * scaled(y, s_ + d);
    numerator <<= ud;
    numerator += plane_.c << (2 * ud);
    mpz_int denominator = plane_.w << (2 * ud + static_cast<unsigned>(t_));
    return {std::move(numerator), std::move(denominator)};
}

Rational ExactDepth::at(double x, double y) const {
    const auto [numerator, denominator] = fraction(x, y);
    return Rational(numerator, denominator);
}

// n1/d1 - n2/d2 has the sign of (n1 d2 - n2 d1) d1 d2.
int ExactDepth::compare(const ExactDepth& other, double x, double y) const {
    const auto [n1, d1] = fraction(x, y);
    const auto [n2, d2] = other.fraction(x, y);
    const mpz_int difference = n1 * d2 - n2 * d1;
    return difference.sign() * d1.sign() * d2.sign();
}

double ExactDepth::nearest(double x, double y) const {
    const auto [numerator, denominator] = fraction(x, y);
    return nearest_double(numerator, denominator);
}

}  // namespace rast::reference::detail
