// The exact depth of a triangle's plane, in integers.
#pragma once

#include "depth_plane.h"

#include <rast/reference.h>

#include <utility>

namespace rast::reference::detail {

// Every double is an integer times a power of two. Scaling x and y by 2^s and z by 2^t makes every
// coefficient of the depth plane an integer, so a depth is one integer fraction: computed and rounded
// with products and one division, without the gcds that rational arithmetic spends on every step.
class ExactDepth {
public:
    // Precondition: t has non-zero area.
    explicit ExactDepth(const Triangle& t);

    Rational at(double x, double y) const;
    // The sign of this plane's depth minus `other`'s, at (x, y).
    int compare(const ExactDepth& other, double x, double y) const;
    // The exact depth rounded to the nearest double.
    double nearest(double x, double y) const;

private:
    // z(x, y) as numerator and denominator.
    std::pair<boost::multiprecision::mpz_int, boost::multiprecision::mpz_int> fraction(double x, double y) const;

    int s_ = 0, t_ = 0;
    DepthPlane<boost::multiprecision::mpz_int> plane_;
};

}  // namespace rast::reference::detail
