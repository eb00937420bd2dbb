// rast — a line's exact depth at a pixel (rast/line.h), in rationals.
#include <rast/line.h>

#include "validate.h"

namespace rast::reference {

Rational line_depth(const Segment& s, int i, int j) {
    detail::require_finite(s);
    const Rational x0(s.v[0].x), y0(s.v[0].y), z0(s.v[0].z);
    const Rational dx = Rational(s.v[1].x) - x0, dy = Rational(s.v[1].y) - y0;
    const Rational length2 = dx * dx + dy * dy;
    if (length2 == 0) return z0;
    const Rational half(1, 2);
    // The nearest point's parameter along the segment: the centre projected on its line, clamped to it.
    Rational t = ((Rational(i) + half - x0) * dx + (Rational(j) + half - y0) * dy) / length2;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    return z0 + t * (Rational(s.v[1].z) - z0);
}

}  // namespace rast::reference
