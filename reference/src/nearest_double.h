// Rounding an exact rational to a double.
#pragma once

#include <rast/reference.h>

namespace rast::reference::detail {

// The double nearest to q, ties to even, subnormals and overflow (to +-infinity) included.
// (mpq_get_d truncates toward zero, which is not this.)
double nearest_double(const Rational& q);

}  // namespace rast::reference::detail
