// rast filters — the orientation filter: the sign of the 2D orientation determinant in double where its
// error bound decides it. The one filter in front of every exact orientation in rast (the reference's
// sample tests and triangle winding, the fast path's winding).
#pragma once

#include <rast/filters/weights.h>

#include <cmath>

namespace rast::filters {

// det = (q - p) x (r - p) = (qx - px)(ry - py) - (qy - py)(rx - px), evaluated as written.
//
// Without underflow, the computed det errs by at most (3 + 16u) u (|left| + |right|), u = 2^-53, where
// left and right are the computed products (Shewchuk 1997, ccwerrboundA: each product carries the
// rounding of its two differences and its own, the subtraction a third; 16u^2 covers the second-order
// terms and the rounding of the bound's own computation). Where a product underflows, its rounding is
// absolute, up to 2^-1075, and the relative term no longer covers it (it may itself underflow to 0):
// 2^-1000 bounds both products' and the bound's own underflow. An overflow gives an infinite or NaN
// det or bound, which decides nothing.
enum class OrientationTerm {
    relative,   // (3 + 16u) u (|left| + |right|)
    underflow,  // 2^-1000
};

inline constexpr double kOrientationRelative = (3 + 16 * 0x1p-53) * 0x1p-53;
inline constexpr double kOrientationUnderflow = 0x1p-1000;

struct Orientation {
    double det;    // the computed determinant
    double bound;  // |det - exact| <= bound (Sound weights, finite det and bound)

    // +1 (r left of p -> q), -1 (right), or 0 when the bound does not decide.
    int certain_sign() const {
        if (det > bound) return 1;
        if (det < -bound) return -1;
        return 0;  // also for an infinite or NaN det or bound
    }
};

template <class Weights = Sound>
inline Orientation orientation(double px, double py, double qx, double qy, double rx, double ry) {
    const double left = (qx - px) * (ry - py);
    const double right = (qy - py) * (rx - px);
    const double bound = Weights::weight(OrientationTerm::relative) * kOrientationRelative *
                             (std::abs(left) + std::abs(right)) +
                         Weights::weight(OrientationTerm::underflow) * kOrientationUnderflow;
    return {left - right, bound};
}

}  // namespace rast::filters
