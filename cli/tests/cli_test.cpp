// The command line, end to end: files in, exit status, messages and files out.
#include "cli_harness.h"

#include <png.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using rast::cli::testing::contains;
using rast::cli::testing::Result;
using rast::cli::testing::rast;
using rast::cli::testing::slurp;
using rast::cli::testing::rast_piped;
using rast::cli::testing::run;
using rast::shell_word;

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

// Threads beyond what the machine runs are not asked of TBB (which would refuse them with a warning on
// stderr), and the engine line names the threads that ran.
TEST_F(Cli, MoreThreadsThanTheMachineRuns) {
    const std::string scene = file("square.tri", kSplitSquare);
    const Result r = rast("render " + scene + " --engine fast --threads 1024 --ids-out " + (dir / "ids.txt").string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "(1024 asked; the most this machine runs)")) << r.out;
    EXPECT_FALSE(contains(r.out, "TBB")) << r.out;
    EXPECT_EQ(read("ids.txt"), kSplitSquareIds);
    const Result all = rast("render " + scene + " --engine fast --threads 0");
    ASSERT_EQ(all.status, 0) << all.out;
    EXPECT_TRUE(contains(all.out, " threads (all)") || contains(all.out, " thread (all)")) << all.out;
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

// z = x and z = y / 2 on two large triangles under x + y = 4 (worked out in docs/design.md's terms): in
// pixel (0, 0) the first is nearer left of x = y / 2 (1/4); in pixel (1, 2), cut by x + y = 4, it sees
// the part left of x = y / 2 (1/6 of its 1/2); pixels beyond the hypotenuse see nothing.
TEST_F(Cli, WritesTheExactVisibleArea) {
    const Result r = rast("render " +
                          file("crossing.tri", "viewport 4 3\ntri -4 -4 -4  8 -4 8  -4 8 -4\n"
                                               "tri -4 -4 -2  8 -4 -2  -4 8 4\n") +
                          " --visible-out " + out("visible.txt") + " -o " + out("error.png") +
                          " --coverage visible-error");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(read("visible.txt"), "0:1 0:1/6,1:1/3 - -\n"
                                   "0:3/4,1:1/4 1:1 1:1/2 -\n"
                                   "0:1/4,1:3/4 1:1 1:1 1:1/2\n");
    // Five panels of 4 x 3 (the ideal, then 1, 4, 8 and 16 samples) with a pixel between: 24 x 3. PNG
    // gives width and height big-endian at bytes 16 and 20.
    const std::string png = read("error.png");
    ASSERT_GE(png.size(), 24u);
    const auto be32 = [&](std::size_t at) {
        return (std::uint32_t(std::uint8_t(png[at])) << 24) | (std::uint32_t(std::uint8_t(png[at + 1])) << 16) |
               (std::uint32_t(std::uint8_t(png[at + 2])) << 8) | std::uint32_t(std::uint8_t(png[at + 3]));
    };
    EXPECT_EQ(be32(16), 24u);
    EXPECT_EQ(be32(20), 3u);
}

// The same planes with a line in front, first in the file: its id 0 moves the triangles to 1 and 2 in the
// visible areas (lines have none), and in the id buffer it holds the top row it lights; below it the centres
// with i + j = 3 lie on the hypotenuse, a right edge, and stay empty. The error picture
// against the visible ideal is refused: the line's samples would count as error.
TEST_F(Cli, VisibleAreaNamesTrianglesByIdAmongLines) {
    const std::string scene = file("crossing-line.tri", "viewport 4 3\nline 0.5 2.5 -9  4.5 2.5 -9\n"
                                                        "tri -4 -4 -4  8 -4 8  -4 8 -4\n"
                                                        "tri -4 -4 -2  8 -4 -2  -4 8 4\n");
    const Result r = rast("render " + scene + " --visible-out " + out("visible.txt") + " --ids-out " + out("ids.txt"));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(read("visible.txt"), "1:1 1:1/6,2:1/3 - -\n"
                                   "1:3/4,2:1/4 2:1 2:1/2 -\n"
                                   "1:1/4,2:3/4 2:1 2:1 2:1/2\n");
    EXPECT_EQ(read("ids.txt"), "0 0 0 0\n1 2 -1 -1\n2 2 2 -1\n");
    const Result refused = rast("render " + scene + " -o " + out("error.png") + " --coverage visible-error");
    EXPECT_EQ(refused.status, 2) << refused.out;
    EXPECT_NE(refused.out.find("lines (no area) have no part"), std::string::npos) << refused.out;
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
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find(path + ":2:"), std::string::npos) << r.out;
}

