// Bresenham and the DDA on the reference's hand cases (reference/tests/line_test.cpp), worked out again
// here: the fast path is tested without the reference. The property tests hold them to each other.
#include <rast/fast.h>

#include <gtest/gtest.h>

#include <cfloat>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rast::fast {
namespace {

Segment segment(double x0, double y0, double x1, double y1) { return {{Vertex{x0, y0, 0}, Vertex{x1, y1, 0}}}; }

// Pixels as (i, j), ascending by j then i as the indices are.
std::vector<std::pair<int, int>> lit(const Segment& s, int bits = 8) {
    std::vector<std::pair<int, int>> out;
    for (const std::size_t p : bresenham(s, Viewport{10, 10}, bits)) out.push_back({int(p % 10), int(p / 10)});
    return out;
}

using Pixels = std::vector<std::pair<int, int>>;

TEST(Bresenham, CentreToCentreLightsAllButTheEnd) {
    EXPECT_EQ(lit(segment(0.5, 0.5, 4.5, 0.5)), (Pixels{{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
    EXPECT_EQ(lit(segment(4.5, 0.5, 0.5, 0.5)), (Pixels{{1, 0}, {2, 0}, {3, 0}, {4, 0}}));
    EXPECT_EQ(lit(segment(0.5, 0.5, 0.5, 3.5)), (Pixels{{0, 0}, {0, 1}, {0, 2}}));
    EXPECT_EQ(lit(segment(0.5, 3.5, 0.5, 0.5)), (Pixels{{0, 1}, {0, 2}, {0, 3}}));
}

// From the centre of (4, 4) by (3, 1) and its reflections: 1/3 from the centres passed.
TEST(Bresenham, EveryOctant) {
    EXPECT_EQ(lit(segment(4.5, 4.5, 7.5, 5.5)), (Pixels{{4, 4}, {5, 4}, {6, 5}}));
    EXPECT_EQ(lit(segment(4.5, 4.5, 5.5, 7.5)), (Pixels{{4, 4}, {4, 5}, {5, 6}}));
    EXPECT_EQ(lit(segment(4.5, 4.5, 3.5, 7.5)), (Pixels{{4, 4}, {4, 5}, {3, 6}}));
    EXPECT_EQ(lit(segment(4.5, 4.5, 1.5, 5.5)), (Pixels{{3, 4}, {4, 4}, {2, 5}}));
    EXPECT_EQ(lit(segment(4.5, 4.5, 1.5, 3.5)), (Pixels{{2, 3}, {3, 4}, {4, 4}}));
    EXPECT_EQ(lit(segment(4.5, 4.5, 3.5, 1.5)), (Pixels{{3, 2}, {4, 3}, {4, 4}}));
    EXPECT_EQ(lit(segment(4.5, 4.5, 5.5, 1.5)), (Pixels{{5, 2}, {4, 3}, {4, 4}}));
    EXPECT_EQ(lit(segment(4.5, 4.5, 7.5, 3.5)), (Pixels{{6, 3}, {4, 4}, {5, 4}}));
}

// Through the bottom corners of row 1 (held) and the right corners of column 1 (held, y-major).
TEST(Bresenham, ThroughCornersBetweenPixels) {
    EXPECT_EQ(lit(segment(0.25, 1, 3.75, 1)), (Pixels{{0, 1}, {1, 1}, {2, 1}, {3, 1}}));
    EXPECT_EQ(lit(segment(2, 0.25, 2, 3.75)), (Pixels{{1, 0}, {1, 1}, {1, 2}, {1, 3}}));
    EXPECT_EQ(lit(segment(0, 0.5, 3, 3.5)), (Pixels{{0, 1}, {1, 2}, {2, 3}}));  // along diamond edges
}

// The ends: on the bottom corner, on the right corner by major axis, into an unheld corner along an edge.
TEST(Bresenham, Ends) {
    EXPECT_EQ(lit(segment(1.5, 1, 4.5, 1.75)), (Pixels{{1, 1}, {2, 1}, {3, 1}}));
    EXPECT_EQ(lit(segment(4.5, 1.75, 1.5, 1)), (Pixels{{2, 1}, {3, 1}, {4, 1}}));
    EXPECT_EQ(lit(segment(0.5, 1, 2, 1.5)), (Pixels{{0, 1}, {1, 1}}));  // x-major: the right corner is not held
    EXPECT_EQ(lit(segment(1.5, 0, 2, 1.5)), (Pixels{{1, 0}}));          // y-major: it is
    // Into (1, 1)'s left corner, not held; on the way it runs along (0, 2)'s lower-left edge, held.
    EXPECT_EQ(lit(segment(0, 2.5, 1, 1.5)), (Pixels{{0, 2}}));
    EXPECT_TRUE(lit(segment(2.5, 2.5, 2.5, 2.5)).empty());
}

// Ends are snapped first: 0.5 + 2^-10 is 0.5 on the 1/256 grid, 0.5 + 2^-9 rounds (a tie) to even, 0.5.
TEST(Bresenham, SnapsTheEndsFirst) {
    EXPECT_EQ(lit(segment(0.5 + 0x1p-10, 0.5, 4.5, 0.5)), lit(segment(0.5, 0.5, 4.5, 0.5)));
    EXPECT_EQ(lit(segment(4.5, 0.5 + 0x1p-9, 0.5, 0.5)), lit(segment(4.5, 0.5, 0.5, 0.5)));
}

// Ends beyond 2^(51 - bits) pixels take big integers. On the viewport they light what a segment along the
// same line with nearer ends, both outside the viewport, lights: y = x lights the diagonal pixels; y = x / 4
// is in row floor((i + 1/2) / 4) at column i's centre.
TEST(Bresenham, FarEndsTakeBigIntegers) {
    EXPECT_EQ(lit(segment(-0x1p60, -0x1p60, 0x1p60, 0x1p60)),
              (Pixels{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}, {6, 6}, {7, 7}, {8, 8}, {9, 9}}));
    EXPECT_EQ(lit(segment(-DBL_MAX, 4.5, DBL_MAX, 4.5)), lit(segment(-1, 4.5, 11, 4.5)));
    EXPECT_EQ(lit(segment(0, 0, 0x1p60, 0x1p58)), (Pixels{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 1}, {5, 1}, {6, 1},
                                                         {7, 1}, {8, 2}, {9, 2}}));
    EXPECT_EQ(lit(segment(0x1p60, 0x1p58, 0, 0)), lit(segment(16, 4, 0, 0)));
    EXPECT_EQ(lit(segment(2.5, 0x1p70, 2.5, -0x1p70)), (Pixels{{2, 0}, {2, 1}, {2, 2}, {2, 3}, {2, 4}, {2, 5},
                                                                {2, 6}, {2, 7}, {2, 8}, {2, 9}}));
}

TEST(Bresenham, RefusesWhatItCannotDo) {
    EXPECT_THROW(bresenham(segment(0, 0, 1, 1), Viewport{10, 10}, 0), std::invalid_argument);
    EXPECT_THROW(bresenham(segment(0, 0, 1, 1), Viewport{10, 10}, 17), std::invalid_argument);
    EXPECT_THROW(bresenham(segment(0, 0, 1, 1), Viewport{0, 10}), std::invalid_argument);
    EXPECT_THROW(bresenham(segment(0, 0, std::nan(""), 1), Viewport{10, 10}), std::invalid_argument);
}

// The hand cases whose slopes and positions every float type holds exactly (0, 1/2, 1, 3/2 and 3 steps):
// the DDA's additions are exact there, and it lights what Bresenham lights.
TEST(Dda, ExactWhereItsArithmeticIs) {
    const std::vector<Segment> exact{segment(0.5, 0.5, 4.5, 0.5), segment(4.5, 0.5, 0.5, 0.5),
                                     segment(0.5, 0.5, 0.5, 3.5), segment(0.25, 1, 3.75, 1),
                                     segment(2, 0.25, 2, 3.75),   segment(0, 0.5, 3, 3.5),
                                     segment(1.5, 1, 4.5, 2.5),   segment(0.5, 1, 2, 1.5),
                                     segment(1.5, 0, 2, 1.5),     segment(0, 2.5, 1, 1.5)};
    for (const Segment& s : exact)
        for (const Precision p : {Precision::float32, Precision::float64})
            EXPECT_EQ(dda(s, Viewport{10, 10}, p), bresenham(s, Viewport{10, 10}))
                << s.v[0].x << "," << s.v[0].y << " to " << s.v[1].x << "," << s.v[1].y << " in " << name(p);
}

// Accumulated rounding. From the centre of (0, 0) to the centre of (10, 1) the slope is 1/10, which no
// binary fraction is. The exact line meets y = 1 at x = 5.5, the bottom corner of pixel (5, 1), held:
// the reference lights (5, 1). Adding the rounded slope five times to 1/2 gives 1 + 2^-23 in float
// (floor 1, the same pixel) but 1 - 2^-53 in double (floor 0): float64 lights (5, 0) instead.
TEST(Dda, RoundingMovesAPixel) {
    const Segment s = segment(0.5, 0.5, 10.5, 1.5);
    const Viewport vp{12, 4};
    const auto exact = bresenham(s, vp);
    EXPECT_NE(std::find(exact.begin(), exact.end(), std::size_t{1 * 12 + 5}), exact.end());
    EXPECT_EQ(dda(s, vp, Precision::float32), exact);
    auto moved = exact;
    std::replace(moved.begin(), moved.end(), std::size_t{1 * 12 + 5}, std::size_t{0 * 12 + 5});
    std::sort(moved.begin(), moved.end());
    EXPECT_EQ(dda(s, vp, Precision::float64), moved);
}

TEST(Dda, RefusesWhatItCannotDo) {
    EXPECT_THROW(dda(segment(0, 0, 1, 1), Viewport{10, 10}, Precision::fixed8), std::invalid_argument);
    EXPECT_THROW(dda(segment(0, 0, std::nan(""), 1), Viewport{10, 10}), std::invalid_argument);
    EXPECT_THROW(dda(segment(0, 0, 1, 1), Viewport{10, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace rast::fast
