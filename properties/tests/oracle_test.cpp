// The exact geometry the properties judge by, and the property library's own logic, on cases worked
// out by hand.
#include <rast/exact_geometry.h>
#include <rast/properties.h>
#include <rast/visible_oracle.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using namespace rast::properties;
using rast::reference_engine;
using rast::Scene;
using rast::Triangle;
using rast::Vertex;

Triangle tri(double x0, double y0, double x1, double y1, double x2, double y2) {
    return {{Vertex{x0, y0, 0}, Vertex{x1, y1, 0}, Vertex{x2, y2, 0}}};
}

const Triangle kLowerLeft = tri(0, 0, 4, 0, 0, 4);  // counter-clockwise
const Triangle kUpperLeft = tri(0, 0, 4, 4, 0, 4);  // counter-clockwise, with a top edge

TEST(ExactGeometry, EdgeSignIsLeftPositive) {
    EXPECT_EQ(edge_sign({0, 0, 0}, {4, 0, 0}, 1, 1), 1);
    EXPECT_EQ(edge_sign({0, 0, 0}, {4, 0, 0}, 1, -1), -1);
    EXPECT_EQ(edge_sign({0, 0, 0}, {4, 0, 0}, 2, 0), 0);
}

TEST(ExactGeometry, EdgeSignDecidesNearDegenerateCasesExactly) {
    // p is one ulp right of the line y = x through a and b: (b - a) x (p - a) = -ulp < 0.
    EXPECT_EQ(edge_sign({0.5, 0.5, 0}, {12, 12, 0}, std::nextafter(0.5, 1.0), 0.5), -1);
    EXPECT_EQ(edge_sign({0.5, 0.5, 0}, {12, 12, 0}, 24, 24), 0);
    // Subnormal and huge coordinates, where the double filter cannot be trusted.
    const double tiny = 4.9406564584124654e-324;
    EXPECT_EQ(edge_sign({0, 0, 0}, {tiny, 0, 0}, 0, tiny), 1);
    EXPECT_EQ(edge_sign({-0x1p60, 0, 0}, {0x1p60, 1, 0}, 0, 0.5), 0);
    EXPECT_EQ(edge_sign({-0x1p60, 0, 0}, {0x1p60, 1, 0}, 0, 0.25), -1);
}

TEST(ExactGeometry, LocateClassifiesClosedTriangle) {
    EXPECT_EQ(locate(kLowerLeft, 1, 1), Location::inside);
    EXPECT_EQ(locate(kLowerLeft, 2, 0), Location::on_edge);
    EXPECT_EQ(locate(kLowerLeft, 0, 0), Location::on_vertex);
    EXPECT_EQ(locate(kLowerLeft, 3, 3), Location::outside);
    const Triangle clockwise{{kLowerLeft.v[0], kLowerLeft.v[2], kLowerLeft.v[1]}};
    EXPECT_EQ(locate(clockwise, 1, 1), Location::inside);
    EXPECT_EQ(locate(clockwise, 2, 2), Location::on_edge);
    EXPECT_EQ(locate(tri(0, 0, 1, 1, 2, 2), 1, 1), Location::outside);
}

TEST(ExactGeometry, RuleCoversLeftAndTopEdgesOnly) {
    // kLowerLeft: bottom edge (0,0)->(4,0), right edge (4,0)->(0,4), left edge (0,4)->(0,0).
    EXPECT_TRUE(rule_covers(kLowerLeft, 1, 1));
    EXPECT_FALSE(rule_covers(kLowerLeft, 2, 0));  // bottom
    EXPECT_FALSE(rule_covers(kLowerLeft, 2, 2));  // right
    EXPECT_TRUE(rule_covers(kLowerLeft, 0, 2));   // left
    EXPECT_FALSE(rule_covers(kLowerLeft, 0, 0));  // left and bottom meet
    EXPECT_FALSE(rule_covers(kLowerLeft, 0, 4));  // left and right meet
    // kUpperLeft: right edge (0,0)->(4,4), top edge (4,4)->(0,4), left edge (0,4)->(0,0).
    EXPECT_TRUE(rule_covers(kUpperLeft, 2, 4));   // top
    EXPECT_TRUE(rule_covers(kUpperLeft, 0, 4));   // top and left meet
    EXPECT_FALSE(rule_covers(kUpperLeft, 4, 4));  // top and right meet
    // Winding does not matter; zero area covers nothing.
    EXPECT_TRUE(rule_covers(Triangle{{kUpperLeft.v[0], kUpperLeft.v[2], kUpperLeft.v[1]}}, 2, 4));
    EXPECT_FALSE(rule_covers(tri(0, 0, 2, 2, 4, 4), 2, 2));
}

