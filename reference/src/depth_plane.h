// The plane of a triangle's depth, for any number type: exact rationals or intervals.
#pragma once

#include <rast/scene.h>

namespace rast::reference::detail {

// z(x, y) = a x + b y + c.
template <class NT>
struct DepthPlane {
    NT a, b, c;
    NT at(const NT& x, const NT& y) const { return a * x + b * y + c; }
};

// The lecture's barycentric interpolation z = (w0 z0 + w1 z1 + w2 z2) / (w0 + w1 + w2), where wi is the
// edge function of the edge opposite vertex i. Each wi = Ai x + Bi y + Ci is affine, so z is a plane;
// winding flips the sign of every wi alike and cancels. Undefined (a division by zero) for zero area.
template <class NT>
DepthPlane<NT> depth_plane(const Triangle& t) {
    NT a(0), b(0), c(0), w_sum(0);
    for (int k = 0; k < 3; ++k) {
        const Vertex& p = t.v[(k + 1) % 3];
        const Vertex& q = t.v[(k + 2) % 3];
        // wk(x, y) = (q - p) x ((x, y) - p), expanded.
        const NT A = NT(p.y) - NT(q.y);
        const NT B = NT(q.x) - NT(p.x);
        const NT C = NT(p.x) * NT(q.y) - NT(q.x) * NT(p.y);
        const NT z(t.v[k].z);
        a += z * A;
        b += z * B;
        c += z * C;
        w_sum += C;  // the Ak and Bk sum to zero
    }
    return {a / w_sum, b / w_sum, c / w_sum};
}

}  // namespace rast::reference::detail
