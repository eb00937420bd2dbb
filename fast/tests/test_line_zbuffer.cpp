// Lines in the fast path's z-buffer, in every precision, worked out by hand (the reference's own tests
// hold the same cases: fast_tests does not link the reference): lit pixels against triangles and other
// lines in the (z, id) order, ties in file order, a lit pixel's samples at one depth, a tie only exact
// arithmetic settles, and bad lines refused before the framebuffer is touched.
#include <rast/fast.h>

#include <rast/testing/line_scenes.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace rast::fast {
namespace {

constexpr Precision kAll[] = {Precision::fixed4, Precision::fixed8, Precision::fixed16, Precision::float32,
                              Precision::float64};

using rast::testing::backdrop;
using rast::testing::row;
using rast::testing::segment;

TEST(LineZBuffer, NearerWinsAgainstATriangle) {
    for (const Precision p : kAll) {
        Scene scene{{5, 3}, 1, {backdrop(0, 0, 0.5)}};
        append_line(scene, segment({0.5, 1.5, 0.25}, {3.5, 1.5, 0.25}));
        Framebuffer fb = render(scene, {p});
        EXPECT_EQ(row(fb, 1), (std::vector<std::int32_t>{1, 1, 1, 0, 0})) << name(p);
        EXPECT_EQ(row(fb, 0), (std::vector<std::int32_t>{0, 0, 0, 0, 0})) << name(p);
        EXPECT_EQ(fb.depth[fb.index(1, 1)], 0.25) << name(p);
        scene.lines[0].segment.v[0].z = scene.lines[0].segment.v[1].z = 0.75;
        EXPECT_EQ(row(render(scene, {p}), 1), (std::vector<std::int32_t>{0, 0, 0, 0, 0})) << name(p);
    }
}

// Equal depths everywhere along the line: z = x / 8 on the row y = 1/2, as the triangle's plane. The
// bounds cannot order them; exact arithmetic finds the tie, which the lower id wins.
TEST(LineZBuffer, TiesGoToTheLowerIdInFileOrder) {
    for (const Precision p : kAll) {
        Scene first{{4, 1}, 1, {backdrop(0.125, 0, 0)}, {}};
        first.lines.push_back({segment({0.5, 0.5, 0.0625}, {3.5, 0.5, 0.4375}), 0});
        EXPECT_EQ(row(render(first, {p}), 0), (std::vector<std::int32_t>{0, 0, 0, 1})) << name(p);
        Scene after = first;
        after.lines[0].id = 1;
        EXPECT_EQ(row(render(after, {p}), 0), (std::vector<std::int32_t>{0, 0, 0, 0})) << name(p);
    }
}

// Four samples: the triangle z = x has x = 2.375, 2.875, 2.125, 2.625 at pixel (2, 0)'s samples, and
// the line z = 2.5 at that pixel's centre, so the line takes samples 1 and 3.
TEST(LineZBuffer, EverySampleOfALitPixelTakesTheCentresDepth) {
    for (const Precision p : kAll) {
        Scene scene{{4, 1}, 4, {backdrop(1, 0, 0)}};
        append_line(scene, segment({0.5, 0.5, 0.5}, {3.5, 0.5, 3.5}));
        const Framebuffer fb = render(scene, {p});
        EXPECT_EQ(fb.id(2, 0, 0), 0) << name(p);
        EXPECT_EQ(fb.id(2, 0, 1), 1) << name(p);
        EXPECT_EQ(fb.id(2, 0, 2), 0) << name(p);
        EXPECT_EQ(fb.id(2, 0, 3), 1) << name(p);
        EXPECT_EQ(fb.depth[fb.index(2, 0, 1)], 2.5) << name(p);
    }
}

// Crossing lines equal at (2.5, 2.5), z = 1 for each: the lower id there, the nearer elsewhere.
TEST(LineZBuffer, LinesOrderAmongThemselves) {
    for (const Precision p : kAll) {
        Scene scene{{5, 5}, 1, {}};
        append_line(scene, segment({0.5, 2.5, 2}, {4.5, 2.5, 0}));
        append_line(scene, segment({2.5, 0.5, 0}, {2.5, 4.5, 2}));
        const Framebuffer fb = render(scene, {p});
        EXPECT_EQ(fb.id(2, 2), 0) << name(p);
        EXPECT_EQ(fb.id(1, 2), 0) << name(p);
        EXPECT_EQ(fb.id(2, 1), 1) << name(p);
        Scene swapped{{5, 5}, 1, {}};
        append_line(swapped, scene.lines[1].segment);
        append_line(swapped, scene.lines[0].segment);
        EXPECT_EQ(render(swapped, {p}).id(2, 2), 0) << name(p);
    }
}

// One ulp apart: the line at 1 + 2^-52 behind the triangle at 1, then at 1 - 2^-53 in front of it. The
// gap is within the two depths' bounds (each about u), so exact arithmetic orders them, not the ids.
TEST(LineZBuffer, OneUlpApartIsNotATie) {
    for (const Precision p : kAll) {
        for (const double z : {1 + 0x1p-52, 1 - 0x1p-53}) {
            Scene scene{{4, 1}, 1, {}};
            append_line(scene, segment({0.5, 0.5, z}, {3.5, 0.5, z}));
            scene.triangles.push_back(backdrop(0, 0, 1));
            const std::int32_t line = z < 1 ? 0 : 1;
            EXPECT_EQ(row(render(scene, {p}), 0), (std::vector<std::int32_t>{line, line, line, 1})) << name(p) << " " << z;
        }
    }
}

TEST(LineZBuffer, RefusesBadLinesBeforeTouchingTheFramebuffer) {
    Scene scene{{4, 4}, 1, {backdrop(0, 0, 0)}};
    append_line(scene, segment({0, 0, 0}, {1, std::numeric_limits<double>::quiet_NaN(), 0}));
    Framebuffer fb(scene.viewport, 1);
    fb.ids[0] = 7;
    EXPECT_THROW(render(scene, fb), std::invalid_argument);
    scene.lines[0] = {segment({0, 0, 0}, {1, 1, 0}), 5};
    EXPECT_THROW(render(scene, fb), std::invalid_argument);
    EXPECT_EQ(fb.ids[0], 7);
}

}  // namespace
}  // namespace rast::fast
