// Coverage: the lecture's inside() with the top-left tie rule, decided exactly. Every expected picture
// was worked out by hand from the edge equations given in the comments.
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

// A = (1, 1), B = (7, 3), C = (3, 6), counter-clockwise. Pixel centres (i + 1/2, j + 1/2) are covered
// where x >= 1 + 2(y - 1)/5 (CA, a left edge), x < 1 + 3(y - 1) (AB, a right edge: the centres
// (2.5, 1.5) and (5.5, 2.5) lie exactly on it and are not covered) and x <= 7 + 4(3 - y)/3 (BC).
TEST(Coverage, LectureExampleTriangle) {
    const Triangle t = flat(1, 1, 7, 3, 3, 6);
    const char* expected = R"(
........
...0....
..000...
..0000..
..000...
.0......
........
)";
    EXPECT_EQ(picture(render(scene(8, 7, {t}))), expected);
    EXPECT_EQ(picture(render(scene(8, 7, {reversed(t)}))), expected);
    EXPECT_FALSE(covers(t, 2.5, 1.5));
    EXPECT_FALSE(covers(t, 5.5, 2.5));
    EXPECT_TRUE(covers(t, 1.5, 1.5));
}

// Left edge x = 1.5 (covered), bottom edge y = 0.5 and right edge x + y = 5 (not covered); every
// vertex is a pixel centre and none is covered (each touches a bottom or right edge).
TEST(Coverage, LeftEdgeCoveredBottomAndRightEdgesNot) {
    const Triangle t = flat(1.5, 0.5, 4.5, 0.5, 1.5, 3.5);
    const char* expected = R"(
......
......
.0....
.00...
......
)";
    EXPECT_EQ(picture(render(scene(6, 5, {t}))), expected);
    EXPECT_EQ(picture(render(scene(6, 5, {reversed(t)}))), expected);
}

// Top edge y = 3.5 and left edge x = 1.5 (covered), right edge y = x - 1 (not). The vertex (1.5, 3.5)
// joins a top and a left edge and is covered; (4.5, 3.5) and (1.5, 0.5) touch the right edge.
TEST(Coverage, TopAndLeftEdgesCoveredRightEdgeNot) {
    const Triangle t = flat(1.5, 0.5, 4.5, 3.5, 1.5, 3.5);
    const char* expected = R"(
......
.000..
.00...
.0....
......
)";
    EXPECT_EQ(picture(render(scene(6, 5, {t}))), expected);
    EXPECT_EQ(picture(render(scene(6, 5, {reversed(t)}))), expected);
    for (const Triangle& u : {t, reversed(t)}) {
        EXPECT_TRUE(covers(u, 1.5, 3.5));
        EXPECT_FALSE(covers(u, 4.5, 3.5));
        EXPECT_FALSE(covers(u, 1.5, 0.5));
    }
}

// Right edge x = 4.5 (not covered), top edge y = 3.5 and left edge x + y = 5 (covered).
TEST(Coverage, VerticalRightEdgeNotCovered) {
    const Triangle t = flat(4.5, 0.5, 4.5, 3.5, 1.5, 3.5);
    const char* expected = R"(
......
.000..
..00..
...0..
......
)";
    EXPECT_EQ(picture(render(scene(6, 5, {t}))), expected);
    EXPECT_EQ(picture(render(scene(6, 5, {reversed(t)}))), expected);
}

// The square [1.5, 4.5]^2 shifted down by one, split on either diagonal: every centre of the square is
// covered exactly once (x = 4.5 and y = 0.5 are right and bottom sides), and the centres on the
// diagonal belong to the triangle for which the diagonal is a left edge.
TEST(Coverage, SquareSplitOnAntiDiagonal) {
    const Triangle lower = flat(1.5, 0.5, 4.5, 0.5, 1.5, 3.5);  // diagonal x + y = 5 is its right edge
    const Triangle upper = flat(4.5, 0.5, 4.5, 3.5, 1.5, 3.5);  // ... and this one's left edge
    const char* expected = R"(
......
.111..
.011..
.001..
......
)";
    EXPECT_EQ(picture(render(scene(6, 5, {lower, upper}))), expected);
    EXPECT_EQ(picture(render(scene(6, 5, {reversed(lower), reversed(upper)}))), expected);
}

