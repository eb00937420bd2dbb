// Any rasterizer through the plugin ABI, from the command line: --engine plugin:PATH wherever an engine is
// chosen, and a plugin that fails ends the command with exit status 2 and its reason, writing nothing.
#include "cli_harness.h"

#include <string>

namespace rast::cli::testing {
namespace {

const std::string kFixed8 = RAST_PLUGINS "/rast-plugin-fixed8.so";
const std::string kNaive = RAST_PLUGINS "/rast-plugin-naive.so";
std::string misbehaving(const std::string& way) { return RAST_TEST_PLUGINS "/misbehaving-" + way + ".so"; }
// The careful engine of plugin/tests/plugins/careful.c, or the same with one seeded defect.
std::string misbehaving_careful(const std::string& defect) {
    return RAST_TEST_PLUGINS "/careful" + (defect.empty() ? "" : "-" + defect) + ".so";
}

// Two triangles sharing the diagonal of a 2x2 square, which passes through the centres (0.5, 0.5) and
// (1.5, 1.5). Counter-clockwise, the diagonal is triangle 0's edge (2,2)->(0,0), a left edge (dy < 0), and
// triangle 1's edge (0,0)->(2,2), a right one: the tie rule gives both centres to triangle 0.
const std::string kSplitSquare =
    "viewport 2 2\n"
    "tri 0 0 0.5  2 0 0.5  2 2 0.5\n"
    "tri 0 0 0.5  2 2 0.5  0 2 0.5\n";

class PluginCommands : public TempDirTest {};

TEST_F(PluginCommands, RenderWithAPluginWritesWhatTheFastPathWrites) {
    const Result plugin = rast("render --default --engine plugin:" + kFixed8 + " --ids-out " + out("plugin.txt"));
    ASSERT_EQ(plugin.status, 0) << plugin.out;
    EXPECT_TRUE(contains(plugin.out, "engine:  plugin fixed8 (" + kFixed8 + ")")) << plugin.out;
    ASSERT_EQ(rast("render --default --engine fast --ids-out " + out("fast.txt")).status, 0);
    EXPECT_EQ(read("plugin.txt"), read("fast.txt"));
}

// With standard input (and fd 3) closed, the socket pair to the plugin's process takes fds 0 and 3: the
// end the host is to read as fd 3 must still reach it.
TEST_F(PluginCommands, APluginRunsWithAStandardStreamClosed) {
    const Result r = rast("render --default --engine plugin:" + kFixed8 + " <&- 3>&-");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "covered: 24576 of 24576 samples")) << r.out;
}

// What a plugin prints on its standard output reaches rast's standard error, never rast's output (a
// script reading it) and never the socket (the render goes on).
TEST_F(PluginCommands, WhatAPluginPrintsGoesToStandardError) {
    const std::string command = std::string(RAST_BINARY) + " render --default --engine plugin:" + misbehaving("prints");
    const Result out_only = run(command + " 2>/dev/null");
    EXPECT_EQ(out_only.status, 0) << out_only.out;
    EXPECT_FALSE(contains(out_only.out, "a plugin that talks on stdout")) << out_only.out;
    EXPECT_TRUE(contains(out_only.out, "covered: 0 of 24576 samples")) << out_only.out;
    const Result err_only = run(command + " 2>&1 >/dev/null");
    EXPECT_TRUE(contains(err_only.out, "a plugin that talks on stdout\n")) << err_only.out;
}

TEST_F(PluginCommands, APluginThatCrashesEndsTheCommandWithItsReasonAndWritesNothing) {
    const Result r = rast("render --default --engine plugin:" + misbehaving("crash") + " -o " + out("picture.png") +
                          " --ids-out " + out("ids.txt"));
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_TRUE(contains(r.out, "rast: error: plugin " + misbehaving("crash") +
                                    ": crashed (signal 11, Segmentation fault) rendering a scene of 17 triangles"))
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "picture.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "ids.txt"));
}

TEST_F(PluginCommands, AHangingPluginIsStoppedAtTheTimeoutGiven) {
    const Result r = rast("render --default --engine plugin:" + misbehaving("hang") + " --plugin-timeout 0.2");
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_TRUE(contains(r.out, ": no answer within 0.2 s rendering a scene of 17 triangles")) << r.out;
}