TEST_F(Cli, NonFiniteCoordinateIsRejected) {
    const std::string path = file("nan.tri", "viewport 4 4\n# fine\ntri 0 0 0  1 0 0  nan 1 0\n");
    const Result r = rast("render " + path);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find(path + ":3:"), std::string::npos) << r.out;
}

// docs/design.md's exit status: 0 nothing found; 1 a verdict failed (the command worked); 2 the command
// could not do its job. Bad usage (CLI11's own errors included) and bad input are 2, help is 0.
TEST_F(Cli, BadArgumentsAreRejected) {
    const std::string scene = file("corner.tri", kCorner);
    EXPECT_EQ(rast("render").status, 2);
    EXPECT_EQ(rast("render " + (dir / "missing.tri").string()).status, 2);
    EXPECT_EQ(rast("render " + scene + " --engine gpu").status, 2);
    EXPECT_EQ(rast("render " + scene + " --engine fast --precision fixed9").status, 2);
    EXPECT_EQ(rast("render " + scene + " --samples 3").status, 2);
    EXPECT_EQ(rast("render " + scene + " --threads -1").status, 2);
    EXPECT_EQ(rast("render " + scene + " --default").status, 2);
    EXPECT_EQ(rast("frobnicate").status, 2);
    EXPECT_EQ(rast("render --help").status, 0);
    EXPECT_EQ(rast("render " + scene + " --ids-out " + out("ids.txt")).status, 0);
}

// What a first try runs into, each answered by name: the version; an unknown command, with the commands
// there are; a picture name that is not .png (rast would have written PNG bytes under it); an option
// given twice.
TEST_F(Cli, FirstTriesAreAnsweredByName) {
    const std::string scene = file("corner.tri", kCorner);
    Result r = rast("--version");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "rast " RAST_VERSION "\n");
    r = rast("frobnicate");
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "rast: error: unknown command 'frobnicate' (the commands: render, replay, check, "
                                "diff")) << r.out;
    for (const std::string command : {"render ", "diff "}) {
        r = rast(command + scene + " -o " + out("picture.jpg"));
        EXPECT_EQ(r.status, 2) << command;
        EXPECT_TRUE(contains(r.out, "rast writes PNG pictures only; name the file .png")) << r.out;
        EXPECT_FALSE(std::filesystem::exists(dir / "picture.jpg")) << command;
    }
    EXPECT_EQ(rast("render " + scene + " -o " + out("picture.PNG")).status, 0);
    r = rast("render " + scene + " --engine fast --engine reference");
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "--engine: At Most 1 required but received 2")) << r.out;
}

// A triangle at 10^38 is beyond what float32 can bound (its products overflow): float32 leaves it out of
// most of the picture, and says why, naming it. float64 and the reference draw it, and say nothing.
TEST_F(Cli, AFloatModeSaysWhichTrianglesItCannotBound) {
    const std::string scene =
        file("huge.tri", "viewport 8 8\ntri 0 0 0  8 0 0  0 8 0\ntri 1e38 0 0  -1e38 1 0  0 3e38 0\n");
    Result r = rast("render " + scene + " --engine fast --precision float32");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "rast: note: float32 cannot bound the edge functions of 1 triangle (the first: "
                                "triangle 1)"))
        << r.out;
    for (const std::string engine : {"--engine fast --precision float64", "--engine reference"}) {
        r = rast("render " + scene + " " + engine);
        EXPECT_EQ(r.status, 0) << r.out;
        EXPECT_FALSE(contains(r.out, "note")) << engine << '\n' << r.out;
        EXPECT_TRUE(contains(r.out, "covered: 64 of 64 samples")) << engine << '\n' << r.out;
    }
}

