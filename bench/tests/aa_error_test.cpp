// Sample patterns against the exact area, on shapes whose answer is worked out by hand.
#include <rast/aa_error.h>

#include <gtest/gtest.h>

#include <rast/visible_area.h>

#include <array>
#include <stdexcept>

namespace rast::bench {
namespace {

Triangle tri(double x0, double y0, double x1, double y1, double x2, double y2) {
    return Triangle{{Vertex{x0, y0, 0}, Vertex{x1, y1, 0}, Vertex{x2, y2, 0}}};
}

constexpr std::array kCounts{1, 4, 8, 16};

// The lower-left half of pixel (0, 0), below the diagonal x + y = 1 (area 1/2). Wound counter-clockwise,
// the diagonal is a right edge, so samples on it are not covered; x = 0 is a left edge, so they are.
// Counted by hand from the y-up patterns of scene.h:
//   1x: the centre lies on the diagonal: 0 of 1.
//   4x: (1/8, 3/8) and (5/8, 1/8) are below it: 2 of 4.
//   8x: (7/16, 5/16), (3/16, 3/16), (1/16, 9/16), (11/16, 1/16): 4 of 8.
//   16x: (5/16, 3/8), (3/16, 5/8), (5/8, 3/16), (3/8, 1/8), (1/8, 1/4), (0, 1/2) on the left edge, and
//        (7/8, 1/16); (9/16, 7/16) is on the diagonal: 7 of 16.
TEST(PatternError, HalfAPixelCountsPerPattern) {
    const Triangle half = tri(0, 0, 1, 0, 0, 1);
    EXPECT_EQ(pixel_coverage_error(half, 0, 0, 1), -0.5);
    EXPECT_EQ(pixel_coverage_error(half, 0, 0, 4), 0);
    EXPECT_EQ(pixel_coverage_error(half, 0, 0, 8), 0);
    EXPECT_EQ(pixel_coverage_error(half, 0, 0, 16), -1.0 / 16);
}

TEST(PatternError, MeanAndWorstOverTheTouchedPixels) {
    // Below x + y = 2 in a 2 x 2 viewport: pixel (0, 0) is inside (area 1), pixels (1, 0) and (0, 1) are
    // half inside with their centres on the diagonal (not covered), and pixel (1, 1) meets it only at its
    // corner (area 0, no sample covered: it does not count). One sample: errors 0, 1/2, 1/2.
    const Scene scene{{2, 2}, 1, {tri(0, 0, 2, 0, 0, 2)}};
    const auto errors = pattern_errors(scene, kCounts);
    ASSERT_EQ(errors.size(), 4u);
    EXPECT_EQ(errors[0].samples, 1);
    EXPECT_EQ(errors[0].pixels, 3u);
    EXPECT_DOUBLE_EQ(errors[0].mean, 1.0 / 3);
    EXPECT_EQ(errors[0].worst, 0.5);
    // 16x: all 16 samples of pixel (0, 0); in each half pixel the 7 of HalfAPixelCountsPerPattern (the
    // sample at x = 0 of pixel (1, 0) is now strictly inside rather than on a left edge, still covered).
    EXPECT_EQ(errors[3].pixels, 3u);
    EXPECT_DOUBLE_EQ(errors[3].mean, (0 + 1.0 / 16 + 1.0 / 16) / 3);
    EXPECT_EQ(errors[3].worst, 1.0 / 16);
}

TEST(PatternError, BorderSamplesOfTheSixteenPatternAreOwnedOnce) {
    // The square [1, 2]^2 as two triangles in a 3 x 3 viewport. The 16x pattern has a sample on the left
    // border of each pixel (x = 0) and one on the top border (y = 1). The square owns its own pixel's
    // left-border sample (left edge) and top-border sample (top edge) but not the left-border sample of
    // pixel (2, 1), on its right edge, nor the top-border sample of pixel (1, 0), on its bottom edge: so
    // its coverage is exactly its area in every pixel, whatever the diagonal does.
    const Triangle lower = tri(1, 1, 2, 1, 2, 2), upper = tri(1, 1, 2, 2, 1, 2);
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(pixel_coverage_error(lower, i, j, 16) + pixel_coverage_error(upper, i, j, 16), 0)
                << "pixel " << i << ", " << j;
        }
    }
}

