// rast replay, check and diff end to end: files in, exit status, lines out, files untouched or written.
#include "cli_harness.h"

#include <string>

namespace {

using rast::cli::testing::contains;
using rast::cli::testing::Result;
using rast::cli::testing::rast;
using rast::cli::testing::slurp;
namespace fs = std::filesystem;

class CorpusCommands : public rast::cli::testing::TempDirTest {};

// The split square: corners on pixel centres, a tiling that every exact engine must own once.
constexpr const char* kGoodCase =
    "# properties: watertight tie_rule\n"
    "# why: the diagonal passes through centres\n"
    "viewport 3 3\n"
    "tri 0.5 0.5 0  2.5 0.5 0  2.5 2.5 0\n"
    "tri 0.5 0.5 0  2.5 2.5 0  0.5 2.5 0\n";

// Triangles A (0,0) (4,0) (0,4) and B (0,0) (4,0) (4,4) share the bottom edge and both lie above it. Their
// overlap is 0 < y <= x (B owns its left edge y = x) and x + y < 4 (A does not own its right edge): the
// centres (0.5, 0.5), (1.5, 0.5), (2.5, 0.5) and (1.5, 1.5).
constexpr const char* kFold = "viewport 4 4\ntri 0 0 0  4 0 0  0 4 0\ntri 0 0 0  4 0 0  4 4 0\n";

TEST_F(CorpusCommands, ReplayPassesAGoodCaseAndReportsAMalformedOneWithItsLine) {
    const std::string good = file("cases/a-good.tri", kGoodCase);
    const std::string bad = file("cases/b-bad.tri", "# properties: tie_rule\nviewport 3 3\ntri 1 2 3\n");
    const Result r = rast("replay " + (dir / "cases").string());
    EXPECT_NE(r.status, 0);
    // watertight and tie_rule each apply to the reference and the three fixed modes.
    EXPECT_TRUE(contains(r.out, "PASS " + good + " (2 properties x 6 engines: 8 checks, 0 not applicable)\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "ERROR " + bad + ":3: ")) << r.out;
    EXPECT_TRUE(contains(r.out, "\n1 passed, 1 failed\n")) << r.out;
}

TEST_F(CorpusCommands, ReplayLeavesTheFilesUntouched) {
    const std::string good = file("good.tri", kGoodCase);
    const std::string failing = file("fold.tri", std::string("# properties: watertight\n") + kFold);
    const auto before = fs::last_write_time(failing);
    const auto good_before = fs::last_write_time(good);
    const Result r = rast("replay " + dir.string());
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_EQ(slurp(good), kGoodCase);
    EXPECT_EQ(slurp(failing), std::string("# properties: watertight\n") + kFold);
    EXPECT_EQ(fs::last_write_time(failing), before);
    EXPECT_EQ(fs::last_write_time(good), good_before);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2);
}

TEST_F(CorpusCommands, CheckPassesAClosedCube) {
    // Twelve outward-facing (counter-clockwise from outside) triangles of the cube [-1, 1]^3.
    const std::string cube = file("cube.off",
                                  "OFF\n8 12 0\n"
                                  "-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n1 1 1\n"
                                  "3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n"
                                  "3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n3 1 3 5\n3 3 7 5\n");
    for (const std::string engine : {"--engine reference", "--engine fast --precision fixed4"}) {
        const Result r = rast("check " + cube + " --width 24 --height 16 --eye 3,2,4 " + engine +
                           " --corpus-out " + (dir / "found").string());
        EXPECT_EQ(r.status, 0) << r.out;
        EXPECT_TRUE(contains(r.out, "closed mesh")) << r.out;
        EXPECT_TRUE(contains(r.out, "\n0 violating samples\n")) << r.out;
    }
    EXPECT_FALSE(fs::exists(dir / "found"));
}

TEST_F(CorpusCommands, CheckReportsSamplesCoveredTwiceAcrossASharedEdgeAndKeepsTheCase) {
    const Result r = rast("check " + file("fold.tri", kFold) + " --corpus-out " + (dir / "found").string());
    EXPECT_EQ(r.status, 1) << r.out;
    for (const char* sample : {"pixel (0, 0) sample 0 at (0.5, 0.5)", "pixel (1, 0) sample 0 at (1.5, 0.5)",
                               "pixel (2, 0) sample 0 at (2.5, 0.5)", "pixel (1, 1) sample 0 at (1.5, 1.5)"})
        EXPECT_TRUE(contains(r.out, std::string(sample) + ": covered 2 times, by triangles 0 and 1")) << r.out;
    EXPECT_TRUE(contains(r.out, "\n4 violating samples\n")) << r.out;

    const fs::path kept = dir / "found" / "check-fold-reference.tri";
    ASSERT_TRUE(fs::exists(kept)) << r.out;
    EXPECT_TRUE(contains(slurp(kept), "# properties: watertight\n"));
    const Result replayed = rast("replay " + kept.string());
    EXPECT_EQ(replayed.status, 1) << replayed.out;
    EXPECT_TRUE(contains(replayed.out, "FAIL " + kept.string() +
                                           " watertight [reference]: pixel (0, 0) sample 0 at (0.5, 0.5): "
                                           "reference covers it twice"))
        << replayed.out;
}

TEST_F(CorpusCommands, DiffCountsWhereFloat32LosesANeedleFarFromTheOrigin) {
    // A needle from x = 0.25, where it spans 3.5 - 2^-22 .. 3.5 + 2^-23, to an apex (2^40, 3.5): the reference
    // covers the eight centres of row 3, strictly inside. float32 rounds 3.5 + 2^-23 to 3.5, and its edge
    // functions there (about 2^40 * 2^-23) are far below its rounding error: it covers none of them.
    const std::string needle =
        file("needle.tri", "viewport 8 8\ntri 0.25 0x1.bffffep+1 0  0x1p+40 3.5 0  0.25 0x1.c00001p+1 0\n");
    const Result r = rast("diff " + needle + " --precision float32 -o " + (dir / "diff.png").string());
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "differing samples: 8 of 64\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "differing pixels: 8 of 64\n")) << r.out;
    EXPECT_EQ(slurp(dir / "diff.png").substr(1, 3), "PNG");
}

TEST_F(CorpusCommands, DiffFindsNothingOnASnappedSceneWithFixed8) {
    const Result r = rast("diff " + file("square.tri", kGoodCase) + " --precision fixed8");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "differing samples: 0 of 9\n")) << r.out;
}

}  // namespace