TEST_F(Cli, OutputIntoAMissingDirectoryFailsCleanly) {
    const Result r = rast("render " + file("corner.tri", kCorner) + " --ids-out " + out("no/such/ids.txt"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "rast: error: --ids-out '" + out("no/such/ids.txt") + "': its folder '" +
                                    out("no/such") + "' does not exist\n"))
        << r.out;
}

// Each output option, given the scene's own path (spelt as given, spelt otherwise, or a hard link to it),
// is refused before anything is written: the scene stays byte for byte what it was. -o is refused for
// its name first: a scene is no PNG picture.
TEST_F(Cli, AnOutputThatIsTheInputIsRefused) {
    const std::string scene = file("corner.tri", kCorner);
    std::filesystem::create_hard_link(scene, dir / "link.tri");
    for (const char* option : {"-o", "--ids-out", "--depth-out", "--coverage-out", "--visible-out"})
        for (const std::string& same : {scene, (dir / "." / "corner.tri").string(), out("link.tri")}) {
            const Result r = rast("render " + scene + " " + option + " " + same);
            EXPECT_EQ(r.status, 2) << option << " " << same;
            const std::string why = std::string(option) == "-o"
                                        ? "'" + same + "': rast writes PNG pictures only; name the file .png"
                                        : std::string(option) + " '" + same + "' is the same file as the input '" +
                                              scene + "': refusing to overwrite it";
            EXPECT_TRUE(contains(r.out, why)) << r.out;
            EXPECT_FALSE(contains(r.out, "scene:")) << "it rendered first:\n" << r.out;
            EXPECT_EQ(read("corner.tri"), kCorner) << option << " " << same;
        }
}

TEST_F(Cli, TwoOutputsOnOneFileAreRefused) {
    const std::string scene = file("corner.tri", kCorner);
    std::filesystem::create_directories(dir / "sub");
    const Result r = rast("render " + scene + " -o " + out("out.png") + " --ids-out " + out("sub/../out.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "--ids-out '" + out("sub/../out.png") + "' is the same file as -o '" + out("out.png") +
                                    "': give each output its own path"))
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

// A bare name that does not exist yet is the same file as that name under "./" (weakly_canonical alone
// leaves the first relative and the second absolute, and the depths were written over the ids).
TEST_F(Cli, TwoOutputsOnOneFileAreRefusedUnderRelativeNames) {
    const std::string scene = file("corner.tri", kCorner);
    const Result r = rast("render " + scene + " --ids-out ids.txt --depth-out ./ids.txt");
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "--depth-out './ids.txt' is the same file as --ids-out 'ids.txt'")) << r.out;
    EXPECT_FALSE(std::filesystem::exists("ids.txt"));
}

// Every output path is checked before the work, so a bad one leaves the others as they were.
TEST_F(Cli, ABadOutputPathLeavesTheOtherOutputsUntouched) {
    const std::string scene = file("corner.tri", kCorner);
    file("old.png", "old picture");
    file("a-file", "not a folder");
    std::filesystem::create_directories(dir / "folder");
    const std::pair<std::string, std::string> bad[] = {
        {out("missing/ids.txt"), "its folder '" + out("missing") + "' does not exist"},
        {out("a-file/ids.txt"), "its parent '" + out("a-file") + "' is not a folder"},
        {out("folder"), "is a folder"},
        {out("folder") + "/", "the path names a folder, not a file"}};
    for (const auto& [path, why] : bad) {
        const Result r = rast("render " + scene + " -o " + out("old.png") + " --depth-out " + out("new.txt") +
                              " --ids-out " + path);
        EXPECT_EQ(r.status, 2) << path;
        EXPECT_TRUE(contains(r.out, "rast: error: --ids-out '" + path + "': " + why + "\n")) << r.out;
        EXPECT_EQ(read("old.png"), "old picture") << path;
        EXPECT_FALSE(std::filesystem::exists(dir / "new.txt")) << path;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir / "folder"));
}

