// The double-double depth filter: its enclosures contain the exact depth, its rounding test never
// answers wrongly, and where it cannot decide, the exact path does (and is counted).
#include "bounded_depth.h"
#include "nearest_double.h"
#include "scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace rast::reference {
namespace {

using detail::Bounded;
using detail::BoundedPlane;
using testing::scene;

Triangle with_depth(double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2,
                    double z2) {
    return Triangle{{Vertex{x0, y0, z0}, Vertex{x1, y1, z1}, Vertex{x2, y2, z2}}};
}

// Whether the exact rational q lies in [value - err, value + err].
bool encloses(const Bounded& z, const Rational& q) {
    const Rational value = Rational(z.value.hi) + Rational(z.value.lo);
    return abs(q - value) <= Rational(z.err);
}

// Random triangles of every shape the bound must survive: ordinary ones, slivers whose apex is a few
// ulps off the base, tilted planes whose depth cancels to near zero, and coordinates spread over many
// binades. At points inside and outside, the enclosure holds the exact depth_at, and whenever the
// rounding test answers, it answers the exact depth rounded to nearest; the cheap lower bound lies
// below the exact depth, and on ordinary triangles within 2^-40 of it (so that it turns fragments away).
TEST(BoundedDepth, EnclosesTheExactDepthAndRoundsCorrectly) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> binade(-60, 60), kind(0, 3);
    int decided = 0, points = 0;  // not counting slivers
    for (int n = 0; n < 400; ++n) {
        const int k = kind(rng);
        const double scale = k == 3 ? std::ldexp(1.0, binade(rng)) : 64;
        Triangle t;
        for (Vertex& v : t.v) v = Vertex{scale * unit(rng), scale * unit(rng), k == 2 ? unit(rng) - 0.5 : unit(rng)};
        if (k == 1) {  // the apex nudged a few ulps off the midpoint of the base
            t.v[2].x = std::nextafter((t.v[0].x + t.v[1].x) / 2, 1e300);
            t.v[2].y = std::nextafter(std::nextafter((t.v[0].y + t.v[1].y) / 2, 1e300), 1e300);
        }
        const auto plane = BoundedPlane::make(t);
        if (!plane) continue;  // too thin for the bound: the exact path's business
        for (int m = 0; m < 8; ++m) {
            const double x = std::floor(scale * unit(rng) * 16) / 16, y = std::floor(scale * unit(rng) * 16) / 16;
            const Bounded z = plane->at(plane->row(y), x);
            const Rational exact = depth_at(t, x, y);
            points += k != 1;
            EXPECT_TRUE(encloses(z, exact)) << n << " " << m;
            const Rational lower(plane->lower(plane->row(y))(x));
            EXPECT_LE(lower, exact) << n << " " << m;
            if (k == 0) {
                EXPECT_LT(exact - lower, Rational(0x1p-40)) << n << " " << m;
            }
            if (const auto rounded = detail::nearest(z)) {
                decided += k != 1;
                EXPECT_EQ(*rounded, detail::nearest_double(exact)) << n << " " << m;
            }
        }
    }
    // Away from slivers (whose steep plane cancels wherever it is evaluated, so they go exact) the
    // filter decides, for points inside and outside alike: it is worth having.
    EXPECT_GT(points, 2000);
    EXPECT_GT(decided, points * 9 / 10);
}

// The row's lower bound on its own, against the least value its enclosures allow, base - base.err +
// slope (v - origin) - slope.err |v - origin|, computed exactly. Base and slope are exact half of the time
// (err 0: the coefficients of the bound's rounding terms are then its only slack) and of nearby magnitudes,
// and v and origin a few binades apart, so that rounding d, m and s all err; the bound must cover every
// rounding.
TEST(BoundedDepth, RowLowerBoundIsBelowEveryEnclosedValue) {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> binade(-40, 40), near(-6, 6), coin(0, 1);
    const auto bounded = [&](int e) {  // about 2^e, with a low part and an error half of the time
        const double hi = std::ldexp(unit(rng), e);
        const double lo = coin(rng) ? 0.0 : std::ldexp(unit(rng), e - 54);
        const double err = coin(rng) ? 0.0 : std::ldexp(std::abs(unit(rng)), e - 60);
        return Bounded{detail::two_sum(hi, lo), err};
    };
    for (int n = 0; n < 200000; ++n) {
        const int e = binade(rng), ed = near(rng), es = e - ed + near(rng);
        const double origin = std::ldexp(unit(rng), ed + near(rng)), v = std::ldexp(unit(rng), ed);
        const Bounded base = bounded(e), slope = bounded(es);
        const double lower = detail::AffineLower(base, slope, origin)(v);
        const Rational d = Rational(v) - Rational(origin);
        const Rational least = Rational(base.value.hi) + Rational(base.value.lo) - Rational(base.err) +
                               (Rational(slope.value.hi) + Rational(slope.value.lo)) * d -
                               Rational(slope.err) * abs(d);
        ASSERT_LE(Rational(lower), least) << n;
        // Close enough to turn fragments away: a few ulps of the magnitudes involved.
        const Rational scale = Rational(std::ldexp(1.0, e)) + Rational(std::ldexp(1.0, es)) * abs(d);
        ASSERT_LE(least - Rational(lower), scale * Rational(0x1p-45)) << n;
    }
}

