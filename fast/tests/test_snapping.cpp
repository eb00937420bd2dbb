// Fixed-point snapping: round to nearest, ties to even, at 4, 8 and 16 subpixel bits.
#include "pixels.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rast::fast {
namespace {

using testing::covered_pixels;
using testing::rendered_pixels;
using testing::tri;

double snap_x(double x, Precision p) { return snap(tri(x, 0, 0, 0, 0, 0), p).v[0].x; }

TEST(Snapping, HalfwayCasesRoundToEven) {
    // At N bits the grid step is g = 2^-N; k + 1/2 steps rounds to the even neighbour.
    for (const auto& [p, bits] : {std::pair{Precision::fixed4, 4}, {Precision::fixed8, 8}, {Precision::fixed16, 16}}) {
        const double g = std::ldexp(1.0, -bits);
        EXPECT_EQ(snap_x(0.5 * g, p), 0.0) << bits;
        EXPECT_EQ(snap_x(1.5 * g, p), 2 * g) << bits;
        EXPECT_EQ(snap_x(2.5 * g, p), 2 * g) << bits;
        EXPECT_EQ(snap_x(3.5 * g, p), 4 * g) << bits;
        EXPECT_EQ(snap_x(-1.5 * g, p), -2 * g) << bits;
        EXPECT_EQ(snap_x(-2.5 * g, p), -2 * g) << bits;
        EXPECT_EQ(snap_x(7 + 0.5 * g, p), 7.0) << bits;
        EXPECT_EQ(snap_x(7 + 1.5 * g, p), 7 + 2 * g) << bits;
        // Not halfway: to the nearest.
        EXPECT_EQ(snap_x(0.49 * g, p), 0.0) << bits;
        EXPECT_EQ(snap_x(0.51 * g, p), g) << bits;
    }
    EXPECT_EQ(snap_x(0.3, Precision::fixed4), 0.3125);  // 4.8 sixteenths -> 5
}

TEST(Snapping, LargeCoordinates) {
    // 2^30 + 2^-17 is 2^46 + 1/2 steps of 2^-16: a tie, to the even 2^46 steps.
    EXPECT_EQ(snap_x(0x1p30 + 0x1p-17, Precision::fixed16), 0x1p30);
    EXPECT_EQ(snap_x(0x1p30 + 3 * 0x1p-17, Precision::fixed16), 0x1p30 + 0x1p-15);
    // Beyond 2^(52-N) every double is on the grid already.
    EXPECT_EQ(snap_x(0x1p60, Precision::fixed8), 0x1p60);
    EXPECT_EQ(snap_x(-DBL_MAX, Precision::fixed16), -DBL_MAX);
    EXPECT_EQ(snap_x(0x1p40 + 0x1p-12, Precision::fixed16), 0x1p40 + 0x1p-12);
    // The float modes do not snap.
    EXPECT_EQ(snap_x(0.3, Precision::float32), 0.3);
}

// A left edge x = c (it runs down the counter-clockwise boundary, so it owns the centres on it): column
// 0 (centres x = 0.5) is covered iff c snaps to <= 0.5, and the rest of the 4 x 4 viewport lies inside.
// 0.5 is an even number of grid steps, so a tie next to it rounds onto it: c = 0.5 +- g/2 covers
// column 0 (rounding half up would not), 0.5 + 3g/4 does not (truncating would), nor does 0.5 + 3g/2
// (to the even 0.5 + 2g). The scene path (render) and the single-triangle path (covered_samples) snap
// separately; both must round so.
TEST(Snapping, HalfwayVerticesSnapToEvenInEveryPath) {
    const Viewport vp{4, 4};
    testing::Pixels all, right;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) (i == 0 ? all : right).insert({i, j});
    all.insert(right.begin(), right.end());
    for (const auto& [p, bits] : {std::pair{Precision::fixed4, 4}, {Precision::fixed8, 8}, {Precision::fixed16, 16}}) {
        const double g = std::ldexp(1.0, -bits);
        for (const auto& [c, covers_column_0] : {std::pair{0.5 - 0.5 * g, true}, {0.5 + 0.5 * g, true},
                                                 {0.5 + 0.75 * g, false}, {0.5 + 1.5 * g, false}}) {
            const Triangle t = tri(c, 9, c, -1, 9, -1);
            const testing::Pixels expected = covers_column_0 ? all : right;
            EXPECT_EQ(rendered_pixels(t, vp, p), expected) << bits << " bits, c = " << c;
            EXPECT_EQ(covered_pixels(t, vp, p), expected) << bits << " bits, c = " << c;
        }
    }
}

// The left edge at x = 0.5 + 1/64 snaps onto the centres x = 0.5 at 4 bits (1/64 is a quarter step):
// the edge-types case, with (0.5,1.5), (0.5,2.5) owned. At 8 and 16 bits it stays right of them, and
// the hypotenuse from (3.5, 0.5) to (0.515625, 3.5) passes x = 1.5104 at y = 2.5 and x = 2.5052 at
// y = 1.5: those centres are strictly inside.
TEST(Snapping, ChangesCoverageExactlyAsTheSnappedTriangle) {
    const double x = 0.5 + 1.0 / 64;
    const Triangle t = tri(x, 0.5, 3.5, 0.5, x, 3.5);
    const testing::Pixels fixed4 = {{1, 1}, {0, 1}, {0, 2}}, finer = {{1, 1}, {1, 2}, {2, 1}};
    EXPECT_EQ(covered_pixels(t, {4, 4}, Precision::fixed4), fixed4);
    EXPECT_EQ(covered_pixels(t, {4, 4}, Precision::fixed8), finer);
    EXPECT_EQ(covered_pixels(t, {4, 4}, Precision::fixed16), finer);
    EXPECT_EQ(covered_pixels(t, {4, 4}, Precision::float64), finer);
}

// A thin sliver that snaps to zero area at 4 bits covers nothing there.
TEST(Snapping, SliverCollapsesToZeroArea) {
    const Triangle t = tri(0, 0.5, 4, 0.5 + 1.0 / 128, 0, 0.5 + 1.0 / 64);
    EXPECT_TRUE(covered_pixels(t, {4, 1}, Precision::fixed4).empty());
    // At 8 bits it keeps its area but lies above the centres: its lower edge passes x = 0.5 at
    // y = 0.5 + 1/1024.
    EXPECT_TRUE(covered_pixels(t, {4, 1}, Precision::fixed8).empty());
}

}  // namespace
}  // namespace rast::fast