// A scene piped in as /dev/stdin is a pipe with no name: the outputs are still checked against it, and
// written.
TEST_F(Cli, APipedSceneCanHaveOutputs) {
    const Result r = rast_piped(kCorner, "render /dev/stdin --ids-out " + out("ids.txt"));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(read("ids.txt"), kCornerIds);
}

// With N samples the buffers hold every sample: W x N entries a line, each pixel's samples in the pattern's
// order. The triangle x / 2 + y <= 1 over two pixels, at depth 0.25; the 4x pattern's samples (0.375,
// 0.875), (0.875, 0.625), (0.125, 0.375), (0.625, 0.125) of either pixel: the first two lie above the
// hypotenuse, the last two below it.
TEST_F(Cli, BuffersHoldEverySample) {
    const std::string scene = file("half.tri", "viewport 2 1\ntri 0 0 0.25  2 0 0.25  0 1 0.25\n");
    for (const std::string engine : {"--engine reference", "--engine fast --precision fixed8"}) {
        const Result r = rast("render " + scene + " --samples 4 " + engine + " --ids-out " + out("ids.txt") +
                              " --depth-out " + out("depth.txt"));
        ASSERT_EQ(r.status, 0) << r.out;
        EXPECT_EQ(read("ids.txt"), "-1 -1 0 0 -1 -1 0 0\n") << engine;
        EXPECT_EQ(read("depth.txt"), "inf inf 0.25 0.25 inf inf 0.25 0.25\n") << engine;
    }
}

// SCENE - reads a .tri scene from standard input; its errors name <stdin> and the line.
TEST_F(Cli, ADashReadsTheSceneFromStandardInput) {
    Result r = rast_piped(kCorner, "render - --ids-out " + out("ids.txt"));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(read("ids.txt"), kCornerIds);
    r = rast_piped("viewport 4 3\ntri 0 0 0  4 0\n", "render -");
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "rast: error: <stdin>:2: ")) << r.out;
}

// The scene's own sample count was within the size limit; the override's is not.
TEST_F(Cli, ASampleCountAboveTheSizeLimitIsRefused) {
    const Result r = rast("render " + file("big.tri", "viewport 16384 16384\ntri 0 0 0 1 0 0 0 1 0\n") +
                          " --samples 16 --ids-out " + out("ids.txt"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "rast: error: --samples 16: viewport 16384x16384 with 16 samples per pixel has "
                                "4294967296 samples, above the limit 268435456\n"))
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "ids.txt"));
}

// A name as long as the file system allows is a legal output: its temporary, named after it, must be too.
TEST_F(Cli, AnOutputWithTheLongestNameIsWritten) {
    const std::string name(255, 'n');
    const Result r = rast("render " + file("corner.tri", kCorner) + " --ids-out " + out(name));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(read(name), kCornerIds);
}

// Refused before the render: libpng writes at most 10^6 pixels across, and 8192^2 magnified 64 times would
// not fit in memory (each ended, after the work, in "Invalid IHDR data" or "std::bad_alloc").
TEST_F(Cli, AMagnifiedPictureTooLargeIsRefused) {
    const std::pair<std::string, std::string> cases[] = {
        {"viewport 20000 1\n", "the picture would be 1280000x64 pixels, and PNG pictures are written at most "
                               "1000000x1000000"},
        {"viewport 8192 8192\n", "the picture would be 524288x524288 pixels, more than the 268435456 a picture "
                                 "may have"}};
    for (const auto& [viewport, why] : cases) {
        const Result r = rast("render " + file("big.tri", viewport + "tri 0 0 0 1 0 0 0 1 0\n") + " --magnify 64 -o " +
                              out("big.png"));
        EXPECT_EQ(r.status, 2);
        EXPECT_TRUE(contains(r.out, "rast: error: --magnify 64: " + why + "\n")) << r.out;
        EXPECT_FALSE(contains(r.out, "scene:")) << "it rendered first:\n" << r.out;
        EXPECT_FALSE(std::filesystem::exists(dir / "big.png"));
    }
}