TEST(ExactGeometry, AreaAndSnapping) {
    EXPECT_EQ(twice_area(kLowerLeft), 16);
    EXPECT_EQ(twice_area(Triangle{{kLowerLeft.v[0], kLowerLeft.v[2], kLowerLeft.v[1]}}), 16);
    EXPECT_EQ(snap(3.0 / 32, 4), 0.125);    // 1.5 sixteenths: ties to even, up
    EXPECT_EQ(snap(5.0 / 32, 4), 0.125);    // 2.5 sixteenths: ties to even, down
    EXPECT_EQ(snap(-3.0 / 32, 4), -0.125);  // symmetric about zero
    EXPECT_EQ(snap(0.3, 1), 0.5);
    EXPECT_EQ(snap(0x1p60 + 0x1p8, 16), 0x1p60 + 0x1p8);
    // Already on every grid, and far too large to scale by 2^bits without overflowing.
    EXPECT_EQ(snap(std::numeric_limits<double>::max(), 16), std::numeric_limits<double>::max());
    EXPECT_EQ(snap(-0x1.fd16781507b56p+1020, 16), -0x1.fd16781507b56p+1020);
}

// The square [0, 4]^2 cut along its diagonal: every pixel centre is inside exactly one half.
const Scene kSplitSquare{{4, 4}, 1, {tri(0, 0, 4, 0, 4, 4), tri(0, 0, 4, 4, 0, 4)}};

TEST(PropertyLibrary, SplitSquarePassesOnEveryEngine) {
    const std::vector<std::string> all{"watertight", "tie_rule", "winding_invariance", "translation_invariance",
                                       "order_independence", "fixed_matches_reference", "float_within_bound",
                                       "msaa_counts", "area_tiling"};
    EXPECT_TRUE(check_case(kSplitSquare, all).empty());
}

TEST(PropertyLibrary, WatertightFindsAHoleAndADoubleCover) {
    Engine holed = reference_engine();
    const auto covers = holed.covered_samples;
    holed.covered_samples = [covers](const Triangle& t, rast::Viewport vp, int n) {
        return t == kSplitSquare.triangles[1] ? std::vector<std::size_t>{} : covers(t, vp, n);
    };
    const Outcome hole = property("watertight").check(kSplitSquare, holed);
    ASSERT_TRUE(hole.failed());
    // Pixel (0, 1), centre (0.5, 1.5), is the first sample inside the upper half and on no boundary.
    EXPECT_NE(hole.detail.find("pixel (0, 1) sample 0"), std::string::npos) << hole.detail;
    EXPECT_NE(hole.detail.find("by no triangle"), std::string::npos) << hole.detail;

    const Scene doubled{{4, 4}, 1, {kSplitSquare.triangles[0], kSplitSquare.triangles[0]}};
    const auto failures = check_case(doubled, std::vector<std::string>{"watertight"});
    ASSERT_EQ(failures.size(), 4u);  // the reference and the three fixed modes; float modes are not bound
    for (const auto& f : failures) EXPECT_NE(f.detail.find("twice"), std::string::npos) << f.detail;
}

TEST(PropertyLibrary, TranslationNeedsExactShifts) {
    // 2^53 + 2 plus 1, 5 or 67 is odd, beyond double's integers: every shift rounds a coordinate.
    const double big = 0x1p53 + 2;
    const Scene far{{4, 4}, 1, {tri(big, big, 0, 0, 4, 0)}};
    EXPECT_EQ(property("translation_invariance").check(far, reference_engine()).verdict,
              Outcome::Verdict::not_applicable);
}

