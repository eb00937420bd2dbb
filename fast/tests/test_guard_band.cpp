// Triangles far outside the viewport or beyond the 64-bit fixed-point range: the wide path must give
// exactly the snapped triangle's coverage, never overflow, loop or write out of bounds.
#include "pixels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

namespace rast::fast {
namespace {

using testing::covered_pixels;
using testing::rendered_pixels;
using testing::Pixels;
using testing::tri;

Pixels all_pixels(Viewport vp) {
    Pixels out;
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) out.insert({i, j});
    return out;
}

// Every row's pixels in columns [first, last].
Pixels columns(int first, int last, Viewport vp) {
    Pixels out;
    for (int j = 0; j < vp.height; ++j)
        for (int i = first; i <= last; ++i) out.insert({i, j});
    return out;
}

Pixels columns_from(int first, Viewport vp) { return columns(first, vp.width - 1, vp); }

class GuardBand : public ::testing::TestWithParam<Precision> {};

TEST_P(GuardBand, HugeTriangleCoversTheViewport) {
    const Viewport vp{8, 8};
    for (const double r : {0x1p20, 0x1p40, 0x1p60}) {
        EXPECT_EQ(covered_pixels(tri(-r, -r, 2 * r, -r, -r, 2 * r), vp, GetParam()), all_pixels(vp)) << r;
    }
}

// A vertical left edge x = 2.5 through the centres, its ends and the third vertex far away: the centres
// on it are owned (it runs down, counter-clockwise), so columns 2.. are covered. Exact in every mode:
// (b - a).x = 0 and (p - a).x = 0 on the edge.
TEST_P(GuardBand, FarVerticesKeepTheTieRule) {
    const Viewport vp{8, 4};
    for (const double r : {0x1p20, 0x1p21, 0x1p22, 0x1p40, 0x1p60})
        EXPECT_EQ(covered_pixels(tri(2.5, -r, 2 * r, 0, 2.5, r), vp, GetParam()), columns_from(2, vp)) << r;
}

TEST_P(GuardBand, TinyTrianglesFarOutside) {
    const Viewport vp{8, 8};
    for (const double d : {1e9, 0x1p40, 0x1p60, -0x1p60, 1e300}) {
        const double step = d * 0x1p-50;  // a few ulps: a tiny triangle at that magnitude
        EXPECT_TRUE(covered_pixels(tri(d, d, d + step, d, d, d + step), vp, GetParam()).empty()) << d;
        EXPECT_TRUE(covered_pixels(tri(d, 0.5, d + step, 0.5, d, 0.5 + step), vp, GetParam()).empty()) << d;
    }
}

TEST_P(GuardBand, ExtremeCoordinatesDoNotCrash) {
    Scene scene;
    scene.viewport = {16, 16};
    scene.samples = 4;
    scene.triangles = {tri(-DBL_MAX, -DBL_MAX, DBL_MAX, -DBL_MAX, 0, DBL_MAX),
                       tri(DBL_MAX, DBL_MAX, -DBL_MAX, DBL_MAX, DBL_MAX, -DBL_MAX),
                       tri(-DBL_MAX, 0.5, DBL_MAX, 0.5, 0.5, DBL_MIN)};
    const Framebuffer fb = render(scene, {GetParam(), 2});
    ASSERT_EQ(fb.ids.size(), 16u * 16u * 4u);
    for (std::int32_t id : fb.ids) EXPECT_TRUE(id >= -1 && id <= 2);
}

INSTANTIATE_TEST_SUITE_P(AllModes, GuardBand, ::testing::ValuesIn(testing::kAllPrecisions),
                         [](const auto& info) { return std::string(name(info.param)); });

// In exact arithmetic, a triangle spanning +-DBL_MAX still has an exact coverage: the fixed modes (wide
// path) must find it. The first triangle's bottom edge is far below and its slanted edges pass far
// outside the viewport: every pixel.
TEST(GuardBandFixed, DblMaxTriangleIsExact) {
    const Viewport vp{8, 8};
    for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16}) {
        EXPECT_EQ(covered_pixels(tri(-DBL_MAX, -DBL_MAX, DBL_MAX, -DBL_MAX, 0, DBL_MAX), vp, p), all_pixels(vp));
        // Bottom edge y = 0.5 from -DBL_MAX to DBL_MAX (its centres not owned), apex (0.5, 2.5) on a right
        // edge (not owned): at y = 1.5 the sides are near x = -+DBL_MAX/2, so exactly row 1 is covered.
        const Pixels row1 = covered_pixels(tri(-DBL_MAX, 0.5, DBL_MAX, 0.5, 0.5, 2.5), vp, p);
        Pixels expected;
        for (int i = 0; i < 8; ++i) expected.insert({i, 1});
        EXPECT_EQ(row1, expected);
    }
}