TEST(Coverage, SquareSplitOnMainDiagonal) {
    const Triangle upper = flat(1.5, 0.5, 4.5, 3.5, 1.5, 3.5);  // diagonal y = x - 1 is its right edge
    const Triangle lower = flat(1.5, 0.5, 4.5, 0.5, 4.5, 3.5);  // ... and this one's left edge
    const char* expected = R"(
......
.000..
.001..
.011..
......
)";
    EXPECT_EQ(picture(render(scene(6, 5, {upper, lower}))), expected);
    EXPECT_EQ(picture(render(scene(6, 5, {reversed(upper), reversed(lower)}))), expected);
}

// The square [0.1, 2.7]^2 split on y = x, through the centres (0.5, 0.5), (1.5, 1.5) and (2.5, 2.5). The
// diagonal's ends have equal coordinates, so those centres lie exactly on it; but 2.7 - 0.1 and 0.5 - 0.1
// round in double, so neither the static filter nor interval arithmetic can tell zero from a tiny value,
// and the exact arithmetic decides. The diagonal is the lower triangle's left edge (covered) and the
// upper one's right edge (not covered).
TEST(Coverage, DiagonalThroughCentresDecidedByExactArithmetic) {
    const Triangle lower = flat(0.1, 0.1, 2.7, 0.1, 2.7, 2.7);
    const Triangle upper = flat(0.1, 0.1, 2.7, 2.7, 0.1, 2.7);
    const char* expected = R"(
110
100
000
)";
    Stats stats;
    EXPECT_EQ(picture(render(scene(3, 3, {lower, upper}), &stats)), expected);
    EXPECT_GE(stats.orientation_exact, 3u);
    EXPECT_EQ(picture(render(scene(3, 3, {reversed(lower), reversed(upper)}))), expected);
    for (const double c : {0.5, 1.5, 2.5}) {  // each centre exactly once, whatever the z-buffer would hide
        EXPECT_TRUE(covers(lower, c, c)) << c;
        EXPECT_FALSE(covers(upper, c, c)) << c;
    }
}

// Eight triangles around the pixel centre c = (4.5, 4.5), spokes towards E, NE, N, ..., SE. Triangle k
// is (c, P_k, P_k+1). c is covered by triangle k iff spoke c->P_k is a covered edge (it points down, or
// left: k in {4, 5, 6, 7}) and spoke P_k+1->c is one (k + 1 in {0, 1, 2, 3} mod 8): only k = 7. The
// fan's union is the square [0.5, 8.5]^2, whose left and top sides are covered: 8 x 8 centres.
TEST(Coverage, ClosedFanCoversItsCentreOnce) {
    const double c = 4.5;
    const double ring[8][2] = {{8.5, 4.5}, {8.5, 8.5}, {4.5, 8.5}, {0.5, 8.5},
                               {0.5, 4.5}, {0.5, 0.5}, {4.5, 0.5}, {8.5, 0.5}};
    Scene fan{Viewport{10, 10}, 1, {}};
    for (int k = 0; k < 8; ++k)
        fan.triangles.push_back(flat(c, c, ring[k][0], ring[k][1], ring[(k + 1) % 8][0], ring[(k + 1) % 8][1]));

    int centre_hits = 0;
    for (const Triangle& t : fan.triangles) centre_hits += covers(t, c, c);
    EXPECT_EQ(centre_hits, 1);

    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) {
            int hits = 0;
            for (const Triangle& t : fan.triangles) hits += covers(t, i + 0.5, j + 0.5);
            const bool in_square = i <= 7 && j >= 1 && j <= 8;
            EXPECT_EQ(hits, in_square ? 1 : 0) << "pixel " << i << ", " << j;
        }

    Stats stats;
    const Framebuffer fb = render(fan, &stats);
    EXPECT_EQ(fb.id(4, 4), 7);
    EXPECT_EQ(stats.samples_covered, 64u);
    EXPECT_EQ(stats.depth_tests, 0u);
}