TEST(PropertyLibrary, UnknownPropertyIsAnError) {
    EXPECT_THROW(property("watertite"), std::invalid_argument);
    EXPECT_THROW(check_case(kSplitSquare, std::vector<std::string>{"tie_rule", "nope"}), std::invalid_argument);
}

// The judge of the visible area on the reference's hand cases: z = x and z = y / 2 meet along x = y / 2,
// the first nearer left of it. That line runs from (0, 0) to (1/2, 1): of the 2 x 2 cells it meets both
// left ones and touches the top right one at its corner; the triangles' edges are far outside.
TEST(VisibleOracle, CrossingPlanesBySlabs) {
    const auto on = [](double a, double b) {
        Triangle t{{Vertex{-4, -4, 0}, Vertex{8, -4, 0}, Vertex{-4, 8, 0}}};
        for (Vertex& v : t.v) v.z = a * v.x + b * v.y;
        return t;
    };
    const Scene s{{1, 1}, 1, {on(1, 0), on(0, 0.5)}};
    const SlabPixel p = visible_by_slabs(s, 0, 0);
    EXPECT_EQ(p.visible, (std::vector<std::pair<std::size_t, Rational>>{{0, Rational(1, 4)}, {1, Rational(3, 4)}}));
    EXPECT_EQ(p.covered, 1);
    EXPECT_EQ(cells_met_by_boundaries(s, 0, 0, 2, 2), 3);
    EXPECT_EQ(cells_met_by_boundaries(s, 0, 0, 1, 1), 1);
    EXPECT_FALSE(front_cover(s, 0, 0));  // each is nearer somewhere
    // z = y / 4 is nearer wherever y > 0; the tie along y = 0 has no area.
    const Scene behind{{1, 1}, 1, {on(0, 0.5), on(0, 0.25)}};
    EXPECT_EQ(front_cover(behind, 0, 0), std::optional<std::size_t>(1));
}

// A half-pixel triangle over a larger one at equal depth, the lower id first: the overlap is the lower
// id's; the edge x + y = 1 meets 3 of the 2 x 2 cells (through the centre, touching the corner two).
TEST(VisibleOracle, CoplanarOverlapAndItsEdge) {
    const Scene s{{1, 1}, 1, {tri(0, 0, 1, 0, 0, 1), tri(-4, -4, 8, -4, -4, 8)}};
    EXPECT_EQ(visible_by_slabs(s, 0, 0).visible,
              (std::vector<std::pair<std::size_t, Rational>>{{0, Rational(1, 2)}, {1, Rational(1, 2)}}));
    EXPECT_EQ(cells_met_by_boundaries(s, 0, 0, 2, 2), 4);
}

// The cell grid gives every sample of each pattern a closed cell of its own: a perfect matching of
// samples to the cells that hold them exists (found by augmenting paths).
TEST(VisibleOracle, EverySampleHasACellOfItsOwn) {
    for (const int n : {1, 4, 8, 16}) {
        const auto [columns, rows] = sample_cells(n);
        ASSERT_EQ(columns * rows, n);
        const auto pattern = rast::sample_pattern(n);
        const auto holds = [&](int cell, int s) {
            const double x = pattern[s].x * columns, y = pattern[s].y * rows;
            const int c = cell % columns, r = cell / columns;
            return c <= x && x <= c + 1 && r <= y && y <= r + 1;
        };
        std::vector<int> sample_in(static_cast<std::size_t>(n), -1);  // cell -> its sample
        std::function<bool(int, std::vector<bool>&)> place = [&](int s, std::vector<bool>& seen) {
            for (int cell = 0; cell < n; ++cell) {
                if (!holds(cell, s) || seen[cell]) continue;
                seen[cell] = true;
                if (sample_in[cell] < 0 || place(sample_in[cell], seen)) {
                    sample_in[cell] = s;
                    return true;
                }
            }
            return false;
        };
        for (int s = 0; s < n; ++s) {
            std::vector<bool> seen(static_cast<std::size_t>(n));
            EXPECT_TRUE(place(s, seen)) << n << " samples: sample " << s << " finds no cell of its own";
        }
    }
    EXPECT_THROW(sample_cells(2), std::invalid_argument);
}

}  // namespace
