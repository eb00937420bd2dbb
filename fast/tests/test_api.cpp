// Precision names, input validation and rendering into a kept framebuffer.
#include "pixels.h"

#include <rast/fast.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rast::fast {
namespace {

TEST(Api, NamesRoundTrip) {
    for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16, Precision::float32,
                        Precision::float64})
        EXPECT_EQ(parse_precision(name(p)), p);
    EXPECT_EQ(name(Precision::fixed8), "fixed8");
    EXPECT_EQ(name(Precision::float32), "float32");
    EXPECT_EQ(parse_precision("fixed12"), std::nullopt);
    EXPECT_EQ(parse_precision(""), std::nullopt);
}

TEST(Api, RejectsBadInput) {
    Scene scene;
    scene.viewport = {0, 4};
    EXPECT_THROW(render(scene), std::invalid_argument);
    scene.viewport = {4, 4};
    scene.samples = 3;
    EXPECT_THROW(render(scene), std::invalid_argument);
    scene.samples = 1;
    scene.triangles.push_back({{{{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}}});
    try {
        render(scene);
        FAIL() << "a NaN coordinate was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("triangle 0, vertex 2"), std::string::npos) << e.what();
    }
    scene.triangles[0].v[2].y = std::numeric_limits<double>::infinity();
    EXPECT_THROW(render(scene), std::invalid_argument);
    scene.triangles[0].v[2].y = 1;
    EXPECT_THROW(render(scene, {Precision::fixed8, -1}), std::invalid_argument);
    EXPECT_THROW(render(scene, {Precision::fixed8, 1025}), std::invalid_argument);  // TBB crashed at 70000
    EXPECT_NO_THROW(render(scene, {Precision::fixed8, 0}));
}

// The functions that take a triangle without rendering check it as render does.
TEST(Api, EveryFunctionRejectsBadInput) {
    const Triangle nan{{{{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}}};
    const Triangle good{{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}};
    const auto bogus = static_cast<Precision>(7);
    EXPECT_EQ(name(bogus), "unknown");
    EXPECT_THROW(snap(nan, Precision::fixed8), std::invalid_argument);
    EXPECT_THROW(snap(good, bogus), std::invalid_argument);
    EXPECT_THROW(edge_error_bound(nan, Precision::float32, {4, 4}), std::invalid_argument);
    EXPECT_THROW(edge_error_bound(good, Precision::float32, {0, -5}), std::invalid_argument);
    EXPECT_THROW(edge_error_bound_at(good, Precision::float32, std::nan(""), 0), std::invalid_argument);
    EXPECT_THROW(edge_error_bound_at(nan, Precision::float32, 0, 0), std::invalid_argument);
    EXPECT_THROW(covered_samples(good, {4, 4}, 1, bogus), std::invalid_argument);
    Scene scene;
    scene.viewport = {4, 4};
    scene.triangles.push_back(good);
    EXPECT_THROW(render(scene, {bogus, 1}), std::invalid_argument);
}

// Sides within 2^24 whose framebuffer would not be: refused before anything is sized for them (a count of
// 2^35 tiles once overflowed an int, and binning wrote out of bounds).
TEST(Api, RejectsAFramebufferOfMoreThan2To32Samples) {
    Scene scene;
    scene.triangles.push_back({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}});
    for (const auto& [viewport, samples] : {std::pair{Viewport{1 << 24, 1 << 23}, 1}, std::pair{Viewport{1 << 16, 1 << 16}, 4},
                                            std::pair{Viewport{1 << 24, 257}, 1}}) {
        scene.viewport = viewport;
        scene.samples = samples;
        try {
            render(scene);
            FAIL() << viewport.width << "x" << viewport.height << " was accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("more than 2^32"), std::string::npos) << e.what();
        }
        EXPECT_THROW(covered_samples(scene.triangles[0], viewport, samples, Precision::fixed8), std::invalid_argument);
    }
}

// A non-finite depth is rejected whichever way binning takes the triangle: small and covering samples,
// small and of zero area, outside the viewport, or large.
TEST(Api, RejectsANonFiniteDepthOnEveryLane) {
    const std::vector<Triangle> lanes{{{{{1, 1, 0}, {9, 1, 0}, {1, 9, 0}}}},
                                      {{{{1, 1, 0}, {2, 2, 0}, {3, 3, 0}}}},
                                      {{{{100, 100, 0}, {109, 100, 0}, {100, 109, 0}}}},
                                      {{{{0, 0, 0}, {60, 0, 0}, {0, 60, 0}}}}};
    for (const Precision precision : testing::kAllPrecisions)
        for (const Triangle& lane : lanes) {
            Scene scene;
            scene.viewport = {64, 64};
            scene.triangles = {lane};
            scene.triangles[0].v[2].z = std::nan("");
            try {
                render(scene, {precision, 1});
                ADD_FAILURE() << "a NaN depth was accepted in " << name(precision);
            } catch (const std::invalid_argument& e) {
                EXPECT_NE(std::string(e.what()).find("triangle 0, vertex 2"), std::string::npos) << e.what();
            }
        }
}

// Binning checks the coordinates, chunk by chunk and in parallel; the error still names the first bad
// triangle, not the first one a thread happened to meet.
TEST(Api, NamesTheFirstBadTriangleOfAScene) {
    Scene scene;
    scene.viewport = {64, 64};
    scene.triangles.assign(20000, Triangle{{{{1, 1, 0}, {9, 1, 0}, {1, 9, 0}}}});
    scene.triangles[17000].v[0].z = std::numeric_limits<double>::infinity();
    scene.triangles[3000].v[1].x = std::nan("");
    for (const int threads : {1, 2}) {
        try {
            render(scene, {Precision::fixed8, threads});
            FAIL() << "a NaN coordinate was accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("triangle 3000, vertex 1"), std::string::npos) << e.what();
        }
    }
}

// One triangle owns pixel (0, 0) alone: the centres (1.5, 0.5) and (0.5, 1.5) lie on its hypotenuse, a
// right edge (it rises along the counter-clockwise boundary), which does not own them.
Scene corner_scene(Viewport vp) {
    Scene scene;
    scene.viewport = vp;
    scene.triangles.push_back({{{{0, 0, 0.5}, {2, 0, 0.5}, {0, 2, 0.5}}}});
    return scene;
}

void expect_corner_only(const Framebuffer& fb, Viewport vp) {
    ASSERT_EQ(fb.viewport.width, vp.width);
    ASSERT_EQ(fb.viewport.height, vp.height);
    ASSERT_EQ(fb.ids.size(), static_cast<std::size_t>(vp.width * vp.height));
    ASSERT_EQ(fb.depth.size(), fb.ids.size());
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            const bool corner = i == 0 && j == 0;
            EXPECT_EQ(fb.id(i, j), corner ? 0 : Framebuffer::kNoTriangle) << i << ", " << j;
            const double depth = corner ? 0.5 : std::numeric_limits<double>::infinity();
            EXPECT_EQ(fb.depth[fb.index(i, j)], depth) << i << ", " << j;
        }
}