TEST_F(PluginCommands, EngineOptionsAreRefusedWhereTheyDoNotApply) {
    const Result timeout = rast("render --default --engine fast --plugin-timeout 5");
    EXPECT_EQ(timeout.status, 2);
    EXPECT_TRUE(contains(timeout.out, "applies to --engine plugin:PATH only")) << timeout.out;
    const Result empty = rast("render --default --engine plugin:");
    EXPECT_EQ(empty.status, 2);
    EXPECT_TRUE(contains(empty.out, "plugin: needs the library's path")) << empty.out;
    const Result unknown = rast("render --default --engine gpu");
    EXPECT_EQ(unknown.status, 2);
    EXPECT_TRUE(contains(unknown.out, "unknown engine 'gpu' (expected reference, fast or plugin:PATH)")) << unknown.out;
    const Result depth = rast("render --default --engine plugin:" + kFixed8 + " --depth-out " + out("depth.txt"));
    EXPECT_EQ(depth.status, 2);
    EXPECT_TRUE(contains(depth.out, "--depth-out: a plugin returns ids only, no depths")) << depth.out;
    const Result diff = rast("diff " + file("s.tri", kSplitSquare) + " --engine reference");
    EXPECT_EQ(diff.status, 2);
    EXPECT_TRUE(contains(diff.out, "diff compares the reference with another engine")) << diff.out;
}

TEST_F(PluginCommands, ReplayHoldsAPluginToTheCasesProperties) {
    const std::string scene = file("split-square.tri", "# properties: watertight tie_rule\n" + kSplitSquare);
    const Result naive = rast("replay --engine plugin:" + kNaive + " " + scene);
    EXPECT_EQ(naive.status, 1) << naive.out;
    // The diagonal passes through the centres of pixels (0, 0) and (1, 1): ">= 0" covers them twice.
    EXPECT_TRUE(contains(naive.out, "FAIL " + scene + " watertight [naive]: pixel (0, 0) sample 0 at (0.5, 0.5): "
                                                      "naive covers it twice, by triangle 0 and triangle 1"))
        << naive.out;
    const Result fixed8 = rast("replay --engine plugin:" + kFixed8 + " " + scene);
    EXPECT_EQ(fixed8.status, 0) << fixed8.out;
    const std::string counts = " (2 properties x 1 engine: 2 checks, 0 not applicable, 0 outside a contract)\n";
    EXPECT_TRUE(contains(fixed8.out, "PASS " + scene + counts)) << fixed8.out;
}

TEST_F(PluginCommands, ReplaySkipsACaseThePluginCannotRender) {
    const std::string scene = file("x4.tri", "# properties: watertight\nsamples 4\n" + kSplitSquare);
    const Result r = rast("replay --engine plugin:" + kNaive + " " + scene);
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "SKIP " + scene + ": watertight [naive]: the engine does not render 4 samples a pixel"))
        << r.out;
    EXPECT_TRUE(contains(r.out, "0 passed, 0 failed, 1 skipped")) << r.out;
}

TEST_F(PluginCommands, DiffComparesAPluginWithTheReference) {
    const Result r = rast("diff " + file("s.tri", kSplitSquare) + " --engine plugin:" + kNaive);
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "compare: reference (exact) vs plugin naive (" + kNaive + ")")) << r.out;
    // ">= 0" lets both triangles cover the diagonal's two centres, and "<=" gives them to the later one.
    EXPECT_TRUE(contains(r.out, "differing samples: 2 of 4")) << r.out;
}

// A closed mesh checked with an engine that culls clockwise triangles: every covered sample is front-facing
// only. The kept case holds the triangle the engine left out too, so it fails again on that engine, and
// passes on rast's own.
TEST_F(PluginCommands, CheckKeepsACaseThatReproducesAPluginsFailure) {
    const std::string mesh = std::string(RAST_TEST_DATA) + "/sliver-sphere.off --width 20 --height 20";
    const Result careful = rast("check " + mesh + " --engine plugin:" + misbehaving_careful(""));
    EXPECT_EQ(careful.status, 0) << careful.out;
    const Result culling =
        rast("check " + mesh + " --engine plugin:" + misbehaving_careful("culls_clockwise") + " --corpus-out " +
             out("found"));
    EXPECT_EQ(culling.status, 1) << culling.out;
    const std::string kept = out("found/check-sliver-sphere-careful.tri");
    ASSERT_TRUE(std::filesystem::exists(kept)) << culling.out;
    const Result again = rast("replay --engine plugin:" + misbehaving_careful("culls_clockwise") + " " + kept);
    EXPECT_EQ(again.status, 1) << again.out;
    EXPECT_TRUE(contains(again.out, "tie_rule [careful]: ")) << again.out;
    const Result built_in = rast("replay " + kept);
    EXPECT_EQ(built_in.status, 0) << built_in.out;
}

