// The z-buffer: smaller z is nearer, equal depth goes to the lower id, decided exactly.
#include "pixels.h"

#include <gtest/gtest.h>

#include <limits>
#include <utility>
#include <vector>

namespace rast::fast {
namespace {

using testing::tri;

class Depth : public ::testing::TestWithParam<Precision> {};

Triangle with_z(Triangle t, double z0, double z1, double z2) {
    t.v[0].z = z0;
    t.v[1].z = z1;
    t.v[2].z = z2;
    return t;
}

TEST_P(Depth, EqualDepthGoesToTheLowerId) {
    Scene scene;
    scene.viewport = {4, 4};
    const Triangle t = tri(0, 0, 8, 0, 0, 8, 0.25);
    scene.triangles = {t, t, t};
    const Framebuffer fb = render(scene, {GetParam(), 1});
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(fb.id(i, j), 0);
            EXPECT_EQ(fb.depth[fb.index(i, j)], 0.25);
        }
}

// Two flat triangles over the same samples, a least step apart in depth (where the double test cannot
// decide and the exact order of constant depths does), or at -0 and +0, which are equal: the nearer wins
// in either id order, and the tie goes to the lower id.
TEST_P(Depth, FlatTrianglesAnUlpApartAreOrderedExactly) {
    Scene scene;
    scene.viewport = {4, 4};
    const Triangle t = tri(0, 0, 8, 0, 0, 8, 0);
    const double least = std::numeric_limits<double>::denorm_min();
    for (const auto& [near, far] : {std::pair{0.0, least}, std::pair{1.0, 1.0 + 0x1p-52}, std::pair{-least, 0.0},
                                    std::pair{-0.0, 0.0}, std::pair{0.0, -0.0}})
        for (const bool near_first : {true, false}) {
            const Triangle n = with_z(t, near, near, near), f = with_z(t, far, far, far);
            scene.triangles = near_first ? std::vector{n, f} : std::vector{f, n};
            const bool tie = near == far;
            const std::int32_t winner = tie || near_first ? 0 : 1;
            const Framebuffer fb = render(scene, {GetParam(), 1});
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i)
                    EXPECT_EQ(fb.id(i, j), winner) << near << " against " << far << ", nearer first " << near_first;
        }
}

// Two different, coplanar triangles on the plane z = (x + y) / 8: where both cover a sample their
// exact depths are equal, whatever their double plane coefficients, so the lower id wins.
TEST_P(Depth, CoplanarOverlapIsATieBrokenById) {
    Scene scene;
    scene.viewport = {8, 8};
    const auto plane = [](double x, double y) { return (x + y) / 8; };
    const Triangle a = with_z(tri(0, 0, 8, 0, 0, 8), plane(0, 0), plane(8, 0), plane(0, 8));
    // On the 1/16 grid, so that snapping keeps the triangle on the plane.
    const Triangle b = with_z(tri(0.125, 0.3125, 7.6875, 1.3125, 2.875, 7.0625), plane(0.125, 0.3125),
                              plane(7.6875, 1.3125), plane(2.875, 7.0625));
    for (const bool a_first : {true, false}) {
        scene.triangles = a_first ? std::vector{a, b} : std::vector{b, a};
        const Framebuffer fb = render(scene, {GetParam(), 1});
        // (2.5, 2.5) is inside both: the triangle listed first owns it.
        EXPECT_EQ(fb.id(2, 2), 0);
        EXPECT_EQ(fb.id(3, 1), 0);
        // (6.5, 6.5) is inside neither.
        EXPECT_EQ(fb.id(6, 6), -1);
    }
}

// Two coplanar triangles of more than a tile's area (occluders: the engine composes them first, nearest
// corner first, so B before A whatever their ids): each sample inside both ties, and goes to the lower id
// with that triangle's own depth, in either id order and on any thread count.
TEST_P(Depth, CoplanarOccludersTieToTheLowerIdInEitherOrder) {
    const auto plane = [](double x, double y) { return 0.25 + (x + y) / 1024; };
    const auto on_plane = [&](double x0, double y0, double x1, double y1, double x2, double y2) {
        return with_z(tri(x0, y0, x1, y1, x2, y2), plane(x0, y0), plane(x1, y1), plane(x2, y2));
    };
    const Triangle a = on_plane(0, 0, 256, 0, 0, 256), b = on_plane(-64, -64, 300, 0, 0, 300);
    const auto alone = [&](const Triangle& t) { return render(Scene{{256, 256}, 1, {t}}, {GetParam(), 1}); };
    const Framebuffer a_alone = alone(a), b_alone = alone(b);
    for (const bool a_first : {true, false}) {
        const Scene scene{{256, 256}, 1, a_first ? std::vector{a, b} : std::vector{b, a}};
        const Framebuffer& first_alone = a_first ? a_alone : b_alone;
        for (const int threads : {1, 2}) {
            const Framebuffer fb = render(scene, {GetParam(), threads});
            for (int j = 0; j < 256; j += 5)
                for (int i = 0; i < 256; i += 3) {
                    const double x = i + 0.5, y = j + 0.5;
                    if (x + y < 255) {  // inside both
                        EXPECT_EQ(fb.id(i, j), 0) << i << ", " << j;
                        EXPECT_EQ(fb.depth[fb.index(i, j)], first_alone.depth[first_alone.index(i, j)])
                            << i << ", " << j;
                    } else if (x + y > 257 && x + y < 299) {  // B's alone
                        EXPECT_EQ(fb.id(i, j), a_first ? 1 : 0) << i << ", " << j;
                    }
                }
        }
    }
}

