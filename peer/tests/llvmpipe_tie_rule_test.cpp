// Hand-computed id buffers for samples exactly on shared edges: llvmpipe, fed the mirrored scene, must
// apply our left + top rule (docs/design.md). In each scene the triangle that must NOT own the shared
// edge is the nearer one with the lower id, so a sample covered twice would show up as its id.
#include <rast/llvmpipe.h>

#include <gtest/gtest.h>

#include <vector>

namespace rast::peer {
namespace {

Triangle tri(Vertex a, Vertex b, Vertex c) { return Triangle{{a, b, c}}; }

// The ids of a 4x4 framebuffer, written top row first as in the picture.
std::vector<std::vector<int>> picture(const Framebuffer& fb) {
    std::vector<std::vector<int>> rows;
    for (int j = fb.viewport.height - 1; j >= 0; --j) {
        rows.emplace_back();
        for (int i = 0; i < fb.viewport.width; ++i) rows.back().push_back(fb.id(i, j));
    }
    return rows;
}

TEST(LlvmpipeTieRule, DiagonalThroughPixelCentresBelongsToTheTriangleOnItsRight) {
    // The diagonal y = x runs through the centres (k + 1/2, k + 1/2). It is a left edge (dy < 0 when
    // traversed counter-clockwise) of triangle 1, below it, and a right edge of triangle 0, above it.
    Scene scene{{4, 4}, 1, {}};
    scene.triangles = {tri({0, 0, 0}, {4, 4, 0}, {0, 4, 0}),   // above the diagonal, nearer
                       tri({0, 0, 1}, {4, 0, 1}, {4, 4, 1})};  // below it: owns it
    const Framebuffer fb = render_llvmpipe(scene, 1);
    const std::vector<std::vector<int>> expected = {{0, 0, 0, 1},  // row j = 3
                                                    {0, 0, 1, 1},
                                                    {0, 1, 1, 1},
                                                    {1, 1, 1, 1}};  // row j = 0
    EXPECT_EQ(picture(fb), expected);
}

TEST(LlvmpipeTieRule, AntiDiagonalThroughPixelCentresBelongsToTheTriangleOnItsRight) {
    // x + y = 4 runs through (k + 1/2, 7/2 - k): a left edge of the upper-right triangle 1.
    Scene scene{{4, 4}, 1, {}};
    scene.triangles = {tri({0, 4, 0}, {4, 0, 0}, {0, 0, 0}),   // lower left, nearer
                       tri({0, 4, 1}, {4, 4, 1}, {4, 0, 1})};  // upper right: owns it
    const Framebuffer fb = render_llvmpipe(scene, 1);
    const std::vector<std::vector<int>> expected = {{1, 1, 1, 1},
                                                    {0, 1, 1, 1},
                                                    {0, 0, 1, 1},
                                                    {0, 0, 0, 1}};
    EXPECT_EQ(picture(fb), expected);
}

TEST(LlvmpipeTieRule, HorizontalEdgeThroughPixelCentresBelongsToTheTriangleBelow) {
    // y = 3/2 runs through the centres of row 1. It is the top edge (dy = 0, dx < 0 counter-clockwise)
    // of triangle 1 below it, and a bottom edge of triangle 0 above it. This is the case the mirror
    // y -> H - y exists for: in GL's coordinates llvmpipe sees it as a bottom edge of triangle 1.
    // No other edge passes through a pixel centre. Row 0 (y = 1/2) meets triangle 1 for
    // 4/3 < x < 8/3, row 2 (y = 5/2) meets triangle 0 for 4/5 < x < 16/5, row 3 (y = 7/2) for
    // 8/5 < x < 12/5, which holds no centre.
    Scene scene{{4, 4}, 1, {}};
    scene.triangles = {tri({0, 1.5, 0}, {4, 1.5, 0}, {2, 4, 0}),   // above, nearer
                       tri({0, 1.5, 1}, {2, 0, 1}, {4, 1.5, 1})};  // below: owns the edge
    const Framebuffer fb = render_llvmpipe(scene, 1);
    const std::vector<std::vector<int>> expected = {{-1, -1, -1, -1},
                                                    {-1, 0, 0, -1},
                                                    {1, 1, 1, 1},
                                                    {-1, 1, 1, -1}};
    EXPECT_EQ(picture(fb), expected);
}

TEST(LlvmpipeTieRule, DepthReadsBackWithinTheDepthBufferQuantum) {
    // z spans [0, 1], mapped onto a quarter..three-quarter band of a 24-bit buffer: the quantum is
    // 2^-23 in scene units.
    Scene scene{{4, 4}, 1, {}};
    scene.triangles = {tri({0, 0, 0}, {4, 4, 0}, {0, 4, 0}), tri({0, 0, 1}, {4, 0, 1}, {4, 4, 1})};
    const Framebuffer fb = render_llvmpipe(scene, 1);
    EXPECT_NEAR(fb.depth[fb.index(0, 3)], 0.0, 0x1p-22);
    EXPECT_NEAR(fb.depth[fb.index(3, 0)], 1.0, 0x1p-22);
}

}  // namespace
}  // namespace rast::peer
