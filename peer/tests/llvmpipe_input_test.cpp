// The peer refuses what it cannot render faithfully, and makes sure it really is llvmpipe.
#include <rast/llvmpipe.h>
#include <rast/reference.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rast::peer {
namespace {

Scene one_triangle(Vertex a) {
    Scene scene{{8, 8}, 1, {}};
    scene.triangles = {Triangle{{Vertex{1, 1, 0}, Vertex{6, 1, 0}, Vertex{1, 6, 0}}},
                       Triangle{{a, Vertex{6, 2, 0}, Vertex{2, 6, 0}}}};
    return scene;
}

// The exception's message, or "" if `f` does not throw std::invalid_argument.
template <class F>
std::string invalid_argument_message(F f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(LlvmpipeInput, RendererIsLlvmpipe) {
    const Llvmpipe llvmpipe(1);
    EXPECT_TRUE(llvmpipe.renderer().starts_with("llvmpipe")) << llvmpipe.renderer();
    EXPECT_EQ(llvmpipe.threads(), 1);
}

TEST(LlvmpipeInput, RejectsASecondThreadCountInTheSameProcess) {
    const Llvmpipe one(1);
    EXPECT_THROW(Llvmpipe(2), std::runtime_error);
}

TEST(LlvmpipeInput, RejectsMultisampledScenes) {
    Scene scene = one_triangle({2, 2, 0});
    scene.samples = 4;
    EXPECT_NE(invalid_argument_message([&] { render_llvmpipe(scene, 1); }).find("1 sample"),
              std::string::npos);
}

TEST(LlvmpipeInput, RejectsNonFiniteCoordinatesNamingTheTriangle) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::string message =
        invalid_argument_message([&] { render_llvmpipe(one_triangle({2, nan, 0}), 1); });
    EXPECT_NE(message.find("triangle 1"), std::string::npos) << message;
    EXPECT_NE(message.find("y"), std::string::npos) << message;
    EXPECT_NE(invalid_argument_message([&] { render_llvmpipe(one_triangle({2, 2, INFINITY}), 1); }),
              "");
}

TEST(LlvmpipeInput, RejectsCoordinatesBeyondFloat) {
    EXPECT_NE(invalid_argument_message([&] { render_llvmpipe(one_triangle({1e39, 2, 0}), 1); }), "");
}

TEST(LlvmpipeInput, RejectsViewportsLargerThanLlvmpipeSupports) {
    // The framebuffer must lie inside the unclipped half of the 16384-wide GL viewport.
    Scene scene = one_triangle({2, 2, 0});
    scene.viewport = {8192, 1};
    EXPECT_NO_THROW(render_llvmpipe(scene, 1));
    scene.viewport = {8193, 1};
    EXPECT_NE(invalid_argument_message([&] { render_llvmpipe(scene, 1); }), "");
    scene.viewport = {0, 8};
    EXPECT_NE(invalid_argument_message([&] { render_llvmpipe(scene, 1); }), "");
}

TEST(LlvmpipeInput, EmptySceneLeavesEveryPixelEmpty) {
    const Framebuffer fb = render_llvmpipe(Scene{{3, 2}, 1, {}}, 1);
    for (const auto id : fb.ids) EXPECT_EQ(id, Framebuffer::kNoTriangle);
}

// Depths one ulp apart, far from zero: both triangles still reach the depth range and are drawn (a depth
// map that scaled the narrow range without first centring it sent them past the far plane, and llvmpipe
// drew nothing; rast conform found it). A 24-bit depth buffer cannot order them: coverage alone is checked.
TEST(LlvmpipeInput, ANarrowDepthRangeFarFromZeroIsDrawn) {
    const double z = 0.5, above = std::nextafter(z, 1.0);
    const Scene scene{{4, 4}, 1, {Triangle{{Vertex{0, 0, above}, Vertex{4, 0, above}, Vertex{0, 4, above}}},
                                  Triangle{{Vertex{0, 0, z}, Vertex{4, 0, z}, Vertex{4, 4, z}}}}};
    const Framebuffer fb = render_llvmpipe(scene, 1);
    const Framebuffer exact = reference::render(scene);
    int covered = 0;
    for (std::size_t k = 0; k < fb.ids.size(); ++k) {
        EXPECT_EQ(fb.ids[k] != Framebuffer::kNoTriangle, exact.ids[k] != Framebuffer::kNoTriangle) << "pixel " << k;
        covered += fb.ids[k] != Framebuffer::kNoTriangle;
    }
    // Centres below the anti-diagonal x + y = 4 (triangle 0; on it, its right edge) or right of the
    // diagonal y = x (triangle 1; on it, its left edge): all but (1, 2), (0, 3), (1, 3) and (2, 3).
    EXPECT_EQ(covered, 12);
}

}  // namespace
}  // namespace rast::peer