TEST(Api, RendersIntoAKeptFramebufferOverwritingEverySample) {
    const Viewport vp{4, 2};
    Framebuffer target(vp, 1);
    std::fill(target.ids.begin(), target.ids.end(), 7);
    std::fill(target.depth.begin(), target.depth.end(), -5.0);
    const std::int32_t* storage = target.ids.data();
    render(corner_scene(vp), target, {Precision::fixed8, 2});
    expect_corner_only(target, vp);
    EXPECT_EQ(target.ids.data(), storage) << "the storage of the right size was not kept";
}

// Tiles no triangle reaches are written empty without a tile buffer: every sample of them in a kept
// framebuffer, partial tiles at the right and bottom edges too, with one sample per pixel and four.
TEST(Api, EmptyTilesOverwriteAKeptFramebuffer) {
    const Viewport vp{130, 70};  // 3 x 2 tiles of 64, the last column and row partial
    for (const int samples : {1, 4, 16}) {
        Scene scene;
        scene.viewport = vp;
        scene.samples = samples;
        scene.triangles.push_back({{{{1, 1, 0.5}, {9, 1, 0.5}, {1, 9, 0.5}}}});
        Framebuffer target(vp, samples);
        std::fill(target.ids.begin(), target.ids.end(), 7);
        std::fill(target.depth.begin(), target.depth.end(), -5.0);
        render(scene, target, {Precision::fixed8, 2});
        const Framebuffer fresh = render(scene);
        EXPECT_EQ(target.ids, fresh.ids);
        EXPECT_EQ(target.depth, fresh.depth);
        for (int j = 0; j < vp.height; ++j)
            for (int i = 0; i < vp.width; ++i)
                for (int s = 0; s < samples; ++s) {
                    if (i < 10 && j < 10) continue;  // around the triangle
                    ASSERT_EQ(target.id(i, j, s), Framebuffer::kNoTriangle) << i << ", " << j << ", " << s;
                    ASSERT_EQ(target.depth[target.index(i, j, s)], std::numeric_limits<double>::infinity());
                }
        EXPECT_EQ(target.id(2, 2, 0), 0);
    }
}

