// Traversal: the row runs found by searching from the row before against brute-force inside() on every
// sample, what that search costs, and
// multisample counts worked out by hand from the sample tables.
#include "pixel_box.h"
#include "scenes.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <limits>
#include <random>
#include <vector>

namespace rast::reference {
namespace {

using testing::flat;
using testing::reversed;

// Pixel k's closed square [k, k + 1] meets [lo, hi] iff ceil(lo) - 1 <= k <= floor(hi), clamped to
// [0, n - 1] for any finite double.
TEST(Traversal, BoundingBoxClampedToTheViewport) {
    using detail::clamped_span;
    const double d = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(clamped_span(3, 3, 8), std::pair(2, 3));          // x = 3 is on pixels 2 and 3
    EXPECT_EQ(clamped_span(2.5, 4.25, 8), std::pair(2, 4));
    EXPECT_EQ(clamped_span(-DBL_MAX, DBL_MAX, 8), std::pair(0, 7));
    EXPECT_EQ(clamped_span(-std::ldexp(1.0, 60), 0.5, 8), std::pair(0, 0));
    EXPECT_EQ(clamped_span(d, d, 8), std::pair(0, 0));
    EXPECT_EQ(clamped_span(-d, -d, 8), std::pair(0, -1));      // left of the viewport
    EXPECT_EQ(clamped_span(8, DBL_MAX, 8), std::pair(7, 7));    // pixel 7 reaches x = 8
    EXPECT_EQ(clamped_span(8.5, DBL_MAX, 8), std::pair(0, -1));
    EXPECT_EQ(clamped_span(std::ldexp(1.0, 60), std::ldexp(1.0, 61), 8), std::pair(0, -1));
}

std::vector<std::size_t> brute_force(const Triangle& t, Viewport vp, int samples) {
    const auto pattern = sample_pattern(samples);
    std::vector<std::size_t> indices;
    std::size_t index = 0;
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i)
            for (const SamplePoint& p : pattern) {
                if (covers(t, i + p.x, j + p.y)) indices.push_back(index);
                ++index;
            }
    return indices;
}

// Vertices on a 1/16 grid (so that edges run through samples and vertices sit on them), anywhere, or
// two of them close together (needles); some triangles reach outside the viewport.
Triangle random_triangle(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> anywhere(-6, 22);
    std::uniform_int_distribution<int> grid(-6 * 16, 22 * 16);
    std::uniform_int_distribution<int> kind(0, 2);
    const auto coordinate = [&](bool on_grid) { return on_grid ? grid(rng) / 16.0 : anywhere(rng); };
    const bool on_grid = kind(rng) != 1;
    Triangle t = flat(coordinate(on_grid), coordinate(on_grid), coordinate(on_grid), coordinate(on_grid),
                      coordinate(on_grid), coordinate(on_grid));
    if (kind(rng) == 0) {
        t.v[2].x = t.v[1].x + (on_grid ? 1 / 16.0 : 1e-3);
        t.v[2].y = t.v[1].y - (on_grid ? 2 / 16.0 : 2e-3);
    }
    return t;
}

TEST(Traversal, MatchesBruteForceOnEverySample) {
    const Viewport vp{16, 12};
    std::mt19937_64 rng(20240531);
    for (const int samples : {1, 4, 8, 16}) {
        for (int n = 0; n < 150; ++n) {
            const Triangle t = random_triangle(rng);
            const auto expected = brute_force(t, vp, samples);
            EXPECT_EQ(covered_samples(t, vp, samples), expected)
                << "samples " << samples << ", triangle (" << t.v[0].x << ", " << t.v[0].y << ") ("
                << t.v[1].x << ", " << t.v[1].y << ") (" << t.v[2].x << ", " << t.v[2].y << ")";
            EXPECT_EQ(covered_samples(reversed(t), vp, samples), expected);
        }
    }
}

// A triangle over the whole 512 x 512 viewport: each row's search costs at most 10 predicate calls per
// left or right edge (512 columns), 1 per horizontal edge, plus 1 for the triangle's orientation: far
// fewer than one call per sample.
TEST(Traversal, LargeTrianglesCostLogarithmicPredicateCallsPerRow) {
    Stats stats;
    render(Scene{Viewport{512, 512}, 1, {flat(-1e6, -1e6, 1e6, -1e6, 0, 1e6)}}, &stats);
    EXPECT_EQ(stats.samples_covered, 512u * 512u);
    EXPECT_LE(stats.orientation_tests, 1u + 512u * 3u * 10u);
}

// Two steep edges through all 512 rows, their ends moving less than a column from row to row, and a
// horizontal one below the viewport. Searched from the row before, an end costs 2 or 3 predicate calls
// (the guess and its neighbours) where bisecting the ~300 columns between the edges would cost 8 or 9;
// the first row, searched from the middle of the box, may take 20 per edge.
TEST(Traversal, SteepEdgesCostAFewPredicateCallsPerRow) {
    Stats stats;
    render(Scene{Viewport{512, 512}, 1, {flat(100.3, -1, 400.2, -1, 250.1, 5000)}}, &stats);
    EXPECT_GT(stats.samples_covered, 512u * 250u);
    EXPECT_LE(stats.orientation_tests, 1u + 512u * (1u + 2u * 3u) + 40u);
}

// Pixel (1, 1) of a 3x3 viewport is framebuffer indices 4n .. 4n + n - 1 for n samples.
std::vector<std::size_t> pixel_1_1(int samples, std::initializer_list<int> sample_ids) {
    std::vector<std::size_t> indices;
    for (const int s : sample_ids) indices.push_back(static_cast<std::size_t>(4 * samples + s));
    return indices;
}

// The half pixel x + y < 3 of pixel (1, 1): its sample offsets (sx, sy) with sx + sy < 1 (the hypotenuse
// is a right edge, its left leg x = 1 a left edge: sample 12 of 16, at offset (0, 1/2), is on it).
// The other half (hypotenuse now a left edge) takes the rest, including 16-sample 0 at (9/16, 7/16).
TEST(Multisample, HalfPixelTrianglesCountedFromTheSampleTables) {
    const Viewport vp{3, 3};
    const Triangle lower = flat(1, 1, 2, 1, 1, 2);
    const Triangle upper = flat(2, 1, 2, 2, 1, 2);
    EXPECT_EQ(covered_samples(lower, vp, 1), std::vector<std::size_t>{});  // centre on the hypotenuse
    EXPECT_EQ(covered_samples(upper, vp, 1), pixel_1_1(1, {0}));
    EXPECT_EQ(covered_samples(lower, vp, 4), pixel_1_1(4, {2, 3}));
    EXPECT_EQ(covered_samples(upper, vp, 4), pixel_1_1(4, {0, 1}));
    EXPECT_EQ(covered_samples(lower, vp, 8), pixel_1_1(8, {1, 4, 5, 6}));
    EXPECT_EQ(covered_samples(upper, vp, 8), pixel_1_1(8, {0, 2, 3, 7}));
    EXPECT_EQ(covered_samples(lower, vp, 16), pixel_1_1(16, {2, 4, 5, 8, 11, 12, 14}));
    EXPECT_EQ(covered_samples(upper, vp, 16), pixel_1_1(16, {0, 1, 3, 6, 7, 9, 10, 13, 15}));
}

// The left and right halves of pixel (1, 1), split at x = 1.5: the split is the left half's right edge
// and the right half's left edge, so the 16-sample 9 at offset x = 1/2 goes right. The pixel's own top
// side is covered (16-sample 15 at offset y = 1), its bottom and right sides are not.
TEST(Multisample, HalfPixelRectanglesCountedFromTheSampleTables) {
    const Viewport vp{3, 3};
    const auto count = [&](double x0, double x1, int samples) {
        return covered_samples(flat(x0, 1, x1, 1, x1, 2), vp, samples).size() +
               covered_samples(flat(x0, 1, x1, 2, x0, 2), vp, samples).size();
    };
    EXPECT_EQ(count(1, 1.5, 1), 0u);
    EXPECT_EQ(count(1.5, 2, 1), 1u);
    EXPECT_EQ(count(1, 1.5, 4), 2u);
    EXPECT_EQ(count(1.5, 2, 4), 2u);
    EXPECT_EQ(count(1, 1.5, 8), 4u);
    EXPECT_EQ(count(1.5, 2, 8), 4u);
    EXPECT_EQ(count(1, 1.5, 16), 8u);
    EXPECT_EQ(count(1.5, 2, 16), 8u);
    EXPECT_EQ(count(1, 2, 16), 16u);
}

}  // namespace
}  // namespace rast::reference

