// The plane of a triangle's depth, for any number type that represents the vertices exactly (the
// integers of exact_depth.h).
#pragma once

#include <rast/scene.h>

namespace rast::reference::detail {

// z(x, y) = (a x + b y + c) / w.
template <class NT>
struct DepthPlane {
    NT a, b, c, w;
};

// The lecture's barycentric interpolation z = (w0 z0 + w1 z1 + w2 z2) / (w0 + w1 + w2), where wi is the
// edge function of the edge opposite vertex i. Each wi = Ai x + Bi y + Ci is affine, so z is a plane;
// winding flips the sign of every wi alike and cancels. w = 0 for zero area. `xy` and `z` convert the
// vertices' coordinates to NT.
template <class NT, class ToXY, class ToZ>
DepthPlane<NT> depth_plane(const Triangle& t, ToXY xy, ToZ z) {
    NT a(0), b(0), c(0), w(0);
    for (int k = 0; k < 3; ++k) {
        const Vertex& p = t.v[(k + 1) % 3];
        const Vertex& q = t.v[(k + 2) % 3];
        // wk(x, y) = (q - p) x ((x, y) - p), expanded.
        const NT A = xy(p.y) - xy(q.y);
        const NT B = xy(q.x) - xy(p.x);
        const NT C = xy(p.x) * xy(q.y) - xy(q.x) * xy(p.y);
        const NT zk = z(t.v[k].z);
        a += zk * A;
        b += zk * B;
        c += zk * C;
        w += C;  // the Ak and Bk sum to zero
    }
    return {a, b, c, w};
}

}  // namespace rast::reference::detail