TEST(PatternError, RejectsAnUnsupportedSampleCount) {
    const Scene scene{{1, 1}, 1, {tri(0, 0, 1, 0, 0, 1)}};
    const std::array counts{2};
    EXPECT_THROW(pattern_errors(scene, counts), std::invalid_argument);
}

TEST(HalfplaneDiscrepancy, AreaBelowALine) {
    EXPECT_DOUBLE_EQ(square_area_below(1, 0, 0.25), 0.25);
    EXPECT_DOUBLE_EQ(square_area_below(1, 1, 1), 0.5);
    EXPECT_DOUBLE_EQ(square_area_below(0, -1, -0.75), 0.25);  // y >= 3/4
    EXPECT_DOUBLE_EQ(square_area_below(1, 0, -1), 0);
    EXPECT_DOUBLE_EQ(square_area_below(1, 0, 2), 1);
    // y <= 2x + 1/8: the square minus the triangle (0, 1/8), (0, 1), (7/16, 1) of area 49/256.
    EXPECT_DOUBLE_EQ(square_area_below(-0.5, 0.25, 1.0 / 32), 1 - 49.0 / 256);
}

// One sample at the centre: any line through it halves the square while the sample counts 0 or 1; a
// line missing it leaves at most half the square on the side without it. Exactly 1/2.
TEST(HalfplaneDiscrepancy, OneSampleIsExactlyOneHalf) {
    EXPECT_EQ(halfplane_discrepancy(sample_pattern(1)).value, 0.5);
}

// The 4x rotated grid: (1/8, 3/8) and (3/8, 7/8) lie on the line y = 2x + 1/8, which cuts off the
// triangle (0, 1/8), (0, 1), (7/16, 1) of area 49/256. With the two samples on the line excluded, the
// half-plane y < 2x + 1/8 has area 207/256 and 2 of 4 samples: error 79/256. By the pattern's
// quarter-turn symmetry the three other lines through two samples give the same.
// No other half-plane does worse.
TEST(HalfplaneDiscrepancy, FourSamplesIsTheTwoSampleLine) {
    EXPECT_EQ(halfplane_discrepancy(sample_pattern(4)).value, 79.0 / 256);
}

// The 16x pattern has four collinear samples on 4x + y = 57/16: (3/4, 9/16), (13/16, 5/16),
// (11/16, 13/16) and (7/8, 1/16); 11 lie below the line and 1 above. The line meets y = 0 at x = 57/64
// and y = 1 at x = 41/64, so the closed side has area 49/64 and, the four included, 15 of 16 samples:
// error 11/64, the worst over all half-planes.
TEST(HalfplaneDiscrepancy, SixteenSamplesIsTheFourSampleLine) {
    EXPECT_EQ(halfplane_discrepancy(sample_pattern(16)).value, 11.0 / 64);
}

// The lower-left half of a pixel in front of a large triangle: each sees 1/2. The one sample, at the
// centre, lies on the half's right edge, so the one behind owns it: fractions 0 and 1 against 1/2 and
// 1/2, error 1/2. Of the 4x samples, (1/8, 3/8) and (5/8, 1/8) lie below x + y = 1: 2 of 4, error 0.
TEST(VisibleErrors, HalfAPixelInFrontOfALargeTriangle) {
    const Scene s{Viewport{2, 1}, 1,
                  {Triangle{{Vertex{0, 0, 0}, Vertex{1, 0, 0}, Vertex{0, 1, 0}}},
                   Triangle{{Vertex{-1, -1, 1}, Vertex{5, -1, 1}, Vertex{-1, 5, 1}}}}};
    const std::array counts{1, 4};
    const auto errors = visible_errors(s, reference::visible_area(s), counts);
    ASSERT_EQ(errors.size(), 2u);
    // Pixel (1, 0) lies inside the triangle behind (x + y <= 4 holds at its corner (2, 1)): no error.
    EXPECT_EQ(errors[0].samples, 1);
    EXPECT_EQ(errors[0].pixels, 2u);
    EXPECT_EQ(errors[0].worst, 0.5);
    EXPECT_EQ(errors[0].mean, 0.25);
    EXPECT_EQ(errors[1].worst, 0);
}

TEST(HalfplaneDiscrepancy, ResolutionIsHalfTheSpacing) {
    EXPECT_DOUBLE_EQ(halfplane_discrepancy(sample_pattern(4), 1024).resolution, 3.141592653589793 / 2048);
}

}  // namespace
}  // namespace rast::bench
