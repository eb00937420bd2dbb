// Extreme coordinates end to end: written as hex-floats in a .tri file, read by the reader and rendered
// by the rast binary with every engine. Expectations are worked out by hand from docs/design.md.
#include "cli_harness.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

namespace rast::robustness {
namespace {

using cli::testing::Result;
using cli::testing::rast;
using CliTest = cli::testing::TempDirTest;

const std::string kReference = "--engine reference";
const std::vector<std::string> kFixed = {"--engine fast --precision fixed4", "--engine fast --precision fixed8",
                                         "--engine fast --precision fixed16"};
const std::vector<std::string> kFloat = {"--engine fast --precision float32", "--engine fast --precision float64"};
// The engines that decide every sample exactly: the reference, and the fixed modes on snapped vertices.
const std::vector<std::string> kExact = {kReference, kFixed[0], kFixed[1], kFixed[2]};
const std::vector<std::string> kAll = {kReference, kFixed[0], kFixed[1], kFixed[2], kFloat[0], kFloat[1]};

const std::string kTwoTo60 = "0x1p+60";
const std::string kDblMax = "0x1.fffffffffffffp+1023";
const std::string kDenormMin = "0x0.0000000000001p-1022";
const std::string kNegDenormMin = "-" + kDenormMin;
const std::string kZero = "0";
const std::string kNegZero = "-0x0p+0";

class ExtremeCoordinates : public CliTest {
protected:
    // The id buffer the binary writes for `scene` with `engine`; the run must succeed.
    std::string ids(const std::string& scene, const std::string& engine) {
        const Result r = rast("render " + file("scene.tri", scene) + " " + engine + " --ids-out " + out("ids.txt"));
        EXPECT_EQ(r.status, 0) << engine << "\n" << r.out;
        return read("ids.txt");
    }
};

// A unit square split on its diagonal from (d, 0) to (1, 1), one pixel, its centre (1/2, 1/2) near the
// diagonal. Triangle 0 (lower right) has the diagonal as a left edge, triangle 1 (upper left) as a right
// edge. The centre's side of the diagonal is the sign of (1 - d) * 1/2 - (1/2 - d) = d / 2:
//   d = +2^-1074: strictly inside triangle 1;
//   d = 0 or -0.0: on the diagonal, owned by triangle 0, its left edge;
//   d = -2^-1074: strictly inside triangle 0.
// The fixed modes snap d to 0: triangle 0 for every d. (The float modes may decide either way: |d / 2| is
// far below their error bound, and docs/design.md promises nothing more.)
TEST_F(ExtremeCoordinates, SubnormalVertexDecidesWhoOwnsTheCentre) {
    const auto scene = [](const std::string& d) {
        return "viewport 1 1\n"
               "tri " + d + " 0 0  1 0 0  1 1 0\n"
               "tri " + d + " 0 0  1 1 0  0 1 0\n";
    };
    EXPECT_EQ(ids(scene(kDenormMin), kReference), "1\n");
    for (const std::string& d : {kZero, kNegZero, kNegDenormMin}) EXPECT_EQ(ids(scene(d), kReference), "0\n") << d;
    for (const std::string& d : {kDenormMin, kZero, kNegZero, kNegDenormMin})
        for (const std::string& engine : kFixed) EXPECT_EQ(ids(scene(d), engine), "0\n") << d << " " << engine;
}

// A left edge x = 3/2 from (3/2, B) down to (3/2, -B), the third vertex at (B, 0): the centres on the
// edge (column 1) are owned, column 0 is outside, and the far edges pass about B - 2 away from columns 2
// and 3. For B = 2^60 and DBL_MAX. The float modes' error bound (a maximum over the edges) is then far
// larger than the distance of every centre to the near edge: they promise only a well-formed answer.
TEST_F(ExtremeCoordinates, FarVerticesKeepTheTieRule) {
    for (const std::string& b : {kTwoTo60, kDblMax}) {
        const std::string scene = "viewport 4 2\ntri 1.5 -" + b + " 0  " + b + " 0 0  1.5 " + b + " 0\n";
        for (const std::string& engine : kExact) EXPECT_EQ(ids(scene, engine), "-1 0 0 0\n-1 0 0 0\n") << b << engine;
        for (const std::string& engine : kFloat) {
            const std::string got = ids(scene, engine);
            EXPECT_TRUE(std::regex_match(got, std::regex("((-1|0)( (-1|0)){3}\n){2}"))) << b << engine << ": " << got;
        }
    }
}

// A triangle with vertices at (-B, -B), (B, -B), (0, B) holds the 3 x 2 viewport deep inside. For
// B = 2^60 every sample is about 2^121 from each edge in edge-function units, far beyond the float modes'
// error bound (about 2^-53 * 2^122): all engines agree. For DBL_MAX the exact ones must still see it.
TEST_F(ExtremeCoordinates, HugeTriangleCoversTheViewport) {
    const auto scene = [](const std::string& b) {
        return "viewport 3 2\ntri -" + b + " -" + b + " 0  " + b + " -" + b + " 0  0 " + b + " 0\n";
    };
    for (const std::string& engine : kAll) EXPECT_EQ(ids(scene(kTwoTo60), engine), "0 0 0\n0 0 0\n") << engine;
    for (const std::string& engine : kExact) EXPECT_EQ(ids(scene(kDblMax), engine), "0 0 0\n0 0 0\n") << engine;
}

// Two triangles over both centres of a 2 x 1 viewport at constant depths z0 and z1. The z-buffer's order:
// smaller z is nearer, equal z goes to the smaller id; -0.0 equals 0.0. Exact in every mode.
TEST_F(ExtremeCoordinates, DepthOrderAtSignedZeroSubnormalAndHugeDepths) {
    struct Case {
        std::string z0, z1, winner;
    };
    const std::vector<Case> cases = {
        {kZero, kNegZero, "0 0\n"},         {kNegZero, kZero, "0 0\n"},
        {kDenormMin, kZero, "1 1\n"},       {kZero, kNegDenormMin, "1 1\n"},
        {kNegDenormMin, kNegZero, "0 0\n"},
        {kDblMax, "-" + kDblMax, "1 1\n"},   {"-" + kDblMax, kDblMax, "0 0\n"},
        {kTwoTo60, "0x1.0000000000001p+60", "0 0\n"}, {"0x1.0000000000001p+60", kTwoTo60, "1 1\n"},
    };
    for (const Case& c : cases) {
        const std::string scene = "viewport 2 1\ntri 0 0 " + c.z0 + "  4 0 " + c.z0 + "  0 4 " + c.z0 +
                                  "\ntri 0 0 " + c.z1 + "  4 0 " + c.z1 + "  0 4 " + c.z1 + "\n";
        for (const std::string& engine : kAll)
            EXPECT_EQ(ids(scene, engine), c.winner) << c.z0 << " vs " << c.z1 << " " << engine;
    }
}

// Depth rising from -DBL_MAX to DBL_MAX over four pixels: z = -M + M/2 * x (M = DBL_MAX), whose slope
// and interpolation overflow in double. Triangle 0 strictly covers all four centres, at exact depths
// -3/4 M, -1/4 M, 1/4 M, 3/4 M; triangle 1 covers them at z = M/2, so it owns only the last. -3/4 M rounds
// to the nearest double, the others are doubles (decimal forms computed with exact rationals in Python).
TEST_F(ExtremeCoordinates, OverflowingDepthPlaneIsOrderedAndRoundedExactly) {
    const std::string m = kDblMax, half = "0x1.fffffffffffffp+1022";
    const std::string scene = "viewport 4 1\n"
                              "tri 0 0 -" + m + "  4 0 " + m + "  0 4.5 -" + m + "\n"
                              "tri -8 -8 " + half + "  16 -8 " + half + "  -8 16 " + half + "\n";
    for (const std::string& engine : kAll) {
        const Result r = rast("render " + file("ramp.tri", scene) + " " + engine + " --ids-out " +
                                   out("ids.txt") + " --depth-out " + out("depth.txt"));
        ASSERT_EQ(r.status, 0) << engine << "\n" << r.out;
        EXPECT_EQ(read("ids.txt"), "0 0 0 1\n") << engine;
        EXPECT_EQ(read("depth.txt"),
                  "-1.3482698511467367e+308 -4.4942328371557893e+307 4.4942328371557893e+307 "
                  "8.988465674311579e+307\n")
            << engine;
    }
}

// A line from -DBL_MAX to +DBL_MAX along row y = 1.5 of a 3 x 3 viewport lights the whole row in every
// engine but float32 (Bresenham's ends in big integers, the DDA's in double); its depth, 2^-1 at one end
// and -2^-1 at the other, is 0 at every pixel's foot up to far below an ulp, in front of the triangle at
// depth 1/4 in row 1 and behind none. A second line at depth DBL_MAX lies behind everything.
TEST_F(ExtremeCoordinates, LineFromEndToEndOfTheDoubles) {
    const std::string scene = "viewport 3 3\n"
                              "tri -8 -8 0x1p-2  24 -8 0x1p-2  -8 24 0x1p-2\n"
                              "line -" + kDblMax + " 1.5 0x1p-1  " + kDblMax + " 1.5 -0x1p-1\n"
                              "line -" + kDblMax + " 0.5 " + kDblMax + "  " + kDblMax + " 0.5 " + kDblMax + "\n";
    for (const std::string& engine : {kReference, kFixed[0], kFixed[1], kFixed[2], kFloat[1]})
        EXPECT_EQ(ids(scene, engine), "0 0 0\n1 1 1\n0 0 0\n") << engine;
    // float32 rounds the ends to -inf and +inf: its DDA has no slope to step by and lights nothing (fast.h).
    EXPECT_EQ(ids(scene, kFloat[0]), "0 0 0\n0 0 0\n0 0 0\n");
}

}  // namespace
}  // namespace rast::robustness
