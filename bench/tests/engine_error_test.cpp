// Differences from the reference, on scenes whose differences are known by hand.
#include "engine_error.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>
#include <limits>

namespace rast::bench {
namespace {

// The fast path in every mode, fixed4 first.
std::vector<Engine> fast_modes() {
    std::vector<Engine> engines = all_engines();
    engines.erase(engines.begin());  // the reference
    return engines;
}

Triangle tri(double x0, double y0, double x1, double y1, double x2, double y2) {
    return Triangle{{Vertex{x0, y0, 0}, Vertex{x1, y1, 0}, Vertex{x2, y2, 0}}};
}

TEST(CompareBuffers, CountsIdsAndDepthBitsSeparately) {
    Framebuffer a({4, 1}, 1), b({4, 1}, 1);
    a.ids = {0, 1, -1, 3};
    b.ids = {0, 2, -1, 4};
    const double inf = std::numeric_limits<double>::infinity();
    a.depth = {0.5, 0.25, inf, 0.75};
    b.depth = {0.5 + 0x1p-10, 0.25, inf, 0.125};
    const BufferDifference d = compare_buffers(a, b);
    EXPECT_EQ(d.ids, 2u);
    EXPECT_EQ(d.depths, 2u);
    // Only pixel 0 holds the same triangle on both sides: the depth gap where ids differ is not an error
    // of depth.
    EXPECT_EQ(d.worst_depth, 0x1p-10);
}

// A vertical left edge at x = 17/32, just right of the centre of pixel (0, 0): the reference leaves that
// centre out. fixed4 snaps 17/32 = 8.5/16 to 8/16 (ties to even): the edge runs through the centre, and
// as a left edge covers it. 17/32 is on the grids of fixed8 and fixed16 and exact in float.
TEST(CompareCoverage, FixedFourSnapsAnEdgeOverACentre) {
    const Scene scene{{2, 1}, 1, {tri(17.0 / 32, -4, 4, 0.5, 17.0 / 32, 4)}};
    const std::vector<Engine> modes = fast_modes();
    const auto d = compare_coverage(scene, modes, true);
    ASSERT_EQ(d.size(), modes.size());
    ASSERT_EQ(modes[0].name, "fixed4");
    EXPECT_EQ(d[0].samples, 1u);
    EXPECT_EQ(d[0].triangles, 1u);
    for (std::size_t m = 1; m < modes.size(); ++m) {
        EXPECT_EQ(d[m].samples, 0u) << modes[m].name;
        EXPECT_EQ(d[m].triangles, 0u) << modes[m].name;
    }
    // Snapped or not, each mode covers what the exact rule gives its own geometry: no violation.
    for (const CoverageDifference& c : d) EXPECT_EQ(c.watertight, 0u);
}

TEST(CompareCoverage, SplitSquareIsWatertightWithBorderSamplesOnce) {
    // A 4 x 4 square split along a diagonal through pixel centres' rows, with 16 samples: every sample of
    // its pixels covered once by exactly one of the two triangles, in every mode (vertices on every grid).
    const Scene scene{{4, 4}, 16, {tri(0, 0, 4, 0, 4, 4), tri(0, 0, 4, 4, 0, 4)}};
    for (const CoverageDifference& c : compare_coverage(scene, fast_modes(), true)) {
        EXPECT_EQ(c.samples, 0u);
        EXPECT_EQ(c.watertight, 0u);
    }
}

TEST(CompareCoverage, WatertightnessOnlyWhenAsked) {
    const Scene scene{{2, 2}, 1, {tri(0, 0, 2, 0, 0, 2)}};
    for (const CoverageDifference& c : compare_coverage(scene, fast_modes(), false)) EXPECT_FALSE(c.watertight);
}

}  // namespace
}  // namespace rast::bench
