// Exact area coverage: Sutherland–Hodgman in rationals, areas worked out by hand.
#include "scenes.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <random>

namespace rast::reference {
namespace {

using testing::flat;
using testing::reversed;

TEST(Area, HalfPixelTriangleIsExactlyOneHalf) {
    const Triangle t = flat(0, 0, 1, 0, 0, 1);
    EXPECT_EQ(pixel_area(t, 0, 0), Rational(1, 2));
    EXPECT_EQ(pixel_area(reversed(t), 0, 0), Rational(1, 2));
    EXPECT_EQ(pixel_area(t, 1, 0), Rational(0));
}

// The last column an int names: (c, 0), (c + 2, 0), (c, 2) with c = INT_MAX holds pixel (c, 0) whole (its far
// corner (c + 1, 1) is on the hypotenuse). Its right side c + 1 is past INT_MAX, where int overflowed.
TEST(Area, PixelInTheLastColumnAnIntNames) {
    const double c = INT_MAX;
    EXPECT_EQ(pixel_area(flat(c, 0, c + 2, 0, c, 2), INT_MAX, 0), Rational(1));
}

// (0, 0), (2, 0), (0, 2): pixel (0, 0) is inside, (1, 0) and (0, 1) are cut on their diagonal, (1, 1)
// only touches at a corner.
TEST(Area, TriangleOverFourPixels) {
    const auto coverage = coverage_area(testing::scene(2, 2, {flat(0, 0, 2, 0, 0, 2)}));
    EXPECT_EQ(coverage, (std::vector<Rational>{Rational(1), Rational(1, 2), Rational(1, 2), Rational(0)}));
}

// x/3 + y <= 1 over the unit squares of row 0: the integrals of 1 - x/3 over [0,1], [1,2], [2,3].
TEST(Area, NonDyadicAreas) {
    const Triangle t = flat(0, 0, 3, 0, 0, 1);
    EXPECT_EQ(pixel_area(t, 0, 0), Rational(5, 6));
    EXPECT_EQ(pixel_area(t, 1, 0), Rational(1, 2));
    EXPECT_EQ(pixel_area(t, 2, 0), Rational(1, 6));
}

// The pixel square (0, 0) cut into four triangles at its centre, and into a fan around an arbitrary
// interior point: the pieces sum to exactly 1.
TEST(Area, PixelTiledByTrianglesSumsToOne) {
    const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& [cx, cy] : {std::pair{0.5, 0.5}, std::pair{0.3, 0.7}, std::pair{0.1, 0.0}}) {
        Scene tiled{Viewport{1, 1}, 1, {}};
        for (int k = 0; k < 4; ++k)
            tiled.triangles.push_back(
                flat(cx, cy, corners[k][0], corners[k][1], corners[(k + 1) % 4][0], corners[(k + 1) % 4][1]));
        EXPECT_EQ(coverage_area(tiled), std::vector<Rational>{Rational(1)}) << cx << ", " << cy;
    }
    Scene quarters{Viewport{1, 1}, 1, {}};
    for (int k = 0; k < 4; ++k)
        quarters.triangles.push_back(
            flat(0.5, 0.5, corners[k][0], corners[k][1], corners[(k + 1) % 4][0], corners[(k + 1) % 4][1]));
    for (const Triangle& t : quarters.triangles) EXPECT_EQ(pixel_area(t, 0, 0), Rational(1, 4));
}

TEST(Area, TriangleFarLargerThanTheViewportCoversEveryPixelFully) {
    for (const double big : {1e6, std::ldexp(1.0, 60), DBL_MAX}) {
        const auto coverage = coverage_area(testing::scene(4, 3, {flat(-big, -big, big, -big, 0, big)}));
        EXPECT_EQ(coverage, std::vector<Rational>(12, Rational(1))) << big;
    }
}

// Above the diagonal y = x, drawn with vertices at 2^60: the diagonal pixels are cut exactly in half.
TEST(Area, HugeCoordinatesCutExactly) {
    const double big = std::ldexp(1.0, 60);
    const auto coverage = coverage_area(testing::scene(2, 2, {flat(0, 0, big, big, 0, big)}));
    EXPECT_EQ(coverage, (std::vector<Rational>{Rational(1, 2), Rational(0), Rational(1), Rational(1, 2)}));
}

TEST(Area, ZeroAreaAndOutsideTrianglesCoverNothing) {
    EXPECT_EQ(pixel_area(flat(0, 0, 0.5, 0.5, 1, 1), 0, 0), Rational(0));
    EXPECT_EQ(pixel_area(flat(0.25, 0.25, 0.25, 0.25, 0.75, 0.5), 0, 0), Rational(0));
    const auto coverage = coverage_area(testing::scene(2, 1, {flat(-5, -5, -1, -5, -5, -1)}));
    EXPECT_EQ(coverage, std::vector<Rational>(2, Rational(0)));
}

// Overlapping triangles are summed, depth ignored: two copies of the half-pixel triangle give 1.
TEST(Area, OverlapsAreSummed) {
    const Triangle half = flat(0, 0, 1, 0, 0, 1);
    EXPECT_EQ(coverage_area(testing::scene(1, 1, {half, reversed(half)})), std::vector<Rational>{Rational(1)});
}

// Random triangles inside an 8x8 viewport: per pixel, the row sweep of coverage_area (which skips the
// clipping of inner pixels) agrees with pixel_area, and the pixels add up to the triangle's area
// |(b - a) x (c - a)| / 2.
TEST(Area, PixelsSumToTheTriangleArea) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> inside(0, 8);
    std::uniform_int_distribution<int> on_grid(0, 32);
    for (int n = 0; n < 40; ++n) {
        const auto coordinate = [&] { return n % 2 ? inside(rng) : on_grid(rng) / 4.0; };
        const Triangle t = flat(coordinate(), coordinate(), coordinate(), coordinate(), coordinate(), coordinate());
        const auto coverage = coverage_area(testing::scene(8, 8, {t}));
        Rational sum(0);
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
                EXPECT_EQ(coverage[static_cast<std::size_t>(j * 8 + i)], pixel_area(t, i, j));
                sum += coverage[static_cast<std::size_t>(j * 8 + i)];
            }
        const Rational ax(t.v[0].x), ay(t.v[0].y);
        const Rational cross = (Rational(t.v[1].x) - ax) * (Rational(t.v[2].y) - ay) -
                               (Rational(t.v[2].x) - ax) * (Rational(t.v[1].y) - ay);
        EXPECT_EQ(sum, abs(cross) / 2);
    }
}

}  // namespace
}  // namespace rast::reference
