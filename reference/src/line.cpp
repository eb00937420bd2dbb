// rast — the diamond-exit rule, exactly (rast/line.h). The second translation unit that includes CGAL:
// orientation predicates on the diamond's corners, which are exact doubles.
#include <rast/line.h>
#include <rast/reference.h>

#include "pixel_box.h"
#include "validate.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rast::reference {

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Epick::Point_2;

int orient(const Point& a, const Point& b, const Point& c) {
    return static_cast<int>(CGAL::orientation(a, b, c));  // +1 left turn, -1 right turn, 0 collinear
}

// The diamond of a pixel, corners counter-clockwise from the left: left, bottom, right, top. Its edges
// run left-bottom, bottom-right, right-top, top-left; the first two are the lower ones.
struct Diamond {
    std::array<Point, 4> corner;

    Diamond(int i, int j) {
        const double cx = i + 0.5, cy = j + 0.5;  // exact: |i|, |j| < 2^31
        corner = {Point(i, cy), Point(cx, j), Point(i + 1.0, cy), Point(cx, j + 1.0)};
    }
    const Point& from(int edge) const { return corner[edge]; }
    const Point& to(int edge) const { return corner[(edge + 1) % 4]; }
};

enum Corner { left, bottom, right, top };

// Whether p is in the diamond with the part of the boundary the rule gives it.
bool holds(const Diamond& d, const Point& p, bool y_major) {
    std::array<int, 4> side;
    for (int e = 0; e < 4; ++e) side[e] = orient(d.from(e), d.to(e), p);
    const auto inside = [&](int e) { return side[e] > 0; };
    if (inside(0) && inside(1) && inside(2) && inside(3)) return true;
    // On a lower edge, strictly between its corners; on the bottom corner; the right one if y-major.
    if (side[0] == 0 && inside(1) && inside(2) && inside(3)) return true;
    if (side[1] == 0 && inside(0) && inside(2) && inside(3)) return true;
    if (p == d.corner[bottom]) return true;
    return y_major && p == d.corner[right];
}

// Whether the segment pq meets the open diamond: no edge of the diamond and not the segment's own line
// separates them (the separating axis theorem; p != q).
bool crosses_interior(const Diamond& d, const Point& p, const Point& q) {
    for (int e = 0; e < 4; ++e)
        if (orient(d.from(e), d.to(e), p) <= 0 && orient(d.from(e), d.to(e), q) <= 0) return false;
    int above = 0, below = 0;
    for (const Point& c : d.corner) {
        const int o = orient(p, q, c);
        above += o > 0;
        below += o < 0;
    }
    return above > 0 && below > 0;
}

// Whether c lies on the closed segment pq, given that it lies on its line.
bool within(const Point& p, const Point& q, const Point& c) {
    return std::min(p.x(), q.x()) <= c.x() && c.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= c.y() &&
           c.y() <= std::max(p.y(), q.y());
}

// Whether the segment pq meets the closed segment ab anywhere but at `excluded` (a or b), when given.
bool meets_edge(const Point& p, const Point& q, const Point& a, const Point& b, const Point* excluded) {
    const int oa = orient(p, q, a), ob = orient(p, q, b);
    if (oa == 0 && ob == 0) {
        // Collinear: the two segments overlap along the line in a segment, a point or nothing. The lower
        // edges run at slopes +-1, so x orders the points of the line.
        const double lo = std::max(std::min(p.x(), q.x()), std::min(a.x(), b.x()));
        const double hi = std::min(std::max(p.x(), q.x()), std::max(a.x(), b.x()));
        if (lo > hi) return false;
        return lo < hi || !excluded || lo != excluded->x();
    }
    const int op = orient(a, b, p), oq = orient(a, b, q);
    if (oa * ob > 0 || op * oq > 0) return false;  // one segment lies strictly on one side of the other
    // They meet in one point: `excluded` exactly when it lies on pq.
    return !excluded || orient(p, q, *excluded) != 0 || !within(p, q, *excluded);
}

