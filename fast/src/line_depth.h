// A line's depth at a pixel in double, with a rigorous error bound (bounded.h): the filter in front of the
// exact comparison (exact.h) when a line meets the z-buffer.
//
// The depth is z at the segment's point nearest the pixel centre c (docs/design.md): with n = (c - a) .
// (b - a) and d = |b - a|^2, z_a where n <= 0, z_b where n >= d, and z_a + (n / d)(z_b - z_a) between.
// The clamp is decided on n's and n - d's enclosures; where they cannot decide it, the bound is +infinity
// and every comparison of that depth goes to exact arithmetic.
#pragma once

#include "bounded.h"

#include <rast/filters/weights.h>
#include <rast/scene.h>

#include <limits>

namespace rast::fast::detail {

// The sources of error (rast/filters/weights.h): the roundings that make the parameter n / d, and those
// of z_a + t (z_b - z_a).
enum class LineDepthTerm { parameter, evaluation };

template <class W = filters::Sound>
Bounded line_depth(const Segment& s, double cx, double cy) {
    const double wp = W::weight(LineDepthTerm::parameter), we = W::weight(LineDepthTerm::evaluation);
    const Vertex &a = s.v[0], &b = s.v[1];
    const Bounded dx = sub(exact(b.x), exact(a.x), wp), dy = sub(exact(b.y), exact(a.y), wp);
    const Bounded n = add(mul(sub(exact(cx), exact(a.x), wp), dx, wp), mul(sub(exact(cy), exact(a.y), wp), dy, wp), wp);
    const Bounded d = add(mul(dx, dx, wp), mul(dy, dy, wp), wp);
    const Bounded gap = sub(n, d, wp);  // n - d
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    // An enclosure that overflowed says nothing (-inf <= -inf would decide the clamp).
    if (!(n.e < kInfinity && gap.e < kInfinity)) return {a.z, kInfinity};
    // The comparisons of a double with a bound are exact; kSlack covers the bounds' own rounding.
    if (n.v <= -n.e * kSlack) return exact(a.z);  // n <= 0: the start (also where d = 0, for n = 0 then)
    if (gap.v >= gap.e * kSlack) return exact(b.z);
    if (!(n.v > n.e * kSlack && gap.v < -gap.e * kSlack)) return {a.z, kInfinity};  // the clamp is undecided
    const Bounded z = add(exact(a.z), mul(div(n, d, wp), sub(exact(b.z), exact(a.z), we), we), we);
    return {z.v, z.e * kSlack};
}

}  // namespace rast::fast::detail