TEST_F(PluginCommands, ConformCatchesTheTutorialRasterizerAndKeepsReplayableCases) {
    const std::string found = out("found");
    const Result r = rast("conform " + kNaive + " --corpus " + RAST_CORPUS + "/tie-rule --cases 20 --found " + found +
                          " --json " + out("verdict.json") + " --markdown " + out("verdict.md"));
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "contract: name=naive samples=1 snap=none ties=top-left depth=zid")) << r.out;
    // The shared diagonals of the tie-rule corpus are covered twice by ">= 0".
    EXPECT_TRUE(contains(r.out, "FAIL watertight: ")) << r.out;
    EXPECT_TRUE(contains(r.out, "FAIL conforms: ")) << r.out;
    EXPECT_TRUE(contains(r.out, "FAIL tie_rule: ")) << r.out;
    EXPECT_TRUE(contains(r.out, " failed")) << r.out;
    EXPECT_TRUE(contains(read("verdict.json"), "\"conforms\": false")) << read("verdict.json");
    EXPECT_TRUE(contains(read("verdict.md"), "| watertight | FAIL |")) << read("verdict.md");
    // Every kept case replays as a failure on the plugin, and has its picture.
    std::size_t kept = 0;
    for (const auto& entry : std::filesystem::directory_iterator(found)) {
        if (entry.path().extension() != ".tri") continue;
        ++kept;
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(entry.path()).replace_extension(".png")));
        const Result replayed = rast("replay --engine plugin:" + kNaive + " " + entry.path().string());
        EXPECT_EQ(replayed.status, 1) << replayed.out;
    }
    EXPECT_GE(kept, 3u);
}

// Run from a folder with no corpus/, a build run in its build tree takes the corpus of its source tree (an
// installed one, the installed corpus): conform's battery and replay's cases are not left empty.
TEST_F(PluginCommands, AwayFromTheSourceTreeTheCorpusIsStillFound) {
    const std::string here = "cd " + shell_word(dir.string()) + " && " + RAST_BINARY + " ";
    Result r = run(here + "conform " + kNaive + " --cases 1 --found " + out("found") + " 2>&1");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_TRUE(contains(r.out, " corpus cases (" RAST_CORPUS "), then 1 generated case a property")) << r.out;
    r = run(here + "replay --engine plugin:" + kNaive + " 2>&1");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "FAIL " RAST_CORPUS "/tie-rule/")) << r.out;
}

