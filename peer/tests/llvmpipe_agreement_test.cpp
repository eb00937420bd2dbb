// On vertices already on llvmpipe's 1/256 grid, llvmpipe decides coverage exactly, so its id buffer
// must equal the exact reference's and the fast path's fixed8 one pixel for pixel. Depths are
// separated into a band per triangle, so the visible triangle never depends on depth precision.
#include <rast/bench_scenes.h>
#include <rast/fast.h>
#include <rast/llvmpipe.h>
#include <rast/reference.h>

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>

namespace rast::peer {
namespace {

using bench::Shape;

struct Case {
    Shape shape;
    std::size_t triangles;
};

class LlvmpipeAgreement : public ::testing::TestWithParam<Case> {};

// "" if the buffers agree, else the number of differing pixels and the first few.
std::string differences(const Framebuffer& expected, const Framebuffer& actual) {
    std::ostringstream out;
    int count = 0;
    for (int j = 0; j < expected.viewport.height; ++j) {
        for (int i = 0; i < expected.viewport.width; ++i) {
            if (expected.id(i, j) == actual.id(i, j)) continue;
            if (++count <= 5) {
                out << " (" << i << ", " << j << "): " << expected.id(i, j) << " vs " << actual.id(i, j) << ";";
            }
        }
    }
    return count == 0 ? "" : std::to_string(count) + " pixels differ:" + out.str();
}

TEST_P(LlvmpipeAgreement, IdBufferEqualsReferenceAndFixed8) {
    // A viewport neither square nor a power of two, so that the mirror and the power-of-two GL
    // viewport are both exercised; triangles near its border reach outside it.
    const bench::SceneSpec spec{.shape = GetParam().shape,
                                .triangles = GetParam().triangles,
                                .viewport = {200, 120},
                                .on_grid_256 = true,
                                .depth = bench::Depth::separated,
                                .seed = 2024};
    const Scene scene = bench::make_scene(spec);
    const Framebuffer exact = reference::render(scene);
    const Framebuffer fixed8 = fast::render(scene, {.precision = fast::Precision::fixed8, .threads = 1});
    const Framebuffer peer = render_llvmpipe(scene, 1);

    const std::set<std::int32_t> visible(exact.ids.begin(), exact.ids.end());
    ASSERT_GT(visible.size(), 2u) << "a scene that shows fewer than two triangles proves little";
    EXPECT_EQ(differences(exact, peer), "") << "reference vs llvmpipe, " << bench::describe(spec);
    EXPECT_EQ(differences(exact, fixed8), "") << "reference vs fast fixed8, " << bench::describe(spec);
}

INSTANTIATE_TEST_SUITE_P(OnThe256Grid, LlvmpipeAgreement,
                         ::testing::Values(Case{Shape::tiny, 3000}, Case{Shape::small, 600},
                                           Case{Shape::medium, 100}, Case{Shape::large, 20},
                                           Case{Shape::needle, 300}, Case{Shape::mesh, 600},
                                           Case{Shape::fan, 600}, Case{Shape::centre_edges, 600}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return std::string(bench::name(info.param.shape));
                         });

}  // namespace
}  // namespace rast::peer