TEST(Api, RendersIntoAFramebufferOfAnotherSize) {
    Framebuffer target(Viewport{64, 64}, 4);
    const Viewport vp{3, 3};
    render(corner_scene(vp), target);
    EXPECT_EQ(target.samples, 1);
    expect_corner_only(target, vp);
}

// Two triangles over the same pixels at depths `near` (id 1) and `far` (id 0) one ulp apart: too close
// for the double filter, so the exact comparison decides every sample.
Scene near_tie_scene(double far, double near) {
    Scene scene;
    scene.viewport = {8, 8};
    scene.triangles.push_back({{{{1, 1, far}, {7, 1, far}, {1, 7, far}}}});
    scene.triangles.push_back({{{{1, 1, near}, {7, 1, near}, {1, 7, near}}}});
    return scene;
}

// A Renderer keeps its memory from call to call, never what it decided: the exact planes it built for
// ids 0 and 1 of one scene would tie them again in the next, whose ids 0 and 1 are different triangles.
TEST(Api, ARendererForgetsTheLastScenesTriangles) {
    Renderer renderer;
    Framebuffer target;
    renderer.render(near_tie_scene(0.5, 0.5), target);
    EXPECT_EQ(target.id(2, 2), 0) << "equal depths: the lower id";
    renderer.render(near_tie_scene(std::nextafter(0.5, 1.0), 0.5), target);
    EXPECT_EQ(target.id(2, 2), 1) << "the nearer one";
    EXPECT_EQ(target.depth[target.index(2, 2)], 0.5);
}

// The wide path's spans, which a thread keeps while it works in one row of tiles, are the scene's own:
// the next scene's big triangle is set up where the last one's was, and in the same row of tiles (the
// only one), where the last scene's spans would draw the last scene's triangle. Its left edge slants,
// so that the tiles it crosses need spans: at row 30 (y = 30.5) it is at x + 30 * 31.5 / 62 = x + 15.24.
TEST(Api, ARendererForgetsTheLastScenesWideSpans) {
    Renderer renderer;
    Framebuffer target;
    const double r = 0x1p45;  // beyond the 64-bit path's range and the near edges' (fixed8: 2^42): spans
    for (const int x : {70, 20}) {
        Scene scene;
        scene.viewport = {200, 60};
        const double left = x;
        scene.triangles.push_back({{{{left, -1, 0.5}, {2 * r, 30, 0.5}, {left + 30, 61, 0.5}}}});
        renderer.render(scene, target);
        EXPECT_EQ(target.id(x + 14, 30), Framebuffer::kNoTriangle) << x;
        EXPECT_EQ(target.id(x + 15, 30), 0) << x;
        EXPECT_EQ(target.ids, render(scene).ids) << x;
    }
}