namespace rast::reference {
namespace {

// The calls a Progress heard.
struct Heard {
    std::vector<std::pair<std::size_t, std::size_t>> calls;
    Progress progress() {
        return [this](std::size_t done, std::size_t total) { calls.emplace_back(done, total); };
    }
};

// 600 triangles, half of them degenerate (they draw nothing but still count as done).
Scene six_hundred_triangles() {
    Scene s{Viewport{8, 8}, 1, {}};
    for (int k = 0; k < 600; ++k)
        s.triangles.push_back(k % 2 ? testing::flat(0, 0, 8, 0, 0, 8) : testing::flat(0, 0, 1, 1, 2, 2));
    return s;
}

TEST(Progress, RenderReportsTheStartEveryStretchAndTheEnd) {
    Heard heard;
    render(six_hundred_triangles(), nullptr, heard.progress());
    using Calls = decltype(heard.calls);
    EXPECT_EQ(heard.calls, (Calls{{0, 600}, {256, 600}, {512, 600}, {600, 600}}));
}

TEST(Progress, CoverageAreaReportsTheStartEveryStretchAndTheEnd) {
    Heard heard;
    coverage_area(six_hundred_triangles(), heard.progress());
    using Calls = decltype(heard.calls);
    EXPECT_EQ(heard.calls, (Calls{{0, 600}, {256, 600}, {512, 600}, {600, 600}}));
}

}  // namespace
}  // namespace rast::reference
