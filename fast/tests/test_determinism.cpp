// The framebuffer does not depend on the thread count or on the SIMD target Highway dispatches to.
#include "pixels.h"
#include "targets.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstring>
#include <random>

namespace rast::fast {
namespace {

using testing::on_every_target;

// Many overlapping triangles of all sizes, with some shared edges and equal depths, so that tiles,
// trivial accept / reject, the filtered depth test and its exact fallback all take part.
Scene random_scene(int samples) {
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> pos(-20, 220), size(0.5, 90), depth(0, 1);
    Scene scene;
    scene.viewport = {200, 150};
    scene.samples = samples;
    for (int k = 0; k < 600; ++k) {
        const double x = pos(rng), y = pos(rng), s = k % 10 == 0 ? 4 * size(rng) : size(rng);
        const double z = k % 7 == 0 ? 0.5 : depth(rng);
        Triangle t{{{{x, y, z}, {x + s * depth(rng), y + s * depth(rng), depth(rng)},
                     {x - s * depth(rng), y + s * depth(rng), z}}}};
        scene.triangles.push_back(t);
        // Its mirror across the edge v0-v2 shares that edge bit for bit.
        if (k % 5 == 0) scene.triangles.push_back({{t.v[0], t.v[2], {2 * x - t.v[1].x, t.v[1].y, 0.5}}});
    }
    return scene;
}

bool identical(const Framebuffer& a, const Framebuffer& b) {
    return a.ids == b.ids && a.depth.size() == b.depth.size() &&
           std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(double)) == 0;
}

class Determinism : public ::testing::TestWithParam<Precision> {};

TEST_P(Determinism, ThreadCounts) {
    for (const int samples : {1, 4}) {
        const Scene scene = random_scene(samples);
        const Framebuffer one = render(scene, {GetParam(), 1});
        EXPECT_GT(std::count_if(one.ids.begin(), one.ids.end(), [](int id) { return id >= 0; }),
                  static_cast<long>(one.ids.size() / 2));
        for (const int threads : {2, 4, 0}) EXPECT_TRUE(identical(one, render(scene, {GetParam(), threads}))) << threads;
    }
}

TEST_P(Determinism, SimdTargets) {
    const Scene scene = random_scene(4);
    const Framebuffer baseline = render(scene, {GetParam(), 2});
    EXPECT_GE(hwy::SupportedAndGeneratedTargets().size(), 2u)
        << "expected at least one SIMD target besides the fallback";
    on_every_target([&] { EXPECT_TRUE(identical(baseline, render(scene, {GetParam(), 2}))); });
}

INSTANTIATE_TEST_SUITE_P(AllModes, Determinism, ::testing::ValuesIn(testing::kAllPrecisions),
                         [](const auto& info) { return std::string(name(info.param)); });

}  // namespace
}  // namespace rast::fast
