#include <rast/exact_geometry.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace rast::properties {

Rational edge_function(const Vertex& a, const Vertex& b, double px, double py) {
    // Conversions from double and rational arithmetic are exact.
    const Rational ax(a.x), ay(a.y);
    return (Rational(b.x) - ax) * (Rational(py) - ay) - (Rational(b.y) - ay) * (Rational(px) - ax);
}

int edge_sign(const Vertex& a, const Vertex& b, double px, double py) {
    // The oracle's own filter, on purpose not the engines' (rast/filters/orientation.h): a wrong bound
    // there must not make the judge agree with the engines it judges. It filters differently too (the
    // products of (a - p) and (b - p), with no underflow term, small sums sent to exact arithmetic).
    // Shewchuk's orient2d stage A: with left = (a - p) x-part products formed in doubles, the sign of
    // left - right is right once |det| exceeds (3 + 16 eps) eps (|left| + |right|). The bound assumes no
    // underflow and no overflow, so tiny and non-finite sums go to the exact path.
    constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
    constexpr double bound = (3.0 + 16.0 * eps) * eps;
    const double left = (a.x - px) * (b.y - py);
    const double right = (a.y - py) * (b.x - px);
    const double det = left - right;
    const double sum = std::abs(left) + std::abs(right);
    if (std::isfinite(sum) && sum > 0x1p-900 && std::abs(det) > bound * sum) return det > 0 ? 1 : -1;
    const Rational exact = edge_function(a, b, px, py);
    return exact > 0 ? 1 : exact < 0 ? -1 : 0;
}

int orientation(const Triangle& t) { return edge_sign(t.v[0], t.v[1], t.v[2].x, t.v[2].y); }

Triangle counter_clockwise(const Triangle& t) {
    Triangle ccw = t;
    if (orientation(t) < 0) std::swap(ccw.v[1], ccw.v[2]);
    return ccw;
}

Location locate(const Triangle& t, double x, double y) {
    if (orientation(t) == 0) return Location::outside;
    const Triangle ccw = counter_clockwise(t);
    int zeros = 0;
    for (int e = 0; e < 3; ++e) {
        const int s = edge_sign(ccw.v[e], ccw.v[(e + 1) % 3], x, y);
        if (s < 0) return Location::outside;
        zeros += s == 0;
    }
    return zeros == 0 ? Location::inside : zeros == 1 ? Location::on_edge : Location::on_vertex;
}

namespace {
// docs/design.md: traversed counter-clockwise, a left edge goes down (dy < 0), a top edge goes left (dy = 0,
// dx < 0). Comparing the endpoints decides this exactly, without forming dy.
bool is_top_left(const Vertex& a, const Vertex& b) { return b.y < a.y || (b.y == a.y && b.x < a.x); }
}  // namespace

bool rule_covers(const Triangle& t, double x, double y) {
    if (orientation(t) == 0) return false;
    const Triangle ccw = counter_clockwise(t);
    for (int e = 0; e < 3; ++e) {
        const Vertex& a = ccw.v[e];
        const Vertex& b = ccw.v[(e + 1) % 3];
        const int s = edge_sign(a, b, x, y);
        if (s < 0 || (s == 0 && !is_top_left(a, b))) return false;
    }
    return true;
}

Rational twice_area(const Triangle& t) {
    const Rational doubled = edge_function(t.v[0], t.v[1], t.v[2].x, t.v[2].y);
    return doubled < 0 ? Rational(-doubled) : doubled;
}

double snap(double value, int bits, Contract::Rounding rounding) {
    if (rounding == Contract::Rounding::any) throw std::invalid_argument("snap: rounding=any is not one snapping");
    // A double of magnitude 2^(52 - bits) or more is already a multiple of 2^-bits, and scaling it could
    // overflow. Below that, scaling by a power of two is exact and nearbyint rounds ties to even.
    if (!(std::abs(value) < std::ldexp(1.0, 52 - bits))) return value;
    const double scaled = std::ldexp(value, bits);
    return std::ldexp(rounding == Contract::Rounding::floor ? std::floor(scaled) : std::nearbyint(scaled), -bits);
}

namespace {

template <class Shape>
Shape snap_vertices(Shape shape, int bits, Contract::Rounding rounding) {
    for (Vertex& v : shape.v) {
        v.x = snap(v.x, bits, rounding);
        v.y = snap(v.y, bits, rounding);
    }
    return shape;
}

}  // namespace

Triangle snap(const Triangle& t, int bits, Contract::Rounding rounding) { return snap_vertices(t, bits, rounding); }

Segment snap(const Segment& s, int bits, Contract::Rounding rounding) { return snap_vertices(s, bits, rounding); }

}  // namespace rast::properties
