// The engines are what their names say, and an engine that keeps memory between renders gives what a
// fresh one gives.
#include <rast/engine.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rast {
namespace {

// Two triangles meeting along a diagonal, one in front of the other where they overlap.
Scene two_triangles(Viewport vp, int samples) {
    const double w = vp.width, h = vp.height;
    return {vp, samples, {Triangle{{Vertex{0, 0, 0.5}, Vertex{w, 0, 0.5}, Vertex{0, h, 0.5}}},
                          Triangle{{Vertex{w, h, 0.25}, Vertex{0, h * 0.25, 0.75}, Vertex{w * 0.25, 0, 0.75}}}}};
}

TEST(Engines, AreTheReferenceThenEveryPrecision) {
    const std::vector<Engine> engines = all_engines();
    std::vector<std::string> names;
    for (const Engine& e : engines) names.push_back(e.name);
    EXPECT_EQ(names, (std::vector<std::string>{"reference", "fixed4", "fixed8", "fixed16", "float32", "float64"}));
    EXPECT_TRUE(engines[0].is_reference());
    EXPECT_EQ(engines[0].description, "reference (exact)");
    EXPECT_EQ(engines[2].description, "fast fixed8, 1 thread");
    for (std::size_t k = 0; k < engines.size(); ++k) {
        EXPECT_EQ(engines[k].exact(), k < 4) << engines[k].name;
        EXPECT_EQ(engines[k].exact_depth(), k == 0) << engines[k].name;
        EXPECT_EQ(static_cast<bool>(engines[k].edge_error_bound_at), k >= 1) << engines[k].name;
    }
    EXPECT_EQ(engines[1].snap_bits(), 4);
    EXPECT_EQ(engines[3].snap_bits(), 16);
    EXPECT_EQ(engines[4].snap_bits(), std::nullopt);
}

// A fast engine keeps its renderer: a larger scene after a smaller one, with more samples, then the
// smaller again into the same framebuffer, each equal to what a fresh engine draws.
TEST(Engines, AKeptRendererGivesWhatAFreshOneGives) {
    const Engine kept = fast_engine(fast::Precision::fixed8, 2);
    Framebuffer fb;
    for (const Scene& scene : {two_triangles({9, 7}, 1), two_triangles({130, 70}, 4), two_triangles({9, 7}, 1)}) {
        kept.draw(scene, fb);
        const Framebuffer fresh = fast_engine(fast::Precision::fixed8).render(scene);
        EXPECT_EQ(fb.ids, fresh.ids);
        EXPECT_EQ(fb.depth, fresh.depth);
        EXPECT_EQ(fb.ids, reference_engine().render(scene).ids);
    }
}

TEST(Engines, TheReferenceCountsItsExactArithmeticWhenAsked) {
    reference::Stats stats;
    reference_engine(&stats).render(two_triangles({9, 7}, 1));
    EXPECT_EQ(stats.triangles, 2u);
    EXPECT_GT(stats.samples_covered, 0u);
}

}  // namespace
}  // namespace rast