// One Renderer through scenes of other triangles, sizes, sample counts and precisions, each rendered as
// a fresh call renders it; the thread count changes only between runs of them, so that its arena and
// tile buffers are kept too. Every fifth triangle is an occluder (binning.h), enough triangles for two
// chunks on two threads, and a scene that fails its check comes before every other one: the occluders'
// order (occluders.h), kept from render to render, must not carry a stale entry over.
TEST(Api, ARendererRendersEachSceneAsAFreshCallDoes) {
    Renderer renderer;
    Framebuffer target;
    const Viewport viewports[] = {{130, 70}, {8, 8}, {64, 200}};
    int step = 0;
    for (const int threads : {2, 1})
        for (const Precision precision : testing::kAllPrecisions)
            for (const int samples : {1, 4}) {
                Scene scene;
                scene.viewport = viewports[step % 3];
                scene.samples = samples;
                for (int k = 0; k < 300; ++k) {
                    const double x = 3.0 * (k % 40) + step, y = 1.5 * (k % 40) + k / 40;
                    const double z = 0.25 + ((k + step) % 7) / 8.0, reach = k % 5 == 0 ? 140 : 40;
                    scene.triangles.push_back(
                        {{{{x, y, z}, {x + reach, y + 3, z}, {x + 5, y + reach + 10 - step, 1 - z}}}});
                }
                if (step % 2 == 1) {
                    Scene bad = scene;
                    bad.triangles[150].v[2].y = std::numeric_limits<double>::quiet_NaN();
                    EXPECT_THROW(renderer.render(bad, target, {precision, threads}), std::invalid_argument);
                }
                ++step;
                renderer.render(scene, target, {precision, threads});
                const Framebuffer fresh = render(scene, {precision, threads});
                EXPECT_EQ(target.ids, fresh.ids) << name(precision) << ", " << samples << " samples, " << threads;
                EXPECT_EQ(target.depth, fresh.depth) << name(precision) << ", " << samples << " samples";
            }
}

// A Renderer moved from starts afresh rather than failing.
TEST(Api, AMovedFromRendererStillRenders) {
    Renderer renderer;
    Framebuffer target;
    renderer.render(corner_scene({4, 2}), target);
    Renderer other = std::move(renderer);
    renderer.render(corner_scene({3, 3}), target);  // NOLINT(bugprone-use-after-move): the case under test
    expect_corner_only(target, {3, 3});
    other.render(corner_scene({4, 2}), target);
    expect_corner_only(target, {4, 2});
}

// The fast path streams whole cache lines of the framebuffer's rows (copy_out): its storage starts on a
// line however it was made, constructed, fitted by a render or copied.
TEST(Api, FramebufferStorageStartsOnACacheLine) {
    const auto on_a_line = [](const Framebuffer& fb) {
        return reinterpret_cast<std::uintptr_t>(fb.ids.data()) % 64 == 0 &&
               reinterpret_cast<std::uintptr_t>(fb.depth.data()) % 64 == 0;
    };
    for (int width = 1; width <= 9; ++width) {
        EXPECT_TRUE(on_a_line(Framebuffer(Viewport{width, 3}, 1))) << width;
        Framebuffer fitted;
        render(Scene{{width, 5}, 4, {}}, fitted);
        EXPECT_TRUE(on_a_line(fitted)) << width;
        const Framebuffer copy = fitted;
        EXPECT_TRUE(on_a_line(copy)) << width;
    }
}

TEST(Api, InvalidInputLeavesTheTargetUntouched) {
    Scene scene = corner_scene({4, 2});
    scene.triangles[0].v[1].x = std::numeric_limits<double>::quiet_NaN();
    Framebuffer target(Viewport{5, 5}, 1);
    std::fill(target.ids.begin(), target.ids.end(), 3);
    EXPECT_THROW(render(scene, target), std::invalid_argument);
    EXPECT_EQ(target.viewport.width, 5);
    EXPECT_EQ(target.ids, Samples<std::int32_t>(25, 3));
}

}  // namespace
}  // namespace rast::fast