// A needle from (0, 2.5) to x = 10, 0.02 wide there: the centre line y = 2.5 is strictly inside for
// x > 0, so exactly the ten centres (0.5 .. 9.5, 2.5).
TEST(Coverage, HorizontalNeedle) {
    const Triangle t = flat(0, 2.5, 10, 2.49, 10, 2.51);
    EXPECT_EQ(picture(render(scene(12, 5, {t}))), R"(
............
............
0000000000..
............
............
)");
}

// Needles along the diagonal through the centres (k + 1/2, k + 1/2), 2^-20 wide at the far end. Above
// the diagonal it is a right edge: nothing. Below it is a left edge: the centres k = 1..8. The far end
// (8.5, 8.5) joins that left edge and a top edge, so it is covered; (0.5, 0.5) touches a right edge.
TEST(Coverage, DiagonalNeedlesOnCentres) {
    const double w = std::ldexp(1.0, -20);
    EXPECT_TRUE(covered_samples(flat(0.5, 0.5, 8.5, 8.5, 8.5, 8.5 + w), Viewport{10, 10}, 1).empty());
    const Triangle below = flat(0.5, 0.5, 8.5, 8.5, 8.5 + w, 8.5);
    std::vector<std::size_t> expected;
    for (std::size_t k = 1; k <= 8; ++k) expected.push_back(k * 10 + k);
    EXPECT_EQ(covered_samples(below, Viewport{10, 10}, 1), expected);
    EXPECT_EQ(covered_samples(reversed(below), Viewport{10, 10}, 1), expected);
}

TEST(Coverage, ZeroAreaTrianglesCoverNothing) {
    const Triangle collinear_through_centres = flat(0.5, 0.5, 2.5, 2.5, 4.5, 4.5);
    const Triangle repeated_vertex = flat(1, 1, 1, 1, 5, 3);
    const Triangle point = flat(2.5, 2.5, 2.5, 2.5, 2.5, 2.5);
    for (const Triangle& t : {collinear_through_centres, repeated_vertex, point}) {
        EXPECT_FALSE(covers(t, 2.5, 2.5));
        EXPECT_TRUE(covered_samples(t, Viewport{6, 6}, 16).empty());
    }
    Stats stats;
    const Framebuffer fb = render(scene(6, 6, {collinear_through_centres, repeated_vertex, point}), &stats);
    EXPECT_EQ(stats.triangles, 3u);
    EXPECT_EQ(stats.degenerate_triangles, 3u);
    EXPECT_EQ(stats.samples_covered, 0u);
    for (auto id : fb.ids) EXPECT_EQ(id, Framebuffer::kNoTriangle);
}

// Vertices at +-2^60 and +-DBL_MAX. The vertical edge x = 0.5 runs through the centres of column 0:
// as a left edge (pointing down) it covers them, as a right edge it does not.
TEST(Coverage, HugeCoordinates) {
    const char* all = R"(
0000
0000
0000
0000
)";
    const char* none = R"(
....
....
....
....
)";
    for (const double big : {std::ldexp(1.0, 60), DBL_MAX}) {
        EXPECT_EQ(picture(render(scene(4, 4, {flat(-big, -big, big, -big, 0, big)}))), all);
        const Triangle left_edge_through_centres = flat(0.5, big, 0.5, -big, big, 0);
        const Triangle right_edge_through_centres = flat(0.5, -big, 0.5, big, -big, 0);
        EXPECT_EQ(picture(render(scene(4, 4, {left_edge_through_centres}))), all);
        EXPECT_EQ(picture(render(scene(4, 4, {reversed(left_edge_through_centres)}))), all);
        EXPECT_EQ(picture(render(scene(4, 4, {right_edge_through_centres}))), none);
        EXPECT_EQ(picture(render(scene(4, 4, {reversed(right_edge_through_centres)}))), none);
    }
    // Entirely outside, far away in every direction: an empty bounding box after clamping.
    const double far = std::ldexp(1.0, 60);
    EXPECT_TRUE(covered_samples(flat(-far, -far, -far / 2, -far, -far, -far / 2), Viewport{4, 4}, 4).empty());
    EXPECT_TRUE(covered_samples(flat(far, far, far / 2, far, far, far / 2), Viewport{4, 4}, 4).empty());
}