// A covers the viewport with z = x, B with z = c: A is nearer where x < c. At c = 4.5 the centre
// x = 4.5 is an exact tie, owned by the lower id.
TEST_P(Depth, Interpenetration) {
    Scene scene;
    scene.viewport = {8, 2};
    const Triangle slope = with_z(tri(0, 0, 16, 0, 0, 16), 0, 16, 0);
    const Triangle flat = tri(0, 0, 16, 0, 0, 16, 4);
    scene.triangles = {slope, flat};
    Framebuffer fb = render(scene, {GetParam(), 1});
    for (int i = 0; i < 8; ++i) EXPECT_EQ(fb.id(i, 1), i <= 3 ? 0 : 1) << i;
    EXPECT_EQ(fb.depth[fb.index(2, 1)], 2.5);
    EXPECT_EQ(fb.depth[fb.index(6, 1)], 4.0);

    const Triangle tie = tri(0, 0, 16, 0, 0, 16, 4.5);
    scene.triangles = {slope, tie};
    fb = render(scene, {GetParam(), 1});
    EXPECT_EQ(fb.id(4, 0), 0);
    EXPECT_EQ(fb.id(5, 0), 1);
    scene.triangles = {tie, slope};
    fb = render(scene, {GetParam(), 1});
    EXPECT_EQ(fb.id(4, 0), 0);
    EXPECT_EQ(fb.id(3, 0), 1);
}

// The per-sample z-buffer with 4 samples: the plane z = x - 0.5 against the flat z = 0 inside pixel
// (0, 0): samples with x < 0.5 (samples 2 at x = 0.125 and 0 at 0.375) are nearer on the slope.
TEST_P(Depth, PerSampleDepth) {
    Scene scene;
    scene.viewport = {1, 1};
    scene.samples = 4;
    scene.triangles = {with_z(tri(-4, -4, 8, -4, -4, 8), -4.5, 7.5, -4.5), tri(-4, -4, 8, -4, -4, 8, 0)};
    const Framebuffer fb = render(scene, {GetParam(), 1});
    EXPECT_EQ(fb.id(0, 0, 0), 0);
    EXPECT_EQ(fb.id(0, 0, 1), 1);
    EXPECT_EQ(fb.id(0, 0, 2), 0);
    EXPECT_EQ(fb.id(0, 0, 3), 1);
    EXPECT_EQ(fb.depth[fb.index(0, 0, 2)], 0.125 - 0.5);
}

// Corner depths of +-2^1023 overflow the double plane (z1 - z0 = -2^1024), so the depth written is the
// exact one rounded to nearest, ties to even. With corners (0, 0), (4, 0), (0, 4) the plane is
// z0 (1 - x/4 - y/4) + z1 x/4 + z2 y/4; at (0.5, 0.5) that is 1.25 * 2^1022 + z2 / 8, and z2 / 8 = 2^969 is
// half an ulp of 2^1022.
TEST_P(Depth, OverflowingPlaneWritesTheExactDepthRounded) {
    Scene scene;
    scene.viewport = {2, 1};
    const Triangle t = tri(0, 0, 4, 0, 0, 4);
    scene.triangles = {with_z(t, 0x1p1023, -0x1p1023, 0x1p972)};
    Framebuffer fb = render(scene, {GetParam(), 1});
    EXPECT_EQ(fb.depth[fb.index(0, 0)], 0x1.4p1022);  // a tie, to the even neighbour below
    // At (1.5, 0.5): 2^1022 - 0.75 * 2^1022 + 2^969 = 2^1020 (1 + 2^-51), exact.
    EXPECT_EQ(fb.depth[fb.index(1, 0)], 0x1.0000000000002p1020);
    // Just above the tie: z2 = 2^972 (1 + 2^-52) rounds up by one ulp.
    scene.triangles = {with_z(t, 0x1p1023, -0x1p1023, 0x1.0000000000001p972)};
    fb = render(scene, {GetParam(), 1});
    EXPECT_EQ(fb.depth[fb.index(0, 0)], 0x1.4000000000001p1022);
    // Both planes overflow and meet where x = y; elsewhere the exact order decides: the mirror image
    // (z1 and z2 swapped) is nearer where y > x, and the lower id wins the tie at (0.5, 0.5).
    scene.viewport = {2, 2};
    scene.triangles = {with_z(t, 0x1p1023, -0x1p1023, 0x1p1023), with_z(t, 0x1p1023, 0x1p1023, -0x1p1023)};
    fb = render(scene, {GetParam(), 1});
    EXPECT_EQ(fb.id(0, 0), 0);
    EXPECT_EQ(fb.id(1, 0), 0);
    EXPECT_EQ(fb.id(0, 1), 1);
}

// A flat triangle at z = DBL_MAX: its depth is finite, but its depth plus the plane's error bound is not,
// so the filtered test cannot place it before an empty slot. The slot takes it all the same, and an equal
// triangle behind it loses the tie.
TEST_P(Depth, DepthAtTheLargestDoubleIsWritten) {
    Scene scene;
    scene.viewport = {4, 4};
    const double top = std::numeric_limits<double>::max();
    const Triangle t = tri(0, 0, 8, 0, 0, 8, top);
    scene.triangles = {t, t};
    const Framebuffer fb = render(scene, {GetParam(), 1});
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            EXPECT_EQ(fb.id(i, j), 0);
            EXPECT_EQ(fb.depth[fb.index(i, j)], top);
        }
}

INSTANTIATE_TEST_SUITE_P(AllModes, Depth, ::testing::ValuesIn(testing::kAllPrecisions),
                         [](const auto& info) { return std::string(name(info.param)); });

}  // namespace
}  // namespace rast::fast