// z = 1 + (x + 1/2) 2^-53: at the centre x = 1/2 the exact depth 1 + 2^-53 is the midpoint between 1
// and the next double, 1 + 2^-52. No enclosure can round it; the exact path rounds the tie to the
// even 1. At x = 3/2 the depth 1 + 2^-52 is a double.
TEST(BoundedDepth, MidpointBetweenDoublesGoesExact) {
    const Triangle t = with_depth(-0.5, 0, 1, 3.5, 0, 1 + 0x1p-51, -0.5, 4, 1);
    const auto plane = BoundedPlane::make(t);
    ASSERT_TRUE(plane);
    EXPECT_FALSE(detail::nearest(plane->at(plane->row(0.5), 0.5)));
    EXPECT_EQ(detail::nearest(plane->at(plane->row(0.5), 1.5)), 1 + 0x1p-52);

    Stats stats;
    const Framebuffer fb = render(scene(2, 1, {t}), &stats);
    EXPECT_EQ(fb.depth[fb.index(0, 0)], 1.0);
    EXPECT_EQ(fb.depth[fb.index(1, 0)], 1 + 0x1p-52);
    EXPECT_EQ(stats.depth_nearest_exact, 1u);
}

// A plane through three zeros of either sign is exactly 0 everywhere, stored as +0 like the exact path.
TEST(BoundedDepth, ZeroPlaneIsExactAndPositiveZero) {
    const Triangle t = with_depth(0, 0, -0.0, 4, 0, -0.0, 0, 4, 0.0);
    const Bounded z = BoundedPlane::make(t)->at(BoundedPlane::make(t)->row(0.5), 0.5);
    EXPECT_EQ(z.err, 0.0);
    Stats stats;
    const Framebuffer fb = render(scene(2, 2, {t}), &stats);
    EXPECT_EQ(fb.depth[fb.index(0, 0)], 0.0);
    EXPECT_FALSE(std::signbit(fb.depth[fb.index(0, 0)]));
    EXPECT_EQ(stats.depth_nearest_exact, 0u);
}

// Outside the safe range there is no bounded plane, and the exact path gives every depth.
TEST(BoundedDepth, OutsideTheSafeRangeEverythingIsExact) {
    EXPECT_FALSE(BoundedPlane::make(with_depth(0, 0, 1e-200, 4, 0, 0, 0, 4, 0)));
    EXPECT_FALSE(BoundedPlane::make(with_depth(0, 0, 0, 0x1p101, 0, 0, 0, 4, 0)));
    EXPECT_FALSE(BoundedPlane::make(with_depth(0, 0, 0, 1, 1, 0, 2, 2, 0)));  // zero area
    EXPECT_TRUE(BoundedPlane::make(with_depth(0, 0, 0x1p-100, 0x1p100, 0, 0, 0, 4, 0)));

    // z = 2^-200 x: depths 2^-201 and 3 * 2^-201 at the two centres.
    Stats stats;
    const Framebuffer fb = render(scene(2, 1, {with_depth(0, 0, 0, 4, 0, 0x1p-198, 0, 4, 0)}), &stats);
    EXPECT_EQ(fb.depth[fb.index(0, 0)], 0x1p-201);
    EXPECT_EQ(fb.depth[fb.index(1, 0)], 3 * 0x1p-201);
    EXPECT_EQ(stats.depth_nearest_exact, 2u);
}

// z = 2^-11 against z = 2^-11 + 2^-65 x (both on [0, 4]^2): at the centre x = 1/2 they are 2^-66 apart,
// below half an ulp of 2^-11 (2^-64), so they round to the same double; the double-double enclosures,
// about 2^-110 wide, still tell them apart without exact arithmetic.
TEST(BoundedDepth, EqualRoundedDepthsSeparatedByTheEnclosures) {
    const Triangle lower = with_depth(0, 0, 0x1p-11, 4, 0, 0x1p-11, 0, 4, 0x1p-11);
    const Triangle upper = with_depth(0, 0, 0x1p-11, 4, 0, 0x1p-11 + 0x1p-63, 0, 4, 0x1p-11);
    const auto at = [](const Triangle& t) { return BoundedPlane::make(t)->at(BoundedPlane::make(t)->row(0.5), 0.5); };
    EXPECT_EQ(detail::nearest(at(lower)), detail::nearest(at(upper)));
    EXPECT_EQ(detail::certain_sign_of_difference(at(lower), at(upper)), -1);
    EXPECT_EQ(detail::certain_sign_of_difference(at(upper), at(lower)), 1);
    EXPECT_EQ(detail::certain_sign_of_difference(at(lower), at(lower)), 0);

    Stats stats;
    const Framebuffer fb = render(scene(1, 1, {upper, lower}), &stats);
    EXPECT_EQ(fb.id(0, 0), 1);
    EXPECT_EQ(stats.depth_tests, 1u);
    EXPECT_EQ(stats.depth_exact, 0u);
}

}  // namespace
}  // namespace rast::reference
