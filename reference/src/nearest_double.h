// Rounding an exact fraction to a double.
#pragma once

#include <rast/reference.h>

namespace rast::reference::detail {

// The double nearest to num / den (den != 0), ties to even, subnormals and overflow (to +-infinity)
// included. (mpq_get_d truncates toward zero, which is not this.)
double nearest_double(boost::multiprecision::mpz_int num, boost::multiprecision::mpz_int den);

inline double nearest_double(const Rational& q) { return nearest_double(numerator(q), denominator(q)); }

}  // namespace rast::reference::detail