// With subnormal coordinates every product in the orientation underflows in double; the exact fallback
// still sees the true sign. d is the smallest subnormal.
TEST(Coverage, SubnormalCoordinates) {
    const double d = std::numeric_limits<double>::denorm_min();
    // Legs on the axes, hypotenuse x + y = 2d (a right edge), then x + y = 4d.
    const Triangle small = flat(0, 0, 2 * d, 0, 0, 2 * d);
    EXPECT_TRUE(covers(small, 0, d));    // on the left edge x = 0
    EXPECT_FALSE(covers(small, d, 0));   // on the bottom edge
    EXPECT_FALSE(covers(small, d, d));   // on the hypotenuse
    EXPECT_FALSE(covers(small, 0, 0));   // the vertex joining the left and bottom edges
    const Triangle larger = flat(0, 0, 4 * d, 0, 0, 4 * d);
    EXPECT_TRUE(covers(larger, d, d));
    EXPECT_TRUE(covers(reversed(larger), d, d));

    // A left edge at x = +-d or 0 beside the sample (0, 1/2) of the 16-sample pattern (offset x = 0).
    const auto left_edge_at = [](double x) { return flat(x, 10, x, -10, 10, 0); };
    EXPECT_FALSE(covers(left_edge_at(d), 0, 0.5));
    EXPECT_TRUE(covers(left_edge_at(0), 0, 0.5));
    EXPECT_TRUE(covers(left_edge_at(-d), 0, 0.5));
    // Sample 12 of pixel (0, 0) in a 1x1 viewport is (0, 1/2): framebuffer index 12.
    const auto indices = covered_samples(left_edge_at(d), Viewport{1, 1}, 16);
    EXPECT_EQ(std::count(indices.begin(), indices.end(), 12u), 0);
    EXPECT_EQ(indices.size(), 15u);
}

TEST(Coverage, BadInputIsRejected) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(covers(flat(0, 0, 1, 0, nan, 1), 0.5, 0.5), std::invalid_argument);
    EXPECT_THROW(covers(flat(0, 0, 1, 0, 0, 1), inf, 0.5), std::invalid_argument);
    EXPECT_THROW(covered_samples(flat(0, 0, 1, 0, 0, 1), Viewport{0, 4}, 1), std::invalid_argument);
    EXPECT_THROW(covered_samples(flat(0, 0, 1, 0, 0, 1), Viewport{4, 4}, 3), std::invalid_argument);
    // The engines' limits (rast/scene_limits.h), refused before anything is sized for them: a side past
    // 2^24, and 2^24 x 2^24 pixels, 2^48 samples, far past 2^32.
    EXPECT_THROW(covered_samples(flat(0, 0, 1, 0, 0, 1), Viewport{(1 << 24) + 1, 1}, 1), std::invalid_argument);
    try {
        render(scene(1 << 24, 1 << 24, {flat(0, 0, 1, 0, 0, 1)}));
        FAIL() << "a framebuffer of 2^48 samples was attempted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("rast::reference: viewport 16777216x16777216"), std::string::npos)
            << e.what();
    }
    try {
        render(scene(4, 4, {flat(0, 0, 1, 0, 0, 1), flat(0, 0, inf, 0, 0, 1)}));
        FAIL() << "a non-finite vertex was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("triangle 1 vertex 1"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rast::reference
