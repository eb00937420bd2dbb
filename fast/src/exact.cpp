// Exact arithmetic on doubles: every finite double is a dyadic rational, so cpp_rational / cpp_int hold
// any coordinate, product and sum here without rounding.
#include "exact.h"

#include "bounded.h"

#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <cmath>

namespace rast::fast::detail {
namespace {

using boost::multiprecision::cpp_int;
using boost::multiprecision::cpp_rational;

int sign(const cpp_rational& r) { return r.sign(); }

cpp_rational cross(const Vertex& a, const Vertex& b, const cpp_rational& px, const cpp_rational& py) {
    const cpp_rational ax(a.x), ay(a.y);
    return (cpp_rational(b.x) - ax) * (py - ay) - (cpp_rational(b.y) - ay) * (px - ax);
}

// The plane's depth at p as the barycentric combination of the corner depths (exact, so any form is).
cpp_rational depth(const Corners& t, double x, double y) {
    const cpp_rational px(x), py(y);
    const cpp_rational area = cross(t[0], t[1], cpp_rational(t[2].x), cpp_rational(t[2].y));
    return (cross(t[1], t[2], px, py) * t[0].z + cross(t[2], t[0], px, py) * t[1].z +
            cross(t[0], t[1], px, py) * t[2].z) /
           area;
}

// x · 2^bits as an integer; x is a multiple of 2^-bits.
cpp_int scaled(double x, int bits) {
    int exponent = 0;
    const double fraction = std::frexp(x, &exponent);
    cpp_int m = static_cast<long long>(std::ldexp(fraction, 53));
    const int shift = exponent - 53 + bits;
    if (shift >= 0) return m << shift;
    return m / (cpp_int(1) << -shift);  // exact: the low bits are zero on the grid
}

// floor(a / b) for b > 0.
cpp_int floor_div(const cpp_int& a, const cpp_int& b) {
    cpp_int q = a / b;
    if (a < 0 && q * b != a) --q;
    return q;
}

// v clamped to [lo - 1, hi + 1]: one past either end already means "no pixel on this side".
int clamp_to(const cpp_int& v, int lo, int hi) {
    if (v < lo) return lo - 1;
    if (v > hi) return hi + 1;
    return static_cast<int>(v);
}

}  // namespace

int orientation(const Corners& v) {
    // Shewchuk's filter for orient2d: the double determinant has the right sign when its magnitude
    // exceeds (3u + 16u^2)(|t1| + |t2|); overflow and NaN fall through to the exact test.
    const double t1 = (v[1].x - v[0].x) * (v[2].y - v[0].y);
    const double t2 = (v[1].y - v[0].y) * (v[2].x - v[0].x);
    const double det = t1 - t2;
    const double bound = (3 * kUnitDouble + 16 * kUnitDouble * kUnitDouble) * (std::abs(t1) + std::abs(t2));
    if (std::isfinite(det) && std::isfinite(bound) && std::abs(det) > bound) return det > 0 ? 1 : -1;
    return sign(cross(v[0], v[1], cpp_rational(v[2].x), cpp_rational(v[2].y)));
}

int compare_depth(const Corners& t, const Corners& u, double x, double y) {
    return sign(depth(t, x, y) - depth(u, x, y));
}

double exact_depth(const Corners& t, double x, double y) { return depth(t, x, y).convert_to<double>(); }

std::vector<Span> wide_spans(const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                             std::span<const SamplePoint> offsets, int i_lo, int i_hi, int j_lo,
                             int j_hi) {
    // Edge a -> b in fixed units: E(X, Y) = A X + B Y + C, A = ay - by, B = bx - ax. Along a sample
    // row X = i·2^bits + SX, so E is P·i + Q and the covered pixels are one half-line per edge.
    struct Edge {
        cpp_int a, b, c;
    };
    std::array<Edge, 3> edges;
    for (int k = 0; k < 3; ++k) {
        const Vertex& p = v[k];
        const Vertex& q = v[(k + 1) % 3];
        const cpp_int ax = scaled(p.x, bits), ay = scaled(p.y, bits);
        Edge& e = edges[k];
        e.a = ay - scaled(q.y, bits);
        e.b = scaled(q.x, bits) - ax;
        // The tie rule as an integer bias: a non-inclusive edge needs E >= 1.
        e.c = -(e.a * ax + e.b * ay) - (inclusive[k] ? 0 : 1);
    }
    const cpp_int unit = cpp_int(1) << bits;
    std::vector<Span> spans;
    spans.reserve(static_cast<std::size_t>(j_hi - j_lo + 1) * offsets.size());
    for (int j = j_lo; j <= j_hi; ++j) {
        for (const SamplePoint& o : offsets) {
            const cpp_int sx = scaled(o.x, bits);
            const cpp_int y = cpp_int(j) * unit + scaled(o.y, bits);
            int lo = i_lo, hi = i_hi;
            for (const Edge& e : edges) {
                const cpp_int p = e.a * unit;
                const cpp_int q = e.a * sx + e.b * y + e.c;
                if (p == 0) {
                    if (q < 0) hi = lo - 1;
                } else if (p > 0) {
                    lo = std::max(lo, clamp_to(-floor_div(q, p), i_lo, i_hi));
                } else {
                    hi = std::min(hi, clamp_to(floor_div(q, -p), i_lo, i_hi));
                }
            }
            spans.push_back({lo, hi});
        }
    }
    return spans;
}

}  // namespace rast::fast::detail
