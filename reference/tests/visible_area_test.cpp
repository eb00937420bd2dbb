// The exact visible area: small cases worked out by hand, and the cut's independence of insertion order.
#include "scenes.h"

#include <rast/visible_area.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <random>
#include <vector>

namespace rast::reference {
namespace {

using testing::flat;
using testing::reversed;

// A triangle whose depth plane is z = a x + b y + c, from its screen-space vertices.
Triangle on_plane(double a, double b, double c, double x0, double y0, double x1, double y1, double x2, double y2) {
    const auto z = [&](double x, double y) { return a * x + b * y + c; };
    return Triangle{{Vertex{x0, y0, z(x0, y0)}, Vertex{x1, y1, z(x1, y1)}, Vertex{x2, y2, z(x2, y2)}}};
}

// Covers pixel (0, 0) and its neighbours whole.
Triangle large_on_plane(double a, double b, double c) { return on_plane(a, b, c, -4, -4, 8, -4, -4, 8); }

using Pieces = std::vector<VisiblePiece>;

Pieces pixel(const Scene& scene, int i = 0, int j = 0) {
    const VisibleArea area = visible_area(scene);
    const auto span = area.at(i, j);
    return Pieces(span.begin(), span.end());
}

// z = x and z = y / 2 meet along x = y / 2: the first is nearer left of it, a triangle of area 1/4.
TEST(VisibleArea, TwoTrianglesCrossingAlongAKnownLine) {
    const Scene s = testing::scene(1, 1, {large_on_plane(1, 0, 0), large_on_plane(0, 0.5, 0)});
    EXPECT_EQ(pixel(s), (Pieces{{0, Rational(1, 4)}, {1, Rational(3, 4)}}));
}

// Equal depths where they overlap: the lower id owns the overlap, whichever triangle it is.
TEST(VisibleArea, CoplanarOverlapGoesToTheLowerId) {
    const Triangle half = flat(0, 0, 1, 0, 0, 1), whole = large_on_plane(0, 0, 0);
    EXPECT_EQ(pixel(testing::scene(1, 1, {half, whole})), (Pieces{{0, Rational(1, 2)}, {1, Rational(1, 2)}}));
    EXPECT_EQ(pixel(testing::scene(1, 1, {whole, half})), (Pieces{{0, Rational(1)}}));
}

// The pixel cut into a fan around (1/4, 1/2): bases of length 1, heights 1/2, 3/4, 1/2, 1/4, each at its
// own depth; nothing overlaps, so each keeps its own area.
TEST(VisibleArea, ClosedFanKeepsEachTrianglesArea) {
    const Scene s = testing::scene(1, 1,
                                   {on_plane(0, 0, 5, 0.25, 0.5, 0, 0, 1, 0), on_plane(0, 0, 1, 0.25, 0.5, 1, 0, 1, 1),
                                    on_plane(0, 0, 3, 0.25, 0.5, 1, 1, 0, 1), on_plane(0, 0, 2, 0.25, 0.5, 0, 1, 0, 0)});
    EXPECT_EQ(pixel(s), (Pieces{{0, Rational(1, 4)}, {1, Rational(3, 8)}, {2, Rational(1, 4)}, {3, Rational(1, 8)}}));
}

// Three layers covering the pixel: the nearest gets it all; a half-pixel triangle in front of the stack
// takes its half.
TEST(VisibleArea, StackCoveringThePixel) {
    const Triangle back = large_on_plane(0, 0, 3), front = large_on_plane(0, 0, 1), middle = large_on_plane(0, 0, 2);
    EXPECT_EQ(pixel(testing::scene(1, 1, {back, front, middle})), (Pieces{{1, Rational(1)}}));
    const Triangle nearest = on_plane(0, 0, 0, 0, 0, 1, 0, 0, 1);
    EXPECT_EQ(pixel(testing::scene(1, 1, {back, front, middle, nearest})),
              (Pieces{{1, Rational(1, 2)}, {3, Rational(1, 2)}}));
}

// Winding changes nothing; a triangle of zero area and one outside the viewport are never visible; an
// empty pixel has no pieces.
TEST(VisibleArea, WindingDegenerateAndEmptyPixels) {
    const Triangle t = flat(0, 0, 1, 0, 0, 1);
    const Triangle line = flat(0, 0, 1, 1, 0.5, 0.5), away = flat(5, 5, 6, 5, 5, 6);
    const Scene s = testing::scene(2, 1, {reversed(t), line, away});
    EXPECT_EQ(pixel(s, 0, 0), (Pieces{{0, Rational(1, 2)}}));
    EXPECT_TRUE(visible_area(s).at(1, 0).empty());
}

// A plane steep enough to cross the pixel only partly: z = 4x - 1 against z = 1 meets at x = 1/2, with a
// triangle that ends at y = 1/2 (area 1/2 of the pixel); the front part is 1/4.
TEST(VisibleArea, CrossingInsideAPartialOverlap) {
    const Scene s = testing::scene(1, 1, {on_plane(4, 0, -1, -4, -4, 20, 0.5, -4, 0.5), large_on_plane(0, 0, 1)});
    EXPECT_EQ(pixel(s), (Pieces{{0, Rational(1, 4)}, {1, Rational(3, 4)}}));
}

// Worked by hand: areas 1/4 (id 0) and 1/2 (id 1), nothing 1/4. Samples 0, 0, 1, -1: fractions 1/2, 1/4,
// 1/4; differences 1/4, -1/4, 0; half their sum is 1/4. Samples matching the areas' proportions differ
// by nothing, and a sample of an id that sees nothing there counts fully.
TEST(VisibleArea, ResolveErrorIsTheTotalVariation) {
    const Pieces areas{{0, Rational(1, 4)}, {1, Rational(1, 2)}};
    EXPECT_EQ(resolve_error(areas, std::vector<std::int32_t>{0, 0, 1, -1}), Rational(1, 4));
    EXPECT_EQ(resolve_error(areas, std::vector<std::int32_t>{0, 1, 1, -1}), 0);
    EXPECT_EQ(resolve_error(Pieces{}, std::vector<std::int32_t>{7}), 1);
    EXPECT_EQ(resolve_error(Pieces{{3, Rational(1)}}, std::vector<std::int32_t>{-1, 3}), Rational(1, 2));
}

// A triangle over x in [0, 2] reaches pixels 0 and 1 (not 2, which it only touches); one inside pixel 0:
// two pixels cut, three (triangle, pixel) pairs.
TEST(VisibleArea, StatsCountTheTrianglesEachPixelCuts) {
    VisibleStats stats;
    visible_area(testing::scene(3, 1, {flat(0, 0, 2, 0, 0, 1), flat(0.25, 0.25, 0.75, 0.25, 0.25, 0.75)}), {}, 1, &stats);
    EXPECT_EQ(stats.pixels_cut, 2u);
    EXPECT_EQ(stats.candidates, 3u);
}

// Several pixels, rows on several threads: every thread count gives the same areas, the progress counts
// rows from 0 to the last, one call at a time.
TEST(VisibleArea, ThreadsAndProgress) {
    Scene s{Viewport{7, 9}, 1, {}};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coordinate(-1, 10), depth(0, 1);
    for (int k = 0; k < 12; ++k)
        s.triangles.push_back(Triangle{{Vertex{coordinate(rng), coordinate(rng), depth(rng)},
                                        Vertex{coordinate(rng), coordinate(rng), depth(rng)},
                                        Vertex{coordinate(rng), coordinate(rng), depth(rng)}}});
    std::vector<std::size_t> reports;
    std::mutex m;
    const VisibleArea one = visible_area(s, {}, 1);
    const VisibleArea two = visible_area(
        s,
        [&](std::size_t done, std::size_t total) {
            const std::unique_lock lock(m, std::try_to_lock);
            ASSERT_TRUE(lock.owns_lock());
            EXPECT_EQ(total, 9u);
            reports.push_back(done);
        },
        2);
    for (int j = 0; j < 9; ++j)
        for (int i = 0; i < 7; ++i) {
            const auto a = one.at(i, j), b = two.at(i, j);
            EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << i << ", " << j;
        }
    ASSERT_EQ(reports.size(), 10u);
    EXPECT_EQ(reports.front(), 0u);
    EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
    EXPECT_EQ(reports.back(), 9u);
}

// Any insertion order cuts the pixel the same way. Coordinates on a 1/8 grid and depths from a few
// small integers make shared lines, vertices on the pixel's sides and coplanar overlaps common: half the
// triangles lie flat at depth 0 or 1.
TEST(VisibleArea, InsertionOrderChangesNothing) {
    std::mt19937 rng(20261126);
    std::uniform_int_distribution<int> eighth(-8, 16), level(0, 3);
    for (int round = 0; round < 400; ++round) {
        Scene s{Viewport{1, 1}, 1, {}};
        for (int k = 0; k < 5; ++k) {
            Triangle t;
            const bool flat_one = level(rng) < 2;
            const double z = level(rng) % 2;
            for (Vertex& v : t.v)
                v = Vertex{eighth(rng) / 8.0, eighth(rng) / 8.0, flat_one ? z : static_cast<double>(level(rng))};
            s.triangles.push_back(t);
        }
        const Pieces first = pixel(s);
        Rational total(0);
        for (const VisiblePiece& p : first) total += p.area;
        EXPECT_LE(total, 1);
        std::vector<std::size_t> order{0, 1, 2, 3, 4};
        for (int shuffle = 0; shuffle < 4; ++shuffle) {
            std::shuffle(order.begin(), order.end(), rng);
            ASSERT_EQ(visible_in_pixel(s, 0, 0, order), first) << "round " << round;
        }
    }
}

// A pixel alone sees only the triangles named; naming one that is not there, or one twice, is an error.
TEST(VisibleArea, OnePixelWithTheTrianglesNamed) {
    const Scene s = testing::scene(1, 1, {large_on_plane(1, 0, 0), large_on_plane(0, 0.5, 0)});
    EXPECT_EQ(visible_in_pixel(s, 0, 0, std::vector<std::size_t>{1}), (Pieces{{1, Rational(1)}}));
    EXPECT_EQ(visible_in_pixel(s, 0, 0, std::vector<std::size_t>{}), Pieces{});
    EXPECT_THROW(visible_in_pixel(s, 0, 0, std::vector<std::size_t>{2}), std::invalid_argument);
    EXPECT_THROW(visible_in_pixel(s, 0, 0, std::vector<std::size_t>{0, 0}), std::invalid_argument);
    EXPECT_THROW(visible_in_pixel(s, 1, 0, std::vector<std::size_t>{0}), std::invalid_argument);
    EXPECT_THROW(visible_in_pixel(s, 0, -1, std::vector<std::size_t>{0}), std::invalid_argument);
}

// Offsets that do not fit the viewport or the pieces, and a viewport of no pixels, are refused.
TEST(VisibleArea, ItsPartsMustFit) {
    EXPECT_THROW(VisibleArea(Viewport{-1, -1}, {0, 0}, {}), std::invalid_argument);
    EXPECT_THROW(VisibleArea(Viewport{0, 5}, {0}, {}), std::invalid_argument);
    EXPECT_THROW(VisibleArea(Viewport{1, 1}, {0, 1}, {}), std::invalid_argument);
    EXPECT_NO_THROW(VisibleArea(Viewport{1, 1}, {0, 0}, {}));
}

// Planes so steep that their slopes overflow double: the rough front-to-back key is then NaN, which
// must still give an order (the areas are exact whatever the order).
TEST(VisibleArea, PlanesBeyondDoublesRange) {
    Scene s{Viewport{4, 4}, 1, {}};
    for (int k = 0; k < 40; ++k) {
        const double x0 = 2 + k * 0x1p-45, dx = 0x1p-40;
        s.triangles.push_back(Triangle{{Vertex{x0, -1, 0}, Vertex{x0 + dx, -1, (k % 2 ? 1 : -1) * 1.7e308},
                                        Vertex{x0, 5, (k % 3) * 5e307}}});
    }
    const VisibleArea area = visible_area(s);
    std::vector<std::size_t> order(s.triangles.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = order.size() - 1 - k;
    for (int j = 0; j < 4; ++j) {
        const auto expected = visible_in_pixel(s, 2, j, order);
        const auto got = area.at(2, j);
        EXPECT_TRUE(std::equal(got.begin(), got.end(), expected.begin(), expected.end())) << j;
    }
}

TEST(VisibleArea, ResolveErrorNeedsSamples) {
    EXPECT_THROW(resolve_error(Pieces{}, std::vector<std::int32_t>{}), std::invalid_argument);
}

}  // namespace
}  // namespace rast::reference
