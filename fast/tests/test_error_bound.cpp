// The float modes' stated error bound, checked against exact rational edge functions (GMP): wherever a
// float mode classifies a sample differently from the exact rule, some edge must be within the bound.
#include "pixels.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>

#include <cfloat>
#include <cmath>
#include <random>
#include <set>

namespace rast::fast {
namespace {

using testing::tri;

mpq_class edge(const Vertex& a, const Vertex& b, double px, double py) {
    return (mpq_class(b.x) - a.x) * (mpq_class(py) - a.y) - (mpq_class(b.y) - a.y) * (mpq_class(px) - a.x);
}

// docs/design.md's rule, exactly: counter-clockwise order, left and top edges own their samples.
bool exact_covers(Triangle t, double px, double py) {
    const int orient = sgn(edge(t.v[0], t.v[1], t.v[2].x, t.v[2].y));
    if (orient == 0) return false;
    if (orient < 0) std::swap(t.v[1], t.v[2]);
    for (int k = 0; k < 3; ++k) {
        const Vertex& a = t.v[k];
        const Vertex& b = t.v[(k + 1) % 3];
        const int s = sgn(edge(a, b, px, py));
        const bool owns = b.y < a.y || (b.y == a.y && b.x < a.x);
        if (s < 0 || (s == 0 && !owns)) return false;
    }
    return true;
}

double min_edge_distance(const Triangle& t, double px, double py) {
    double least = INFINITY;
    for (int k = 0; k < 3; ++k) least = std::min(least, std::abs(edge(t.v[k], t.v[(k + 1) % 3], px, py).get_d()));
    return least;
}

// Calls visit(i, j, px, py, wrong) for every pixel centre of the viewport, `wrong` when the float mode
// classifies it unlike the exact rule; returns how many it got wrong.
template <class Visit>
long for_each_sample(const Triangle& t, Viewport vp, Precision p, Visit visit) {
    const std::vector<std::size_t> fast = covered_samples(t, vp, 1, p);
    const std::set<std::size_t> covered(fast.begin(), fast.end());
    long wrong = 0;
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            const double px = i + 0.5, py = j + 0.5;
            const bool ours = covered.count(static_cast<std::size_t>(j) * vp.width + i) != 0;
            const bool differs = ours != exact_covers(t, px, py);
            wrong += differs;
            visit(i, j, px, py, differs);
        }
    return wrong;
}

// Counts the samples a float mode gets wrong, and checks each against the bound.
long check(const Triangle& t, Viewport vp, Precision p) {
    const double bound = edge_error_bound(t, p, vp);
    return for_each_sample(t, vp, p, [&](int i, int j, double px, double py, bool wrong) {
        if (!wrong) return;
        EXPECT_LE(min_edge_distance(t, px, py), bound) << name(p) << " sample " << i << "," << j;
    });
}

// Thin needles crossing the viewport with their vertices far away (large edge functions, cancellation
// in every difference), and edges through a line of sample positions moved off it by far less than a
// float32 ulp, so that rounding the inputs decides which side the samples fall on.
std::vector<Triangle> hard_cases() {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Triangle> out;
    for (int k = 0; k < 40; ++k) {
        const double x1 = 2 + std::floor(8 * unit(rng)) + 0.5, y1 = 2 + std::floor(8 * unit(rng)) + 0.5;
        const double dx = 1 + std::floor(4 * unit(rng)), dy = std::floor(9 * unit(rng)) - 4;
        const double reach = k % 2 ? 3 : 0x1p12, shift = (unit(rng) - 0.5) * 1e-9;
        const double nx = -dy * shift, ny = dx * shift;  // off the line, along its normal
        out.push_back(tri(x1 - reach * dx + nx, y1 - reach * dy + ny, x1 + reach * dx + nx,
                          y1 + reach * dy + ny, x1 + 2 * dx - 3 * dy, y1 + 2 * dy + 3 * dx));
    }
    for (const double reach : {0x1p10, 0x1p20, 0x1p26, 0x1p34})
        for (int k = 0; k < 12; ++k) {
            const double y = 8 + 16 * unit(rng), slope = (unit(rng) - 0.5) * 16 / reach;
            const double width = unit(rng) * (k % 2 ? 1e-3 : 2);
            out.push_back(tri(-reach, y - reach * slope, reach, y + reach * slope + width,
                              reach * (unit(rng) - 0.5), y + width * unit(rng) + slope * unit(rng)));
        }
    return out;
}

// Per sample and edge: each sample a float mode gets wrong has some edge within its bound there, and
// no sample's bound exceeds the viewport's. Counts the samples it gets wrong.
long check_at(const Triangle& t, Viewport vp, Precision p) {
    const double viewport_bound = edge_error_bound(t, p, vp);
    return for_each_sample(t, vp, p, [&](int i, int j, double px, double py, bool wrong) {
        const std::array<double, 3> bound = edge_error_bound_at(t, p, px, py);
        for (const double b : bound) EXPECT_LE(b, viewport_bound) << name(p) << " sample " << i << "," << j;
        if (!wrong) return;
        bool near = false;
        for (int k = 0; k < 3; ++k) near = near || abs(edge(t.v[k], t.v[(k + 1) % 3], px, py)) <= bound[k];
        EXPECT_TRUE(near) << name(p) << " sample " << i << "," << j;
    });
}

// An edge from a pixel centre along a line of pixel centres to a vertex 2^20 pixels away, nudged a few
// ulps off the line: the samples on it have tiny nonzero edge functions, and the bound near the edge's
// start is far below the viewport's.
std::vector<Triangle> nudged_lines() {
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int> pick(0, 1 << 20);
    std::vector<Triangle> out;
    for (int k = 0; k < 40; ++k) {
        const double ax = 8 + pick(rng) % 16 + 0.5, ay = 8 + pick(rng) % 16 + 0.5;
        const double dx = 1 + pick(rng) % 3, dy = pick(rng) % 3 - 1, m = (k % 2 ? 1 : -1) * 0x1p20;
        double by = ay + m * dy;
        for (int n = pick(rng) % 64; n > 0; --n) by = std::nextafter(by, k % 4 < 2 ? INFINITY : -INFINITY);
        const double cx = pick(rng) % 32 + 0.25, cy = pick(rng) % 32 + 0.75;
        out.push_back(k % 3 ? tri(ax + m * dx, by, ax, ay, cx, cy) : tri(ax + m * dx, by, cx, cy, ax, ay));
    }
    return out;
}

TEST(ErrorBoundAt, HoldsOnHardCases) {
    const Viewport vp{32, 32};
    long wrong32 = 0, wrong64 = 0;
    for (const auto& cases : {hard_cases(), nudged_lines()})
        for (const Triangle& t : cases) {
            wrong32 += check_at(t, vp, Precision::float32);
            wrong64 += check_at(t, vp, Precision::float64);
        }
    EXPECT_GT(wrong32, 0);
    EXPECT_GT(wrong64, 0);
}

// At a vertex that is a sample, the edge evaluated from it has py - ay = px - ax = 0 exactly: only
// underflow terms remain (float64 rounds no input). Which edge that is follows the winding: the
// counter-clockwise order starts the edge between v[0] and v[1] at v[0], the clockwise one at v[1].
TEST(ErrorBoundAt, SmallAtTheStartOfAnEdge) {
    const Triangle ccw = tri(0.5, 0.5, 3.5, 0.5, 0.5, 3.5);
    const Triangle cw = tri(0.5, 0.5, 0.5, 3.5, 3.5, 0.5);
    EXPECT_LT(edge_error_bound_at(ccw, Precision::float64, 0.5, 0.5)[0], 1e-300);
    EXPECT_LT(edge_error_bound_at(cw, Precision::float64, 0.5, 0.5)[2], 1e-300);
    // The edge from (0.5, 3.5) to (0.5, 0.5) evaluated at (0.5, 0.5), 3 pixels from its start.
    EXPECT_GT(edge_error_bound_at(cw, Precision::float64, 0.5, 0.5)[0], 0);
    // 1e39 is beyond float; a fixed mode is exact.
    EXPECT_EQ(edge_error_bound_at(tri(0, 0, 1e39, 0, 0, 1), Precision::float32, 1, 1)[0], INFINITY);
    for (const double b : edge_error_bound_at(ccw, Precision::fixed8, 1, 1)) EXPECT_EQ(b, 0);
}

TEST(ErrorBound, HoldsOnHardCases) {
    const Viewport vp{32, 32};
    long wrong32 = 0, wrong64 = 0;
    for (const Triangle& t : hard_cases()) {
        wrong32 += check(t, vp, Precision::float32);
        wrong64 += check(t, vp, Precision::float64);
    }
    // The cases are hard enough that float32 does misclassify: the bound is what keeps that honest.
    EXPECT_GT(wrong32, 0);
    EXPECT_LT(wrong64, wrong32);
}

TEST(ErrorBound, ExactCasesAndLimits) {
    const Viewport vp{4, 4};
    const Triangle small = tri(0.5, 0.5, 3.5, 0.5, 0.5, 3.5);
    // Small integers and halves: every operation is exact, so no misclassification, and the bound is tiny.
    EXPECT_EQ(check(small, vp, Precision::float32), 0);
    EXPECT_LT(edge_error_bound(small, Precision::float32, vp), 1e-4);
    EXPECT_GT(edge_error_bound(small, Precision::float32, vp), 0);
    EXPECT_LT(edge_error_bound(small, Precision::float64, vp), edge_error_bound(small, Precision::float32, vp));
    EXPECT_EQ(edge_error_bound(small, Precision::fixed8, vp), 0);
    // Float32 cannot hold 1e39; double arithmetic overflows on a DBL_MAX span.
    EXPECT_EQ(edge_error_bound(tri(0, 0, 1e39, 0, 0, 1), Precision::float32, vp), INFINITY);
    EXPECT_EQ(edge_error_bound(tri(-DBL_MAX, 0, DBL_MAX, 0, 0, 1), Precision::float64, vp), INFINITY);
    EXPECT_LT(edge_error_bound(tri(0, 0, 1e39, 0, 0, 1), Precision::float64, vp), INFINITY);
    // Each product of edge 1 at (0.5, 0.5) fits in float32, their difference (3.7e38 exactly) does not: the
    // evaluation gives infinity, so no finite bound holds.
    const Triangle wide = tri(0x1.b7f98b96bd528p+61, 0x1.43197f2f982eap+63, -0x1.aaadf99c69708p+61,
                              0x1.0e51483b80384p+64, -0x1.142e285dcd655p+64, 0x1.d9e2c97d8ea6p+61);
    EXPECT_EQ(edge_error_bound(wide, Precision::float32, {10, 10}), INFINITY);
    EXPECT_EQ(edge_error_bound_at(wide, Precision::float32, 0.5, 0.5)[1], INFINITY);
}

// The bound scales with the magnitudes: a vertex at 2^20 in float32 (ulp 1/8) gives errors of order
// 2^20 * 2^20 * 2^-24 = 2^16 in E; the bound must be at least a fraction of that and not wildly more.
TEST(ErrorBound, ScalesWithMagnitude) {
    const Viewport vp{32, 32};
    const double b = edge_error_bound(tri(-0x1p20, 3, 0x1p20, 5, 0, 0x1p20), Precision::float32, vp);
    EXPECT_GT(b, 0x1p16);
    EXPECT_LT(b, 0x1p24);
}

}  // namespace
}  // namespace rast::fast
