// Depth: exact plane values, the (z, id) order of the z-buffer, and depths rounded to nearest.
#include "nearest_double.h"
#include "scenes.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rast::reference {
namespace {

using testing::flat;
using testing::picture;
using testing::reversed;
using testing::scene;

Triangle with_depth(double x0, double y0, double z0, double x1, double y1, double z1, double x2, double y2,
                    double z2) {
    return Triangle{{Vertex{x0, y0, z0}, Vertex{x1, y1, z1}, Vertex{x2, y2, z2}}};
}

// z = x/3 + 2y/3 through (0, 0, 0), (3, 0, 1), (0, 3, 2).
TEST(Depth, DepthAtIsTheExactPlane) {
    const Triangle t = with_depth(0, 0, 0, 3, 0, 1, 0, 3, 2);
    for (const Triangle& u : {t, reversed(t)}) {
        EXPECT_EQ(depth_at(u, 1, 1), Rational(1));
        EXPECT_EQ(depth_at(u, 0.5, 0.5), Rational(1, 2));
        EXPECT_EQ(depth_at(u, 1, 0), Rational(1, 3));
        EXPECT_EQ(depth_at(u, 0, 0.25), Rational(1, 6));
        EXPECT_EQ(depth_at(u, 3, 3), Rational(3));  // the plane, also outside the triangle
        // Points off the 1/16 grid of the sample positions, down to the smallest subnormal.
        EXPECT_EQ(depth_at(u, 0.1, 0), Rational(0.1) / 3);
        EXPECT_EQ(depth_at(u, 0, 0.1), Rational(0.1) * 2 / 3);
        const double d = std::numeric_limits<double>::denorm_min();
        EXPECT_EQ(depth_at(u, d, d), Rational(d));
    }
    // Vertices off that grid, and depths that are not integers.
    // z = 1/4 + (x - x0) (1/2) / (x1 - x0), with x0 and x1 the doubles nearest 0.1 and 1.1.
    const Triangle fine = with_depth(0.1, 0, 0.25, 1.1, 0, 0.75, 0.1, 1, 0.25);
    EXPECT_EQ(depth_at(fine, 0.6, 7),
              Rational(1, 4) + (Rational(0.6) - Rational(0.1)) / 2 / (Rational(1.1) - Rational(0.1)));
    // z = x / 2^60 on a triangle with vertices at 2^60.
    const double big = std::ldexp(1.0, 60);
    const Rational two_to_60 = Rational(boost::multiprecision::mpz_int(1) << 60);
    EXPECT_EQ(depth_at(with_depth(0, 0, 0, big, 0, 1, 0, big, 0), 3, 5), Rational(3) / two_to_60);
}

TEST(Depth, DepthAtRejectsZeroAreaAndNonFiniteInput) {
    EXPECT_THROW(depth_at(flat(0, 0, 1, 1, 2, 2), 0.5, 0.5), std::invalid_argument);
    EXPECT_THROW(depth_at(flat(0, 0, 1, 0, 0, 1), std::numeric_limits<double>::quiet_NaN(), 0),
                 std::invalid_argument);
}

// Rounding to nearest, ties to even, checked against values whose rounding is known: IEEE division of
// two exact doubles is correctly rounded, and powers of two are exact.
TEST(Depth, NearestDoubleRoundsToNearestTiesToEven) {
    using boost::multiprecision::mpz_int;
    using detail::nearest_double;
    const auto pow2 = [](int e) {
        return e >= 0 ? Rational(mpz_int(1) << e) : Rational(mpz_int(1), mpz_int(1) << -e);
    };
    EXPECT_EQ(nearest_double(Rational(0)), 0.0);
    EXPECT_EQ(nearest_double(Rational(1, 3)), 1.0 / 3.0);
    EXPECT_EQ(nearest_double(Rational(5, 6)), 5.0 / 6.0);  // truncation would give the double below
    EXPECT_EQ(nearest_double(Rational(-5, 6)), -5.0 / 6.0);
    EXPECT_EQ(nearest_double(Rational(1, 10)), 0.1);
    EXPECT_EQ(nearest_double(pow2(53) + 1), std::ldexp(1.0, 53));      // tie, to the even 2^53
    EXPECT_EQ(nearest_double(pow2(53) + 3), std::ldexp(1.0, 53) + 4);  // tie, to the even 2^53 + 4
    EXPECT_EQ(nearest_double(-(pow2(53) + 3)), -(std::ldexp(1.0, 53) + 4));
    const double d = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(nearest_double(pow2(-1075)), 0.0);                  // half of d: tie, to even 0
    EXPECT_EQ(nearest_double(3 * pow2(-1075)), 2 * d);            // 1.5 d: tie, to even 2d
    EXPECT_EQ(nearest_double(pow2(-1075) + pow2(-1100)), d);      // just above half of d
    EXPECT_EQ(nearest_double(Rational(DBL_MAX)), DBL_MAX);
    EXPECT_EQ(nearest_double(pow2(1024)), std::numeric_limits<double>::infinity());
    EXPECT_EQ(nearest_double(-pow2(1024)), -std::numeric_limits<double>::infinity());
}

// The rendered depth is the exact depth rounded to nearest: z = x/3 at the centres gives (2i + 1)/6.
TEST(Depth, RenderedDepthsAreExactDepthsRounded) {
    const Framebuffer thirds = render(scene(6, 1, {with_depth(0, -10, 0, 30, -10, 10, 0, 20, 0)}));
    const Framebuffer tenths = render(scene(6, 1, {with_depth(0, -10, 0, 30, -10, 3, 0, 20, 0)}));
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(thirds.depth[thirds.index(i, 0)], (2 * i + 1) / 6.0) << i;
        EXPECT_EQ(tenths.depth[tenths.index(i, 0)], (2 * i + 1) / 20.0) << i;
    }
}