// Writing is a rename over the path: it would replace a pipe or a device, not write into it.
TEST_F(Cli, AnOutputThatIsNotARegularFileIsRefused) {
    ASSERT_EQ(::mkfifo(out("pipe").c_str(), 0600), 0);
    const Result r = rast("render " + file("corner.tri", kCorner) + " --ids-out " + out("pipe"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "--ids-out '" + out("pipe") + "': exists and is not a regular file")) << r.out;
    EXPECT_TRUE(std::filesystem::is_fifo(dir / "pipe"));
}

TEST_F(Cli, AnEmptyOutputPathIsRefused) {
    const std::string scene = file("corner.tri", kCorner);
    for (const char* option : {"-o", "--ids-out", "--depth-out", "--coverage-out", "--visible-out"}) {
        const Result r = rast("render " + scene + " " + option + " ''");
        EXPECT_EQ(r.status, 2) << option;
        EXPECT_TRUE(contains(r.out, "rast: error: " + std::string(option) + " '': the path is empty\n")) << r.out;
    }
}

TEST_F(Cli, EveryFileWrittenIsReported) {
    const Result r = rast("render " + file("corner.tri", kCorner) + " -o " + out("a.png") + " --ids-out " +
                          out("ids.txt") + " --coverage-out " + out("area.txt"));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "wrote " + out("a.png") + "\nwrote " + out("ids.txt") + "\nwrote " + out("area.txt") +
                                    "\n"))
        << r.out;
    EXPECT_EQ(read("ids.txt"), kCornerIds);
}

// A .tri scene (or the built-in one) is in screen space already: the mesh options would be ignored.
TEST_F(Cli, MeshOptionsWithoutAMeshAreRefused) {
    const std::string scene = file("corner.tri", kCorner);
    const std::pair<std::string, std::string> options[] = {
        {"--width", "8"},     {"--height", "8"}, {"--eye", "1,2,3"}, {"--target", "0,0,0"},
        {"--up", "0,0,1"},    {"--fov", "30"},   {"--near", "0.5"},  {"--far", "9"}};
    for (const auto& [option, value] : options) {
        Result r = rast("render " + scene + " " + option + " " + value + " --ids-out " + out("ids.txt"));
        EXPECT_NE(r.status, 0) << option;
        EXPECT_TRUE(contains(r.out, option + ": applies to meshes only (OBJ, OFF, PLY, STL), and " + scene +
                                        " is a .tri scene"))
            << r.out;
        r = rast("render --default " + option + " " + value + " --ids-out " + out("ids.txt"));
        EXPECT_NE(r.status, 0) << option;
        EXPECT_TRUE(contains(r.out, option + " excludes --default")) << r.out;
        EXPECT_FALSE(std::filesystem::exists(dir / "ids.txt")) << option;
    }
}

TEST_F(Cli, MeshOptionsPlaceAMesh) {
    // One triangle facing the camera: what matters here is the viewport the options make.
    const Result r = rast("render " + file("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") +
                          " --width 5 --height 2 --eye 0,0,4 --fov 40 --ids-out " + out("ids.txt"));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, " 1 triangle, 5x2, ")) << r.out;
}

