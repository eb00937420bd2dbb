// Lines held to the diamond-exit rule as RapidCheck properties: Bresenham equals the exact reference on
// snapped ends, and the rule's own symmetries hold on the reference. These take segments, not scenes;
// lines in scenes, against triangles in the z-buffer, are the registry's lines_zbuffer.
#include <rast/exact_geometry.h>
#include <rast/fast.h>
#include <rast/line.h>
#include <rast/property_generators.h>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <vector>

namespace {

using rast::Segment;
using rast::Vertex;
using rast::Viewport;
using rast::properties::Rational;

// Ends anywhere near a viewport of 1..16 pixels a side: on the grid, on centres, on subpixel grids, a
// few ulps off them, or arbitrary (rast::gen::coordinate).
struct Case {
    Viewport vp;
    Segment s;
};

rc::Gen<Case> cases() {
    return rc::gen::exec([] {
        const Viewport vp{*rc::gen::inRange(1, 17), *rc::gen::inRange(1, 17)};
        Segment s;
        for (Vertex& v : s.v) v = {*rast::gen::coordinate(-2, vp.width + 2.0), *rast::gen::coordinate(-2, vp.height + 2.0), 0};
        return Case{vp, s};
    });
}

// The pixel whose diamond holds (x, y) with the rule's boundary, decided in rationals; written apart from
// the reference's predicates.
std::optional<std::pair<int, int>> holder(const Segment& s, const Vertex& p) {
    const Rational dx = abs(Rational(s.v[1].x) - Rational(s.v[0].x)), dy = abs(Rational(s.v[1].y) - Rational(s.v[0].y));
    const bool y_major = dy > dx;
    const Rational x(p.x), y(p.y);
    for (int j = static_cast<int>(std::floor(p.y)) - 1; j <= static_cast<int>(std::floor(p.y)) + 1; ++j)
        for (int i = static_cast<int>(std::floor(p.x)) - 1; i <= static_cast<int>(std::floor(p.x)) + 1; ++i) {
            const Rational ax = x - Rational(2 * i + 1, 2), ay = y - Rational(2 * j + 1, 2);
            const Rational d = abs(ax) + abs(ay);
            const bool held = d < Rational(1, 2) ||
                              (d == Rational(1, 2) && (ay < 0 || (y_major && ay == 0 && ax > 0)));
            if (held) return std::pair{i, j};
        }
    return std::nullopt;
}

Segment reversed(Segment s) {
    std::swap(s.v[0], s.v[1]);
    return s;
}

std::size_t index(Viewport vp, std::pair<int, int> p) {
    return static_cast<std::size_t>(p.second) * static_cast<std::size_t>(vp.width) + static_cast<std::size_t>(p.first);
}

bool in_viewport(Viewport vp, std::optional<std::pair<int, int>> p) {
    return p && p->first >= 0 && p->first < vp.width && p->second >= 0 && p->second < vp.height;
}

RC_GTEST_PROP(Lines, BresenhamEqualsTheReferenceOnSnappedEnds, ()) {
    const auto [vp, s] = *cases();
    const int bits = *rc::gen::element(4, 8, 16);
    RC_ASSERT(rast::fast::bresenham(s, vp, bits) == rast::reference::lit_pixels(rast::properties::snap(s, bits), vp));
}

// Travelling the other way changes only the pixels whose diamonds hold an end.
RC_GTEST_PROP(Lines, ReversingChangesOnlyTheEnds, ()) {
    const auto [vp, s] = *cases();
    const auto forward = rast::reference::lit_pixels(s, vp), backward = rast::reference::lit_pixels(reversed(s), vp);
    std::vector<std::size_t> changed;
    std::set_symmetric_difference(forward.begin(), forward.end(), backward.begin(), backward.end(),
                                  std::back_inserter(changed));
    std::vector<std::size_t> ends;
    for (const Vertex& v : s.v)
        if (const auto h = holder(s, v); in_viewport(vp, h)) ends.push_back(index(vp, *h));
    for (const std::size_t p : changed) RC_ASSERT(std::find(ends.begin(), ends.end(), p) != ends.end());
}

// A polyline A-B-C: the pixel whose diamond holds B is lit by the second segment alone, exactly when it
// leaves that diamond (C outside it), never by the first.
// B is drawn in or on a diamond of the viewport (offsets on a 1/8 grid reach its boundary).
RC_GTEST_PROP(Lines, APolylineLightsItsJointOnce, ()) {
    auto [vp, first] = *cases();
    const int i = *rc::gen::inRange(0, vp.width), j = *rc::gen::inRange(0, vp.height);
    const int a = *rc::gen::inRange(-4, 5), b = *rc::gen::inRange(-4 + std::abs(a), 5 - std::abs(a));
    first.v[1] = {i + 0.5 + a / 8.0, j + 0.5 + b / 8.0, 0};
    const Vertex c{*rast::gen::coordinate(-2, vp.width + 2.0), *rast::gen::coordinate(-2, vp.height + 2.0), 0};
    const Segment second{{first.v[1], c}};
    const auto joint = holder(first, first.v[1]);
    RC_PRE(in_viewport(vp, joint) && holder(second, first.v[1]) == joint);
    RC_ASSERT(!rast::reference::lights(first, joint->first, joint->second));
    const bool leaves = holder(second, c) != joint;
    RC_ASSERT(rast::reference::lights(second, joint->first, joint->second) == leaves);
}

// A whole-pixel shift, where it is exact, shifts the pixels lit.
RC_GTEST_PROP(Lines, WholePixelShiftsShiftThePixels, ()) {
    const auto [vp, s] = *cases();
    const int di = *rc::gen::inRange(-3, 4), dj = *rc::gen::inRange(-3, 4);
    Segment moved = s;
    for (Vertex& v : moved.v) {
        v.x += di;
        v.y += dj;
    }
    for (int e = 0; e < 2; ++e) RC_PRE(moved.v[e].x - di == s.v[e].x && moved.v[e].y - dj == s.v[e].y);
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i)
            RC_ASSERT(rast::reference::lights(s, i, j) == rast::reference::lights(moved, i + di, j + dj));
}

}  // namespace
