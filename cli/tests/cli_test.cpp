// The command line, end to end: files in, exit status, messages and files out.
#include "cli_harness.h"

#include <fstream>
#include <string>

namespace {

using rast::cli::testing::Result;
using rast::cli::testing::rast;

class Cli : public rast::cli::testing::TempDirTest {};

// A right triangle with legs 4 and 3: centre (i+1/2, j+1/2) is inside iff 3x + 4y < 12 (never equal).
constexpr const char* kCorner = "viewport 4 3\ntri 0 0 0  4 0 0  0 3 0\n";
constexpr const char* kCornerIds = "0 -1 -1 -1\n0 0 -1 -1\n0 0 0 -1\n";

// A square with corners on pixel centres, split on its diagonal: triangle 0 (lower right) owns the diagonal
// (its left edge), triangle 1 (upper left) owns its top and left edges and their shared corner; no triangle
// owns a bottom or right edge.
constexpr const char* kSplitSquare =
    "viewport 3 3\n"
    "tri 0.5 0.5 0  2.5 0.5 0  2.5 2.5 0\n"
    "tri 0.5 0.5 0  2.5 2.5 0  0.5 2.5 0\n";
constexpr const char* kSplitSquareIds = "1 1 -1\n1 0 -1\n-1 -1 -1\n";

TEST_F(Cli, WritesTheIdBufferTopRowFirst) {
    for (const char* engine : {"reference", "fast"}) {
        const Result r = rast("render " + file("corner.tri", kCorner) + " --engine " + engine + " --ids-out " +
                           (dir / "ids.txt").string());
        ASSERT_EQ(r.status, 0) << r.out;
        EXPECT_EQ(read("ids.txt"), kCornerIds) << engine;
    }
}

TEST_F(Cli, TieRuleOnASplitSquare) {
    for (const char* engine : {"reference", "fast"}) {
        const Result r = rast("render " + file("square.tri", kSplitSquare) + " --engine " + engine + " --ids-out " +
                           (dir / "ids.txt").string());
        ASSERT_EQ(r.status, 0) << r.out;
        EXPECT_EQ(read("ids.txt"), kSplitSquareIds) << engine;
    }
}

TEST_F(Cli, FastPrecisionsAgreeOnSnappedVertices) {
    for (const char* precision : {"fixed4", "fixed8", "fixed16", "float32", "float64"}) {
        const Result r = rast("render " + file("square.tri", kSplitSquare) + " --engine fast --precision " +
                           precision + " --threads 2 --ids-out " + (dir / "ids.txt").string());
        ASSERT_EQ(r.status, 0) << r.out;
        EXPECT_EQ(read("ids.txt"), kSplitSquareIds) << precision;
    }
}

TEST_F(Cli, DepthAtPixelCentres) {
    // z = x on a triangle covering the left column of a 2x1 viewport; the right pixel is empty.
    const Result r = rast("render " + file("ramp.tri", "viewport 2 1\ntri 0 0 0  1 0 1  0 4 0\n") + " --depth-out " +
                       (dir / "depth.txt").string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(read("depth.txt"), "0.5 inf\n");
}

TEST_F(Cli, ExactCoverageAreas) {
    // Half of pixel (0, 0); a triangle with legs 1 and 1/2 inside pixel (1, 0) covers a quarter of it.
    const Result r = rast("render " +
                       file("half.tri", "viewport 2 1\ntri 0 0 0  1 0 0  0 1 0\ntri 1 0 0  2 0 0  2 0.5 0\n") +
                       " --coverage-out " + (dir / "area.txt").string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(read("area.txt"), "1/2 1/4\n");
}

TEST_F(Cli, WritesAPictureAndASummary) {
    const Result r = rast("render --default -o " + (dir / "out.png").string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("exact arithmetic needed for:"), std::string::npos) << r.out;
    std::ifstream png(dir / "out.png", std::ios::binary);
    char magic[8] = {};
    png.read(magic, 8);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}

TEST_F(Cli, MalformedSceneNamesFileAndLine) {
    const std::string path = file("bad.tri", "viewport 4 4\ntri 0 0 0  1 1\n");
    const Result r = rast("render " + path);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.out.find(path + ":2:"), std::string::npos) << r.out;
}

TEST_F(Cli, NonFiniteCoordinateIsRejected) {
    const std::string path = file("nan.tri", "viewport 4 4\n# fine\ntri 0 0 0  1 0 0  nan 1 0\n");
    const Result r = rast("render " + path);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.out.find(path + ":3:"), std::string::npos) << r.out;
}

TEST_F(Cli, BadArgumentsAreRejected) {
    const std::string scene = file("corner.tri", kCorner);
    EXPECT_NE(rast("render").status, 0);
    EXPECT_NE(rast("render " + (dir / "missing.tri").string()).status, 0);
    EXPECT_NE(rast("render " + scene + " --engine gpu").status, 0);
    EXPECT_NE(rast("render " + scene + " --engine fast --precision fixed9").status, 0);
    EXPECT_NE(rast("render " + scene + " --samples 3").status, 0);
    EXPECT_NE(rast("render " + scene + " --threads -1").status, 0);
    EXPECT_NE(rast("render " + scene + " --default").status, 0);
    EXPECT_NE(rast("frobnicate").status, 0);
}

TEST_F(Cli, OutputIntoAMissingDirectoryFailsCleanly) {
    const Result r = rast("render " + file("corner.tri", kCorner) + " --ids-out " + (dir / "no/such/ids.txt").string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.out.find("rast: error:"), std::string::npos) << r.out;
}

TEST_F(Cli, HelpExplainsEveryOption) {
    const Result r = rast("render --help");
    EXPECT_EQ(r.status, 0);
    for (const char* option : {"--engine", "--precision", "--threads", "--samples", "--output", "--ids-out",
                               "--depth-out", "--coverage-out", "--coverage", "--magnify", "--width", "--height", "--eye",
                               "--target", "--up", "--fov", "--near", "--far", "--default"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

}  // namespace