// The near and far planes' distances are finite and normal (a subnormal near plane drew nothing), and a
// refusal says so in a few words.
TEST_F(Cli, ANearOrFarPlaneNotAboveZeroIsRefused) {
    const std::string mesh = file("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for (const std::string option : {"--near", "--far"})
        for (const std::string value : {"-1", "0", "1e-320", "inf", "nan", "x"}) {
            const Result r = rast("render " + mesh + " " + option + " " + value);
            EXPECT_EQ(r.status, 2) << option << " " << value << ": " << r.out;
            EXPECT_TRUE(contains(r.out, option + ": a distance must be finite and at least 2^-1022, the least "
                                                 "normal double; got " + value + "\n"))
                << r.out;
        }
    EXPECT_EQ(rast("render " + mesh + " --near 0.5 --far 9").status, 0);
    EXPECT_EQ(rast("render " + mesh + " --near 1e-300").status, 0);
}

// A floor under the eye reaching behind it, seen from the origin looking down -z: the near and far planes
// are framed for this camera, not the default one (which put the whole floor behind the near plane and
// drew nothing, silently), and the note says what the near plane still cuts: the two faces that reach
// behind the eye. A camera that sees all of a mesh gets no note.
TEST_F(Cli, NearAndFarAreFramedForTheCameraInUse) {
    const std::string floor = file("floor.obj", "v -5 -1 5\nv 5 -1 5\nv 5 -1 -5\nv -5 -1 -5\nf 1 2 3\nf 1 3 4\n");
    const Result r = rast("render " + floor + " --width 16 --height 16 --eye 0,0,0 --target 0,0,-1 --ids-out " +
                          out("ids.txt"));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "rast: note: the near plane, ")) << r.out;
    EXPECT_TRUE(contains(r.out, " cuts 2 of the mesh's 2 faces and hides 0 behind it")) << r.out;
    // The floor fills the lower half of the picture, below the horizon: the id file's last line (the bottom
    // row) is all floor, its first (the top row) all empty.
    const std::string ids = slurp(dir / "ids.txt");
    const std::string top = ids.substr(0, ids.find('\n')), bottom = ids.substr(ids.rfind('\n', ids.size() - 2) + 1);
    EXPECT_FALSE(contains(bottom, "-1")) << ids;
    EXPECT_EQ(top.find_first_not_of("-1 "), std::string::npos) << ids;

    const Result seen = rast("render " + floor + " --width 16 --height 16 --ids-out " + out("ids.txt"));
    ASSERT_EQ(seen.status, 0) << seen.out;
    EXPECT_FALSE(contains(seen.out, "note")) << seen.out;
}

// A PNG's pixels as 8-bit RGB, rows top first (libpng's simplified reader); empty if it cannot be read.
std::vector<std::uint8_t> png_rgb(const std::filesystem::path& file, unsigned& width) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, file.c_str())) return {};
    image.format = PNG_FORMAT_RGB;
    std::vector<std::uint8_t> rgb(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) return {};
    width = image.width;
    return rgb;
}

// --coverage depth: a grey ramp over the finite depths. Pixel 0 holds depth 0.5, the nearest (white);
// pixels 1 and 2 depth 1, the farthest (a fifth of white, 51). With 4 samples, pixel 2's sample (2.875,
// 0.625) lies on the second triangle's right edge x + y = 3.5, which does not own it, and is empty; the
// other three are inside: 3/4 of 51, 38.
TEST_F(Cli, TheDepthPictureIsAGreyRampOverFiniteDepths) {
    const std::string scene =
        file("two.tri", "viewport 3 1\ntri 0 0 0.5  1.5 0 0.5  0 1.5 0.5\ntri 1 0 1  3.5 0 1  1 2.5 1\n");
    Result r = rast("render " + scene + " --coverage depth -o " + out("depth.png"));
    ASSERT_EQ(r.status, 0) << r.out;
    unsigned width = 0;
    EXPECT_EQ(png_rgb(dir / "depth.png", width), (std::vector<std::uint8_t>{255, 255, 255, 51, 51, 51, 51, 51, 51}));
    EXPECT_EQ(width, 3u);
    r = rast("render " + scene + " --samples 4 --coverage depth -o " + out("depth.png"));
    ASSERT_EQ(r.status, 0) << r.out;
    const std::vector<std::uint8_t> rgb = png_rgb(dir / "depth.png", width);
    ASSERT_EQ(rgb.size(), 9u);
    EXPECT_EQ(rgb[6], 38);
}

