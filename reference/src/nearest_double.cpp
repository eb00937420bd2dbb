#include "nearest_double.h"

#include <algorithm>
#include <cmath>

namespace rast::reference::detail {

using boost::multiprecision::mpz_int;

double nearest_double(mpz_int num, mpz_int den) {
    if (num.is_zero()) return 0.0;
    const bool negative = (num.sign() < 0) != (den.sign() < 0);
    num = abs(num);
    den = abs(den);

    // e with 2^e <= num/den < 2^(e+1).
    long e = static_cast<long>(msb(num)) - static_cast<long>(msb(den));
    mpz_int scaled_num = num, scaled_den = den;
    if (e >= 0)
        scaled_den <<= static_cast<unsigned>(e);
    else
        scaled_num <<= static_cast<unsigned>(-e);
    if (scaled_num < scaled_den) --e;

    // Weight of the last significand bit: 53 significant bits, but never below the subnormal step 2^-1074.
    const long lsb = std::max(e - 52, -1074L);
    if (lsb >= 0)
        den <<= static_cast<unsigned>(lsb);
    else
        num <<= static_cast<unsigned>(-lsb);

    mpz_int m, r;
    divide_qr(num, den, m, r);
    const int half = mpz_int(2 * r).compare(den);
    if (half > 0 || (half == 0 && bit_test(m, 0))) ++m;

    // m <= 2^53 converts exactly; ldexp is exact unless it overflows, which is the correct infinity.
    const double magnitude = std::ldexp(m.convert_to<double>(), static_cast<int>(lsb));
    return negative ? -magnitude : magnitude;
}

}  // namespace rast::reference::detail
