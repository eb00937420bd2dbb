// The conformance verdict on hand-computed cases: what each contract demands of a sample, and which
// framebuffers depart from it.
#include <rast/conformance.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace rast::properties {
namespace {

Contract contract(const std::string& text) { return Contract::parse("name=t samples=1,4 " + text); }

Triangle tri(double x0, double y0, double x1, double y1, double x2, double y2, double z = 0.5) {
    return {{Vertex{x0, y0, z}, Vertex{x1, y1, z}, Vertex{x2, y2, z}}};
}

// A 2x2 square split on its rising diagonal, which runs through the centres of pixels (0, 0) and (1, 1).
// Counter-clockwise it is triangle 0's edge (2,2)->(0,0), a left edge, and triangle 1's (0,0)->(2,2), a
// right edge: the tie rule gives both centres to triangle 0.
Scene split_square() { return {{2, 2}, 1, {tri(0, 0, 2, 0, 2, 2), tri(0, 0, 2, 2, 0, 2)}}; }

Framebuffer with_ids(const Scene& scene, const std::vector<std::int32_t>& ids) {
    Framebuffer fb(scene.viewport, scene.samples);
    fb.ids.assign(ids.begin(), ids.end());
    return fb;
}

std::vector<std::string> whats(const std::vector<ConformanceViolation>& violations) {
    std::vector<std::string> out;
    for (const auto& v : violations) out.push_back(v.what);
    return out;
}

const std::string kExact = "snap=none ties=top-left depth=zid";

TEST(Conformance, TheTieRuleDecidesEverySampleOfTheSplitSquare) {
    const Scene s = split_square();
    // Pixels in index order (0,0), (1,0), (0,1), (1,1): the centres on the diagonal and (1, 0) below it
    // are triangle 0's, (0, 1) above it triangle 1's.
    EXPECT_TRUE(conformance_violations(s, contract(kExact), with_ids(s, {0, 0, 1, 0})).empty());
    // Later-wins on the diagonal, as a ">= 0, <=" rasterizer draws it.
    EXPECT_EQ(whats(conformance_violations(s, contract(kExact), with_ids(s, {1, 0, 1, 1}))),
              (std::vector<std::string>{
                  "pixel (0, 0) sample 0 at (0.5, 0.5): forbidden to triangle 1 (outside it under every snapping), "
                  "the engine wrote 1",
                  "pixel (1, 1) sample 0 at (1.5, 1.5): forbidden to triangle 1 (outside it under every snapping), "
                  "the engine wrote 1"}));
    EXPECT_EQ(whats(conformance_violations(s, contract(kExact), with_ids(s, {0, -1, 1, 0}))),
              (std::vector<std::string>{"pixel (1, 0) sample 0 at (1.5, 0.5): required (triangle 0 covers it under "
                                        "the contract), the engine left it empty"}));
}

TEST(Conformance, WithoutTheTieRuleASampleOnAnEdgeIsFree) {
    const Scene s = split_square();
    const Contract loose = contract("snap=none ties=none depth=zid");
    EXPECT_TRUE(conformance_violations(s, loose, with_ids(s, {1, 0, 1, 1})).empty());
    EXPECT_TRUE(conformance_violations(s, loose, with_ids(s, {0, 0, 1, 0})).empty());
    // Free, not required: an edge sample may stay empty, when no other triangle requires it.
    EXPECT_TRUE(conformance_violations(s, loose, with_ids(s, {-1, 0, 1, -1})).empty());
    EXPECT_EQ(coverage_demands(Scene{{2, 2}, 1, {s.triangles[0]}}, loose),
              (std::vector<Demand>{Demand::free, Demand::required, Demand::forbidden, Demand::free}));
    // The off-diagonal pixels stay decided.
    EXPECT_EQ(conformance_violations(s, loose, with_ids(s, {0, 1, 1, 0})).size(), 1u);
}

TEST(Conformance, DepthNoneJudgesCoverageAlone) {
    const Scene s = split_square();
    const Contract coverage_only = contract("snap=none ties=top-left depth=none");
    EXPECT_TRUE(conformance_violations(s, coverage_only, with_ids(s, {1, 1, 0, 1})).empty());
    EXPECT_EQ(conformance_violations(s, coverage_only, with_ids(s, {1, -1, 0, 1})).size(), 1u);
    // Nothing may cover pixel (1, 0) of a scene with triangle 1 alone.
    const Scene upper{{2, 2}, 1, {s.triangles[1]}};
    EXPECT_EQ(whats(conformance_violations(upper, coverage_only, with_ids(upper, {-1, 0, 0, -1}))),
              (std::vector<std::string>{"pixel (1, 0) sample 0 at (1.5, 0.5): forbidden (no triangle may cover it), "
                                        "the engine covered it"}));
}

// A left edge at x = 0.5 + 2^-9, halfway between the snap=8 grid points 0.5 and 0.5 + 2^-8. The centre
// (0.5, 0.5) is on the edge when it snaps down (a left edge: covered) and outside when it snaps up.
Scene halfway_edge() {
    const double x = 0.5 + std::ldexp(1.0, -9);
    return {{2, 1}, 1, {tri(x, -1, 4, -1, x, 4)}};
}

TEST(Conformance, EachRoundingDecidesTheHalfwayEdge) {
    const Scene s = halfway_edge();
    // Nearest, ties to even: 128.5/256 goes to 128/256 = 0.5, the centre is on the left edge.
    EXPECT_EQ(coverage_demands(s, contract("snap=8 rounding=nearest-even ties=top-left depth=zid")),
              (std::vector<Demand>{Demand::required, Demand::required}));
    EXPECT_EQ(coverage_demands(s, contract("snap=8 rounding=floor ties=top-left depth=zid")),
              (std::vector<Demand>{Demand::required, Demand::required}));
    EXPECT_EQ(coverage_demands(s, contract("snap=8 rounding=any ties=top-left depth=zid")),
              (std::vector<Demand>{Demand::free, Demand::required}));
    // Unsnapped, the centre is outside.
    EXPECT_EQ(coverage_demands(s, contract(kExact)), (std::vector<Demand>{Demand::forbidden, Demand::required}));
    // Snapped by 9 bits the edge is on the grid: every rounding keeps it where it is.
    EXPECT_EQ(coverage_demands(s, contract("snap=9 rounding=any ties=top-left depth=zid")),
              (std::vector<Demand>{Demand::forbidden, Demand::required}));
}

TEST(Conformance, ValuesSharedByTwoVerticesSnapAlike) {
    // Two vertices at one point c = (0.5 - 2^-9, 0.5 - 2^-9), halfway between grid points: snapped alike
    // they stay one point, the triangle has no area and covers nothing. Snapped apart, to (0.5 - 2^-8, 0.5)
    // and (0.5, 0.5 - 2^-8), they would make a sliver with the centre (0.5, 0.5) strictly inside it.
    const double c = 0.5 - std::ldexp(1.0, -9);
    const Scene s{{2, 2}, 1, {tri(c, c, c, c, 1.5, 1.5)}};
    EXPECT_EQ(coverage_demands(s, contract("snap=8 rounding=any ties=top-left depth=zid")),
              std::vector<Demand>(4, Demand::forbidden));
    // The sliver itself, given: the centre is required, whichever way its halfway coordinates go.
    const double lo = 0.5 - std::ldexp(1.0, -8);
    const Scene sliver{{2, 2}, 1, {tri(lo, 0.5, 0.5, lo, 1.5, 1.5)}};
    EXPECT_EQ(coverage_demands(sliver, contract("snap=8 rounding=any ties=top-left depth=zid"))[0], Demand::required);
}

TEST(Conformance, TheZidOrderIsHeldWhereItIsCertain) {
    // Two full-viewport triangles, triangle 1 nearer (z 0.25 against 0.75) everywhere.
    const Scene s{{2, 1}, 1, {tri(-1, -1, 4, -1, -1, 4, 0.75), tri(-1, -1, 4, -1, -1, 4, 0.25)}};
    const Contract zid = contract(kExact);
    EXPECT_TRUE(conformance_violations(s, zid, with_ids(s, {1, 1})).empty());
    EXPECT_EQ(whats(conformance_violations(s, zid, with_ids(s, {1, 0}))),
              (std::vector<std::string>{"pixel (1, 0) sample 0 at (1.5, 0.5): triangle 1 covers it (required) and "
                                        "precedes triangle 0 in the (z, id) order, the engine wrote 0"}));
    // At equal depth the lower id precedes.
    const Scene tied{{2, 1}, 1, {tri(-1, -1, 4, -1, -1, 4), tri(-1, -1, 4, -1, -1, 4)}};
    EXPECT_TRUE(conformance_violations(tied, zid, with_ids(tied, {0, 0})).empty());
    EXPECT_EQ(conformance_violations(tied, zid, with_ids(tied, {1, 0})).size(), 1u);
    // depth=none: either id.
    EXPECT_TRUE(conformance_violations(tied, contract("snap=none ties=top-left depth=none"), with_ids(tied, {1, 0}))
                    .empty());
}

TEST(Conformance, UnderRoundingAnyAnOrderThatSomeSnappingGivesIsAllowed) {
    // Triangle 0 has the halfway left edge x = c (c = 0.5 + 2^-9) and the plane z = x - c: at the centre
    // (0.5, 0.5) it is free (covered when c snaps down to 0.5, at depth 0; not when c snaps up, where its
    // plane would give -2^-8 there). Triangle 1 covers the whole pixel at a flat depth z1.
    const double c = 0.5 + std::ldexp(1.0, -9);
    const auto scene = [c](double z1) {
        return Scene{{1, 1}, 1,
                     {Triangle{{Vertex{c, -4, 0}, Vertex{c + 8, -4, 8}, Vertex{c, 4, 0}}}, tri(-4, -4, 8, -4, -4, 8, z1)}};
    };
    const Contract any = contract("snap=8 rounding=any ties=top-left depth=zid");
    // z1 = -2^-9 lies between triangle 0's depths 0 and -2^-8: either may be nearer.
    const Scene between = scene(-std::ldexp(1.0, -9));
    EXPECT_TRUE(conformance_violations(between, any, with_ids(between, {0})).empty());
    EXPECT_TRUE(conformance_violations(between, any, with_ids(between, {1})).empty());
    EXPECT_EQ(conformance_violations(between, any, with_ids(between, {-1})).size(), 1u);
    // z1 = -1 is nearer under every snapping.
    const Scene nearer = scene(-1);
    EXPECT_EQ(whats(conformance_violations(nearer, any, with_ids(nearer, {0}))),
              (std::vector<std::string>{"pixel (0, 0) sample 0 at (0.5, 0.5): triangle 1 covers it (required) and "
                                        "precedes triangle 0 in the (z, id) order, the engine wrote 0"}));
    // z1 = 1 is farther, but triangle 0 need not cover the centre: 1 is allowed.
    const Scene farther = scene(1);
    EXPECT_TRUE(conformance_violations(farther, any, with_ids(farther, {1})).empty());
    EXPECT_TRUE(conformance_violations(farther, any, with_ids(farther, {0})).empty());
    // Nearest-even snaps c down: triangle 0 then covers the centre at depth 0, required, and precedes z1 = 1.
    EXPECT_EQ(conformance_violations(farther, contract("snap=8 rounding=nearest-even ties=top-left depth=zid"),
                                     with_ids(farther, {1}))
                  .size(),
              1u);
}

}  // namespace
}  // namespace rast::properties