// The reference is exact; it would ignore the fast path's precision and threads.
TEST_F(Cli, FastPathOptionsWithoutTheFastPathAreRefused) {
    const std::string scene = file("corner.tri", kCorner);
    for (const char* engine : {"", " --engine reference"})
        for (const std::string option : {"--precision", "--threads"}) {
            const std::string value = option == "--threads" ? " 2" : " fixed4";
            const Result r = rast("render " + scene + engine + " " + option + value);
            EXPECT_NE(r.status, 0) << engine << " " << option;
            EXPECT_TRUE(contains(r.out, option + ": applies to --engine fast only")) << r.out;
            EXPECT_FALSE(contains(r.out, "scene:")) << r.out;
        }
}

// --magnify and --coverage shape the picture: without -o they would be ignored.
TEST_F(Cli, PictureOptionsWithoutAPictureAreRefused) {
    const std::string scene = file("corner.tri", kCorner);
    for (const std::string option : {"--magnify", "--coverage"}) {
        const Result r = rast("render " + scene + " " + option + (option == "--magnify" ? " 2" : " area") +
                              " --ids-out " + out("ids.txt"));
        EXPECT_NE(r.status, 0) << option;
        EXPECT_TRUE(contains(r.out, option + " requires --output")) << r.out;
        EXPECT_FALSE(std::filesystem::exists(dir / "ids.txt")) << option;
    }
}

// rast bench checks its outputs before it runs (which takes a minute even with --quick).
TEST_F(Cli, BenchRefusesBadOutputsBeforeRunning) {
    // Without it, "bench --help" is the top-level help, which succeeds: ask the list of subcommands.
    if (!contains(rast("--help").out, "\n  bench ")) GTEST_SKIP() << "built without rast bench";
    Result r = rast("bench --quick --json " + out("a.json") + " --plot " + out("missing/plot.svg"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "rast: error: --plot '" + out("missing/plot.svg") + "': its folder '" + out("missing") +
                                    "' does not exist\n"))
        << r.out;
    r = rast("bench --quick --json " + out("a.json") + " --markdown " + out("a.json"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "--markdown '" + out("a.json") + "' is the same file as --json '" + out("a.json")))
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.json"));
}

// The hard-case section renders no mesh: --mesh would be ignored.
TEST_F(Cli, BenchRefusesAMeshNoChosenSectionRenders) {
    if (!contains(rast("--help").out, "\n  bench ")) GTEST_SKIP() << "built without rast bench";
    const std::string mesh = file("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Result r = rast("bench --quick --only hard --mesh " + mesh + " --json " + out("a.json"));
    EXPECT_NE(r.status, 0);
    EXPECT_TRUE(contains(r.out, "--mesh: no section chosen with --only renders a mesh (speed and aa do)")) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.json"));
}

// Without the antialiasing section there is nothing to plot: --aa-plot would be ignored.
TEST_F(Cli, BenchRefusesAnAaPlotWithoutTheAaSection) {
    if (!contains(rast("--help").out, "\n  bench ")) GTEST_SKIP() << "built without rast bench";
    const Result r = rast("bench --quick --only hard --aa-plot " + out("aa.svg"));
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(contains(r.out, "--aa-plot: no section chosen with --only measures antialiasing (aa does)")) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "aa.svg"));
}

// What rast writes as a command to type again: each word read back by the shell as it was.
TEST(ShellWord, EveryWordReadsBackFromTheShellAsItWas) {
    EXPECT_EQ(shell_word("corpus/fans/a-b_c.tri"), "corpus/fans/a-b_c.tri");  // nothing to quote
    EXPECT_EQ(shell_word("it's"), "'it'\\''s'");
    EXPECT_EQ(shell_word(""), "''");
    for (const std::string word : {"plain", "a b", "it's", "'", "''", "", "$HOME", "`id`", "$(id)", "a\\b", "x;y",
                                   "*", "~", "\"q\"", "tab\there", "new\nline", "-n", "été", "!1", "#x", "a=b c"}) {
        const Result r = rast::cli::testing::run("printf '%s' " + shell_word(word));
        EXPECT_EQ(r.status, 0) << word;
        EXPECT_EQ(r.out, word) << shell_word(word);
    }
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
