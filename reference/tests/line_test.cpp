// The diamond-exit rule on segments worked out by hand: each octant, the rule's boundary parts, and the
// ends of a segment; then lit_pixels against the rule pixel by pixel.
#include <rast/line.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <set>
#include <utility>
#include <vector>

namespace rast::reference {
namespace {

Segment segment(double x0, double y0, double x1, double y1) { return {{Vertex{x0, y0, 0}, Vertex{x1, y1, 0}}}; }

using Pixels = std::set<std::pair<int, int>>;

// Every pixel of a 10 x 10 viewport that `s` lights, by the rule alone.
Pixels lit(const Segment& s) {
    Pixels out;
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i)
            if (lights(s, i, j)) out.insert({i, j});
    return out;
}

// From the centre of pixel a to the centre of pixel b along a row: a .. b - 1; reversed, b .. a + 1. The
// same along a column.
TEST(Line, CentreToCentreLightsAllButTheEnd) {
    EXPECT_EQ(lit(segment(0.5, 0.5, 4.5, 0.5)), (Pixels{{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
    EXPECT_EQ(lit(segment(4.5, 0.5, 0.5, 0.5)), (Pixels{{4, 0}, {3, 0}, {2, 0}, {1, 0}}));
    EXPECT_EQ(lit(segment(0.5, 0.5, 0.5, 3.5)), (Pixels{{0, 0}, {0, 1}, {0, 2}}));
    EXPECT_EQ(lit(segment(0.5, 3.5, 0.5, 0.5)), (Pixels{{0, 3}, {0, 2}, {0, 1}}));
}

// From the centre of pixel (4, 4) by (3, 1) and its seven reflections, to another centre. Along (3, 1),
// y = 4.5 + (x - 4.5) / 3 passes 1/3 from the centres of (5, 4) and (6, 5) (inside their diamonds) and
// at least 2/3 from every other; the start's pixel is lit, the end's is not.
TEST(Line, EveryOctant) {
    const std::vector<std::pair<std::pair<int, int>, Pixels>> cases{
        {{3, 1}, {{4, 4}, {5, 4}, {6, 5}}},    {{1, 3}, {{4, 4}, {4, 5}, {5, 6}}},
        {{-1, 3}, {{4, 4}, {4, 5}, {3, 6}}},   {{-3, 1}, {{4, 4}, {3, 4}, {2, 5}}},
        {{-3, -1}, {{4, 4}, {3, 4}, {2, 3}}},  {{-1, -3}, {{4, 4}, {4, 3}, {3, 2}}},
        {{1, -3}, {{4, 4}, {4, 3}, {5, 2}}},   {{3, -1}, {{4, 4}, {5, 4}, {6, 3}}}};
    for (const auto& [d, expected] : cases)
        EXPECT_EQ(lit(segment(4.5, 4.5, 4.5 + d.first, 4.5 + d.second)), expected) << d.first << ", " << d.second;
}

// Along y = 1 (x-major) the segment runs through the bottom corners of row 1, which the diamonds hold,
// and the top corners of row 0, which they do not. Along x = 2 (y-major) it runs through the right
// corners of column 1, held for y-major segments, and the left corners of column 2, never held.
TEST(Line, ThroughCornersBetweenPixels) {
    EXPECT_EQ(lit(segment(0.25, 1, 3.75, 1)), (Pixels{{0, 1}, {1, 1}, {2, 1}, {3, 1}}));
    EXPECT_EQ(lit(segment(2, 0.25, 2, 3.75)), (Pixels{{1, 0}, {1, 1}, {1, 2}, {1, 3}}));
}

// y = x + 1/2 at 45 degrees (x-major): it runs along the upper-left edges of the diamonds of (i, i), not
// held, and the lower-right edges of (i, i + 1), held but for their right corners.
TEST(Line, AlongDiamondEdges) {
    EXPECT_EQ(lit(segment(0, 0.5, 3, 3.5)), (Pixels{{0, 1}, {1, 2}, {2, 3}}));
}

// Starting on a bottom corner is starting inside: the pixel is lit. Ending there lights it not.
TEST(Line, EndsOnTheBottomCorner) {
    EXPECT_TRUE(lights(segment(1.5, 1, 4.5, 1.75), 1, 1));
    EXPECT_FALSE(lights(segment(4.5, 1.75, 1.5, 1), 1, 1));
}

// Ending on the right corner (2, 3/2) of pixel (1, 1): an x-major segment does not end in the diamond, so
// it lights the pixel it crossed; a y-major one ends in it, so it does not.
TEST(Line, EndsOnTheRightCornerByMajorAxis) {
    EXPECT_TRUE(lights(segment(0.5, 1, 2, 1.5), 1, 1));   // dx 3/2, dy 1/2: crosses 1/6 below the centre
    EXPECT_FALSE(lights(segment(1.5, 0, 2, 1.5), 1, 1));  // dx 1/2, dy 3/2
    EXPECT_EQ(lit(segment(0, 1.5, 2, 1.5)), (Pixels{{0, 1}, {1, 1}}));  // ends on the left corner of (2, 1)
}

// Collinear with a lower edge of pixel (1, 1) but meeting it only at a corner the diamond does not hold:
// along slope -1 into its left corner (1, 3/2), along slope +1 out of its right corner (2, 3/2) (x-major).
// Run along the whole edge instead, and they light it; stop on the edge, and they end inside it.
TEST(Line, TouchingOnlyAnUnheldCornerAlongAnEdge) {
    EXPECT_FALSE(lights(segment(0, 2.5, 1, 1.5), 1, 1));
    EXPECT_FALSE(lights(segment(2, 1.5, 3, 2.5), 1, 1));
    EXPECT_TRUE(lights(segment(0, 2.5, 2, 0.5), 1, 1));
    EXPECT_TRUE(lights(segment(1, 0.5, 3, 2.5), 1, 1));
    EXPECT_FALSE(lights(segment(0, 2.5, 1.25, 1.25), 1, 1));
}

TEST(Line, ANonFiniteEndIsRefused) {
    EXPECT_THROW(lights(segment(0, 0, INFINITY, 1), 0, 0), std::invalid_argument);
    EXPECT_THROW(lit_pixels(segment(NAN, 0, 1, 1), Viewport{10, 10}), std::invalid_argument);
}

TEST(Line, ZeroLengthLightsNothing) {
    EXPECT_TRUE(lit(segment(2.5, 2.5, 2.5, 2.5)).empty());
    EXPECT_TRUE(lit_pixels(segment(2.5, 2.5, 2.5, 2.5), Viewport{10, 10}).empty());
}

// lit_pixels walks the major axis; it must find exactly the pixels the rule lights, for segments on the
// half-pixel grid (every tie), arbitrary ones and ones reaching far outside.
TEST(Line, LitPixelsFindsEveryPixelTheRuleLights) {
    std::mt19937 rng(32);
    std::uniform_int_distribution<int> half(-4, 24);
    std::uniform_real_distribution<double> any(-3, 13), far(-1e9, 1e9);
    for (int round = 0; round < 600; ++round) {
        const int kind = round % 3;
        const auto value = [&] { return kind == 0 ? half(rng) / 2.0 : kind == 1 ? any(rng) : far(rng); };
        const Segment s = kind == 2 ? segment(any(rng), any(rng), value(), value()) : segment(value(), value(), value(), value());
        std::vector<std::size_t> expected;
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 10; ++i)
                if (lights(s, i, j)) expected.push_back(static_cast<std::size_t>(j * 10 + i));
        ASSERT_EQ(lit_pixels(s, Viewport{10, 10}), expected) << "round " << round;
    }
}

}  // namespace
}  // namespace rast::reference