// Two triangles in the plane z = x/8 + y/16: the big one covers the 4x4 viewport, the small one the
// centres with x >= 1, y > 1, x + y < 6. Where they overlap the depths are equal and the smaller id
// wins, whichever is listed first.
TEST(Depth, EqualDepthsAreDecidedById) {
    const Triangle big = with_depth(-10, -10, -1.875, 30, -10, 3.125, -10, 30, 0.625);
    const Triangle small = with_depth(1, 1, 0.1875, 5, 1, 0.6875, 1, 5, 0.4375);

    Stats stats;
    const Framebuffer big_first = render(scene(4, 4, {big, small}), &stats);
    EXPECT_EQ(picture(big_first), R"(
0000
0000
0000
0000
)");
    EXPECT_EQ(stats.depth_tests, 6u);
    EXPECT_EQ(stats.depth_exact, 6u);  // equal depths: no enclosure can separate them

    const Framebuffer small_first = render(scene(4, 4, {small, big}));
    EXPECT_EQ(picture(small_first), R"(
1011
1001
1000
1111
)");
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const double z = (i + 0.5) / 8 + (j + 0.5) / 16;
            EXPECT_EQ(big_first.depth[big_first.index(i, j)], z);
            EXPECT_EQ(small_first.depth[small_first.index(i, j)], z);
        }
}

// z = x - 2.5 against z = 2.5 - x: the first is nearer left of x = 2.5, the second right of it, and on
// the column of centres x = 2.5 they tie (z = 0) and the smaller id wins.
TEST(Depth, InterpenetratingTrianglesFlipAcrossALineOfCentres) {
    const Triangle rising = with_depth(-10, -10, -12.5, 30, -10, 27.5, -10, 30, -12.5);
    const Triangle falling = with_depth(-10, -10, 12.5, 30, -10, -27.5, -10, 30, 12.5);

    Stats stats;
    const Framebuffer fb = render(scene(4, 2, {rising, falling}), &stats);
    EXPECT_EQ(picture(fb), "\n0001\n0001\n");
    EXPECT_EQ(stats.depth_tests, 8u);
    EXPECT_EQ(stats.depth_exact, 2u);  // only the ties; elsewhere the depths differ by at least 2
    const double expected_depth[] = {-2, -1, 0, -1};
    for (int i = 0; i < 4; ++i) EXPECT_EQ(fb.depth[fb.index(i, 1)], expected_depth[i]);

    EXPECT_EQ(picture(render(scene(4, 2, {falling, rising}))), "\n1100\n1100\n");
}

TEST(Depth, EmptySamplesKeepInfiniteDepth) {
    const Framebuffer fb = render(scene(3, 1, {flat(0, 0, 2, 0, 0, 2)}));  // (2.5, 0.5) is outside
    EXPECT_EQ(fb.id(0, 0), 0);
    EXPECT_EQ(fb.depth[fb.index(0, 0)], 0.0);
    EXPECT_EQ(fb.id(2, 0), Framebuffer::kNoTriangle);
    EXPECT_EQ(fb.depth[fb.index(2, 0)], std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace rast::reference