// Whether the segment meets the diamond's part of the lower boundary: the lower edges without the left
// corner, and without the right one unless the segment is y-major.
bool meets_lower_edges(const Diamond& d, const Point& p, const Point& q, bool y_major) {
    return meets_edge(p, q, d.corner[left], d.corner[bottom], &d.corner[left]) ||
           meets_edge(p, q, d.corner[bottom], d.corner[right], y_major ? nullptr : &d.corner[right]);
}

// |dy| > |dx|, exactly: the differences of doubles compared without rounding them.
bool is_y_major(const Segment& s) {
    using I = CGAL::Interval_nt<>;
    const I dx = CGAL::abs(I(s.v[1].x) - I(s.v[0].x)), dy = CGAL::abs(I(s.v[1].y) - I(s.v[0].y));
    if (dy.inf() > dx.sup()) return true;
    if (dy.sup() < dx.inf()) return false;
    const Rational ex = abs(Rational(s.v[1].x) - Rational(s.v[0].x)), ey = abs(Rational(s.v[1].y) - Rational(s.v[0].y));
    return ey > ex;
}

// The rule for a segment pq of non-zero length.
bool lights(const Point& p, const Point& q, bool y_major, int i, int j) {
    const Diamond d(i, j);
    if (holds(d, q, y_major)) return false;  // it ends inside: it never leaves
    return holds(d, p, y_major) || crosses_interior(d, p, q) || meets_lower_edges(d, p, q, y_major);
}

}  // namespace

bool lights(const Segment& s, int i, int j) {
    detail::require_finite(s);
    const Point p(s.v[0].x, s.v[0].y), q(s.v[1].x, s.v[1].y);
    return p != q && lights(p, q, is_y_major(s), i, j);
}

std::vector<std::size_t> lit_pixels(const Segment& s, Viewport vp) {
    detail::require_valid(vp, 1);
    detail::require_finite(s);
    std::vector<std::size_t> lit;
    const Point p(s.v[0].x, s.v[0].y), q(s.v[1].x, s.v[1].y);
    if (p == q) return lit;
    // Along the major axis, pixel by pixel: the segment's other coordinate over that pixel's span, in
    // interval arithmetic, bounds the pixels across it whose closed square it can meet.
    const bool y_major = is_y_major(s);
    const auto along = [&](const Vertex& v) { return y_major ? v.y : v.x; };
    const auto across = [&](const Vertex& v) { return y_major ? v.x : v.y; };
    const double a0 = along(s.v[0]), a1 = along(s.v[1]), b0 = across(s.v[0]), b1 = across(s.v[1]);
    const int n_along = y_major ? vp.height : vp.width, n_across = y_major ? vp.width : vp.height;
    const auto [first, last] = detail::clamped_span(std::min(a0, a1), std::max(a0, a1), n_along);
    using I = CGAL::Interval_nt<>;
    const I slope = (I(b1) - I(b0)) / (I(a1) - I(a0));
    for (int k = first; k <= last; ++k) {
        const double lo = std::max<double>(k, std::min(a0, a1)), hi = std::min<double>(k + 1.0, std::max(a0, a1));
        const I at_lo = I(b0) + (I(lo) - I(a0)) * slope, at_hi = I(b0) + (I(hi) - I(a0)) * slope;
        const double b_lo = std::min(at_lo.inf(), at_hi.inf()), b_hi = std::max(at_lo.sup(), at_hi.sup());
        const auto [m0, m1] = detail::clamped_span(b_lo, b_hi, n_across);
        for (int m = m0; m <= m1; ++m) {
            const int i = y_major ? m : k, j = y_major ? k : m;
            if (lights(p, q, y_major, i, j))
                lit.push_back(static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) + static_cast<std::size_t>(i));
        }
    }
    std::sort(lit.begin(), lit.end());
    return lit;
}

}  // namespace rast::reference
