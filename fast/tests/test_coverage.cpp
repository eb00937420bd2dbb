// The reference's hand cases, in every precision mode: their coordinates are multiples of 1/16, exact
// on every fixed grid and in float, so every mode must give exactly the hand-computed coverage.
#include "pixels.h"

#include <gtest/gtest.h>

#include <map>

namespace rast::fast {
namespace {

using testing::covered_pixels;
using testing::Pixels;
using testing::tri;

class Coverage : public ::testing::TestWithParam<Precision> {};

// Counter-clockwise (0.5,0.5) -> (3.5,0.5) -> (0.5,3.5): a bottom edge, a right edge (the hypotenuse)
// and a left edge, each through pixel centres. Inside strictly: (1.5,1.5). On the left edge x = 0.5:
// (0.5,1.5), (0.5,2.5) are owned; the vertices touch a non-owning edge; the hypotenuse x + y = 4 and
// the bottom edge y = 0.5 own nothing.
TEST_P(Coverage, BottomRightLeftEdges) {
    const Pixels expected = {{1, 1}, {0, 1}, {0, 2}};
    EXPECT_EQ(covered_pixels(tri(0.5, 0.5, 3.5, 0.5, 0.5, 3.5), {4, 4}, GetParam()), expected);
    // Winding does not matter.
    EXPECT_EQ(covered_pixels(tri(0.5, 0.5, 0.5, 3.5, 3.5, 0.5), {4, 4}, GetParam()), expected);
}

// Counter-clockwise (3.5,3.5) -> (0.5,3.5) -> (3.5,0.5): a top edge, a left edge (x + y = 4) and a right
// edge x = 3.5. Owned: the top edge's centres with x < 3.5, the hypotenuse's, the vertex (0.5,3.5) where
// top meets left; inside strictly: (2.5,2.5).
TEST_P(Coverage, TopLeftRightEdges) {
    const Pixels expected = {{0, 3}, {1, 3}, {2, 3}, {1, 2}, {2, 2}, {2, 1}};
    EXPECT_EQ(covered_pixels(tri(3.5, 3.5, 0.5, 3.5, 3.5, 0.5), {4, 4}, GetParam()), expected);
}

// The square [0,4]^2 split along y = x: every centre exactly once; the diagonal's centres go to the
// lower triangle, whose diagonal runs down (a left edge).
TEST_P(Coverage, DiagonalSplitSquare) {
    const Viewport vp{4, 4};
    const Pixels lower = covered_pixels(tri(0, 0, 4, 0, 4, 4), vp, GetParam());
    const Pixels upper = covered_pixels(tri(0, 0, 4, 4, 0, 4), vp, GetParam());
    Pixels expected_lower, expected_upper;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) (i >= j ? expected_lower : expected_upper).insert({i, j});
    EXPECT_EQ(lower, expected_lower);
    EXPECT_EQ(upper, expected_upper);
}

// Six triangles around the pixel centre (2.5, 2.5), sharing it as a vertex: together they cover every
// centre of the hexagon exactly once, the shared vertex included.
TEST_P(Coverage, ClosedFanCoversItsCentreOnce) {
    const Viewport vp{5, 5};
    const double ring[6][2] = {{0.5, 2.5}, {1.5, 0.5}, {3.5, 0.5}, {4.5, 2.5}, {3.5, 4.5}, {1.5, 4.5}};
    std::map<std::pair<int, int>, int> count;
    for (int k = 0; k < 6; ++k) {
        const auto& a = ring[k];
        const auto& b = ring[(k + 1) % 6];
        for (const auto& p : covered_pixels(tri(2.5, 2.5, a[0], a[1], b[0], b[1]), vp, GetParam())) ++count[p];
    }
    EXPECT_EQ(count[std::pair(2, 2)], 1);
    // Strictly inside the hexagon: the centre row and the rows above and below, x between the slanted
    // sides (|y - 2.5| = 2 (x - 0.5) on the left), checked by hand: rows 1..3.
    for (const auto& p : Pixels{{1, 1}, {2, 1}, {3, 1}, {1, 2}, {2, 2}, {3, 2}, {1, 3}, {2, 3}, {3, 3}})
        EXPECT_EQ(count[p], 1) << p.first << "," << p.second;
    for (const auto& [p, n] : count) EXPECT_EQ(n, 1) << p.first << "," << p.second;
}

// A needle from (0, 0.5) to the short vertical edge x = 6, y in [0.4375, 0.5625]: symmetric about
// y = 0.5, so the centres (i + 0.5, 0.5) for x in (0, 6) are strictly inside, nothing else.
TEST_P(Coverage, Needle) {
    const Pixels expected = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}};
    EXPECT_EQ(covered_pixels(tri(0, 0.5, 6, 0.4375, 6, 0.5625), {8, 2}, GetParam()), expected);
}

TEST_P(Coverage, ZeroAreaCoversNothing) {
    EXPECT_TRUE(covered_pixels(tri(0.5, 0.5, 2.5, 2.5, 3.5, 3.5), {4, 4}, GetParam()).empty());
    EXPECT_TRUE(covered_pixels(tri(0.5, 0.5, 3.5, 0.5, 3.5, 0.5), {4, 4}, GetParam()).empty());
    EXPECT_TRUE(covered_pixels(tri(1.5, 1.5, 1.5, 1.5, 1.5, 1.5), {4, 4}, GetParam()).empty());
}

// 4x MSAA on one pixel: the lower-left half-square (0,0), (1,0), (0,1) holds the samples with x + y < 1;
// of the four (mirrored Vulkan) positions (0.375, 0.875), (0.875, 0.625), (0.125, 0.375),
// (0.625, 0.125) that is samples 2 and 3.
TEST_P(Coverage, FourSamples) {
    const std::vector<std::size_t> expected = {2, 3};
    EXPECT_EQ(covered_samples(tri(0, 0, 1, 0, 0, 1), {1, 1}, 4, GetParam()), expected);
}

// A triangle larger than a tile and crossing tile borders: the render's tiles (with trivial accept and
// reject) must agree with covered_samples' plain rows, sample for sample.
TEST_P(Coverage, TilesAgreeWithRows) {
    Scene scene;
    scene.viewport = {150, 140};
    scene.samples = 4;
    scene.triangles = {tri(-10.25, 3.5, 149.75, 60.125, 20.5, 139.0625)};
    const Framebuffer fb = render(scene, {GetParam(), 2});
    std::vector<std::size_t> drawn;
    for (std::size_t k = 0; k < fb.ids.size(); ++k)
        if (fb.ids[k] == 0) drawn.push_back(k);
    EXPECT_EQ(drawn, covered_samples(scene.triangles[0], scene.viewport, 4, GetParam()));
    EXPECT_GT(drawn.size(), 20000u);
}

INSTANTIATE_TEST_SUITE_P(AllModes, Coverage, ::testing::ValuesIn(testing::kAllPrecisions),
                         [](const auto& info) { return std::string(name(info.param)); });

}  // namespace
}  // namespace rast::fast