// Both sides of each range give the same answer: within 2^(29-N) pixels the 64-bit path, beyond it the
// wide path; within 2^(60-N) the wide path's 128-bit integers, beyond them its big integers.
TEST(GuardBandFixed, BothSidesOfEachRange) {
    const Viewport vp{8, 4};
    for (const int bits : {4, 8, 16}) {
        const Precision p = bits == 4 ? Precision::fixed4 : bits == 8 ? Precision::fixed8 : Precision::fixed16;
        for (const double limit : {std::ldexp(1.0, 29 - bits), std::ldexp(1.0, 60 - bits)})
            for (const double r : {limit / 2, limit, 2 * limit})
                EXPECT_EQ(covered_pixels(tri(2.5, -r, r, 0, 2.5, r), vp, p), columns_from(2, vp)) << r;
    }
}

// A scene's triangle whose box in the viewport is small takes the compact small-triangle path, where
// edge functions are stepped in 32 bits when they fit at every sample of the triangle's own box (the
// triangle spans less than about 128 pixels at fixed8, 2048 at fixed4). Half-widths on both sides of
// each bound, and far beyond it, where 32 bits would wrap around.
TEST(GuardBandFixed, SmallBoxOfALargeTriangleOnBothSidesOf32BitEdges) {
    const Viewport vp{16, 8};
    for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
        for (const double r : {60.0, 70.0, 1000.0, 1100.0, 0x1p20})
            EXPECT_EQ(rendered_pixels(tri(2.5, -r, r, 0, 2.5, r), vp, p), columns_from(2, vp)) << name(p) << " " << r;
}

// The wide path classifies whole tiles, by its near edges' values at their corners or by its spans'
// extremes per row of tiles, on a viewport of 4 x 3 tiles (the last ones partial), with triangles whose
// other corners are far enough away for the wide path in every fixed mode: near edges at 2^30 pixels,
// none at 2^50, with its 128-bit integers and with big ones. A vertical left edge x = 70.5
// through the centres (owned) covers columns 70.. (as in FarVerticesKeepTheTieRule): the second column
// of tiles is partial, the third and fourth accepted. A vertical right edge x = 129.5 (not owned) covers
// columns ..128: the first two columns of tiles are accepted, the third partial (its box ends at 129).
TEST(GuardBandFixed, WideTrianglesClassifyWholeTiles) {
    const Viewport vp{200, 150};
    for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
        for (const double r : {0x1p30, 0x1p50}) {
            EXPECT_EQ(rendered_pixels(tri(70.5, -r, 2 * r, 0, 70.5, r), vp, p), columns_from(70, vp))
                << name(p) << " " << r;
            EXPECT_EQ(rendered_pixels(tri(129.5, r, -2 * r, 0, 129.5, -r), vp, p), columns(0, 128, vp))
                << name(p) << " " << r;
        }
}

// A wide sliver steeper than a tile is wide: along x = 96 + 100 (y - 32), from row to row its spans
// jump 100 pixels, so in the first row of tiles the second tile lies between them and holds none. The
// band's extremes cannot see that gap (the tile is rasterized as partial): the screen must still get
// exactly the triangle's coverage, found here without tiles (covered_pixels).
TEST(GuardBandFixed, WideSliverSkippingATileKeepsItsCoverage) {
    const Viewport vp{256, 128};
    const double r = 0x1p30;
    for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16}) {
        const Triangle sliver = tri(96 - 100 * r, 32 - r, 96 + 100 * r, 32 + r, 99 + 100 * r, 32 + r);
        const Pixels expected = covered_pixels(sliver, vp, p);
        EXPECT_GE(expected.size(), 2u) << name(p);  // a row above and below the gap, at least
        for (const auto& [i, j] : expected) EXPECT_FALSE(i >= 64 && i < 128 && j < 64) << name(p) << " " << i << "," << j;
        EXPECT_EQ(rendered_pixels(sliver, vp, p), expected) << name(p);
    }
}

// A wide triangle too large for near edges (its sides beyond 2^42 pixels in fixed8: it walks spans), behind
// a big near one that covers the top bands of subtiles of the tile at x = 64: hierarchical z trims those
// rows off the far one's block there, which then starts below the tile's first row, and must read the
// spans of its own rows (456 samples were another row's). Each sample holds the near triangle where it
// covers it, else the far one where that covers it, as each alone covers (covered_samples, no tiles).
TEST(GuardBandFixed, SpansOfAWideTrianglesTrimmedBlockAreItsOwnRows) {
    Scene scene;
    scene.viewport = {128, 64};
    const double r = 0x1p45;
    scene.triangles = {tri(-1000, -10, 1000, -10, 0, 40, 0.1),
                       tri(96 - r / 2, 32 - r, 0x1p46, 32, 96 + r / 2, 32 + r, 0.9)};
    const Framebuffer fb = render(scene, {Precision::fixed8, 1});
    std::vector<std::int32_t> expected(fb.ids.size(), Framebuffer::kNoTriangle);
    for (const std::size_t k : covered_samples(scene.triangles[1], scene.viewport, 1)) expected[k] = 1;
    for (const std::size_t k : covered_samples(scene.triangles[0], scene.viewport, 1)) expected[k] = 0;
    EXPECT_GT(std::count(expected.begin(), expected.end(), 1), 500);  // the far one shows below the near one
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), fb.ids.begin(), fb.ids.end()));
}

}  // namespace
}  // namespace rast::fast