TEST_F(PluginCommands, ConformPassesTheFixedPathOnTheScenesGiven) {
    const std::string scene = file("split-square.tri", "# properties: watertight\n" + kSplitSquare);
    const Result r = rast("conform " + kFixed8 + " " + scene + " --found " + out("found"));
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "judged:   1 scene given\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "PASS watertight (1 scene)\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "PASS conforms (1 scene)\n")) << r.out;
    // The properties the scene does not claim judge nothing.
    EXPECT_TRUE(contains(r.out, "SKIP tie_rule (no scene it applies to)\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "2 passed, 0 failed, 8 skipped\n")) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir / "found"));
}

TEST_F(PluginCommands, ConformKeepsTheSceneAPluginCrashedOn) {
    const std::string scene = file("split-square.tri", kSplitSquare);
    const Result r = rast("conform " + misbehaving("crash") + " " + scene + " --found " + out("found"));
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_TRUE(contains(r.out, "crashed (signal 11, Segmentation fault) rendering a scene of 2 triangles")) << r.out;
    const std::string prefix = "; the scene is kept in ";
    const std::size_t at = r.out.find(prefix + out("found") + "/misbehaving-engine-error-");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::size_t begin = at + prefix.size();
    const std::string kept = r.out.substr(begin, r.out.find(' ', begin) - begin);
    const Result again = rast("replay --engine plugin:" + misbehaving("crash") + " " + kept);
    EXPECT_EQ(again.status, 2) << again.out;
    EXPECT_TRUE(contains(again.out, "crashed (signal 11, Segmentation fault) rendering a scene of 2 triangles"))
        << again.out;
}

TEST_F(PluginCommands, ConformRefusesABadShard) {
    for (const char* shard : {"0/4", "5/4", "2", "1/0", "a/b"}) {
        const Result r = rast("conform " + kFixed8 + " --shard " + shard);
        EXPECT_EQ(r.status, 2) << shard << ": " << r.out;
        EXPECT_TRUE(contains(r.out, "expected K/N with 1 <= K <= N")) << r.out;
    }
}

// The battery's options with scenes given would be ignored, and a seed not in decimal digits would be read
// wrongly: both refused. An empty --found, a file, or one that cannot be made is refused before the plugin
// is even loaded.
TEST_F(PluginCommands, ConformRefusesWhatItWouldIgnoreOrCouldNotWrite) {
    const std::string scene = file("split-square.tri", kSplitSquare);
    for (const std::string& option : {std::string("--cases 5"), std::string("--seed 5"), std::string("--shard 1/2"),
                                      "--corpus " + dir.string()}) {
        const Result r = rast("conform " + kFixed8 + " " + scene + " " + option);
        EXPECT_EQ(r.status, 2) << option << ": " << r.out;
        EXPECT_TRUE(contains(r.out, "SCENE excludes " + option.substr(0, option.find(' ')))) << r.out;
    }
    // CLI11 alone would wrap -1, saturate 2^64 and read 010 as octal.
    for (const std::string seed : {"-1", "+5", "0x10", "18446744073709551616", "1e3", "' 5'"}) {
        const Result r = rast("conform " + kFixed8 + " --seed " + seed + " --cases 1");
        EXPECT_EQ(r.status, 2) << seed << ": " << r.out;
        EXPECT_TRUE(contains(r.out, "--seed: a seed is a whole number from 0 to 18446744073709551615 in decimal digits, "
                                    "got "))
            << r.out;
    }
    for (const std::string cases : {"-5", "100000001", "010x"}) {
        const Result r = rast("conform " + kFixed8 + " --cases " + cases);
        EXPECT_EQ(r.status, 2) << cases << ": " << r.out;
        EXPECT_TRUE(contains(r.out, "--cases: a count of cases is a whole number from 0 to 100000000 in decimal digits"))
            << r.out;
    }
    const Result empty = rast("conform " + misbehaving("crash") + " " + scene + " --found ''");
    EXPECT_EQ(empty.status, 2) << empty.out;
    EXPECT_TRUE(contains(empty.out, "--found: the path is empty")) << empty.out;
    Result found = rast("conform " + misbehaving("crash") + " " + scene + " --found " + scene + "/found");
    EXPECT_EQ(found.status, 2) << found.out;
    EXPECT_TRUE(contains(found.out, "--found '" + scene + "/found': its parent '" + scene + "' is not a folder"))
        << found.out;
    found = rast("conform " + misbehaving("crash") + " " + scene + " --found " + scene);
    EXPECT_EQ(found.status, 2) << found.out;
    EXPECT_TRUE(contains(found.out, "--found '" + scene + "': exists and is not a folder")) << found.out;
}

#ifdef RAST_WITH_BENCH
// A plugin measured beside rast's engines: its own rows, ids compared with the reference, no depth columns.
TEST_F(PluginCommands, BenchMeasuresAPluginBesideRastsEngines) {
    const Result r = rast("bench --quick --only hard --engine plugin:" + kNaive);
    ASSERT_EQ(r.status, 0) << r.out;
    // Vertices on pixel centres put samples on edges, where ">= 0" and "<=" give other ids than the rule.
    const std::size_t row = r.out.find("| vertices on centres | plugin:naive | 4096 | — | — | ");
    ASSERT_NE(row, std::string::npos) << r.out;
    const std::string line = r.out.substr(row, r.out.find('\n', row) - row);
    EXPECT_TRUE(line.ends_with("| — | — | — |")) << line;  // depths, worst depth error, watertightness
    EXPECT_EQ(line.find("| 0 | — |"), std::string::npos) << line;  // some ids differ
    const Result refused = rast("bench --quick --only hard --engine fast");
    EXPECT_EQ(refused.status, 2) << refused.out;
    EXPECT_TRUE(contains(refused.out, "expected plugin:PATH")) << refused.out;
}
#endif

}  // namespace
}  // namespace rast::cli::testing
