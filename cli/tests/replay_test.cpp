// The replay core against a deliberately broken fast path: a case that a failing property writes fails the
// same way when replayed, and passes once the engine is fixed.
#include "replay.h"

#include <rast/fast_faults.h>
#include <rast/tri_format.h>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;
using rast::cli::CaseReport;

using rast::fast::Fault;

// fixed8 with a bug injected: by default, bottom instead of top edges owning their samples.
rast::Engine broken_fixed8(Fault fault = Fault::wrong_tie_bias) {
    using rast::fast::Precision;
    rast::Engine engine = rast::fast_engine(Precision::fixed8);
    engine.draw = [fault](const rast::Scene& s, rast::Framebuffer& fb) {
        fb = rast::fast::render_with_fault(s, {Precision::fixed8, 1}, fault);
    };
    engine.covered_samples = [fault](const rast::Triangle& t, rast::Viewport vp, int n) {
        return rast::fast::covered_samples_with_fault(t, vp, n, Precision::fixed8, fault);
    };
    return engine;
}

// Two triangles sharing the horizontal line y = 1.5 through the centres (0.5, 1.5) .. (3.5, 1.5): the
// lower triangle's top edge owns them; the broken engine gives them to the upper triangle's bottom edge.
rast::Scene horizontal_split() {
    rast::Scene scene;
    scene.viewport = {4, 3};
    scene.triangles = {{{{{0.25, 1.5, 0}, {3.75, 1.5, 0}, {2, 2.75, 0}}}},
                       {{{{0.25, 1.5, 0}, {2, 0.25, 0}, {3.75, 1.5, 0}}}}};
    return scene;
}

// A directory of each test's own: ctest runs the tests of this file in parallel processes, and a shared
// one was emptied by one test under another's feet.
class Replay : public ::testing::Test {
protected:
    fs::path dir = fs::temp_directory_path() /
                   ("rast-replay-" + std::to_string(::getpid()) + "-" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    void SetUp() override {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
};

TEST_F(Replay, ACaseWrittenByAFailingPropertyFailsTheSameWayAndPassesAfterTheFix) {
    const rast::Engine broken = broken_fixed8();
    const auto outcome = rast::properties::property("tie_rule").check(horizontal_split(), broken);
    ASSERT_TRUE(outcome.failed());

    const fs::path file = dir / "tie_rule-broken.tri";
    rast::write_tri_file(file, horizontal_split(),
                         {{"properties", "tie_rule"}, {"why", "bottom edges own samples in the broken engine"}});

    const std::vector<rast::Engine> with_bug{rast::reference_engine(), broken};
    const CaseReport failing = rast::cli::replay_case(file, with_bug);
    ASSERT_EQ(failing.status, CaseReport::Status::fail) << failing.line;
    ASSERT_EQ(failing.failures.size(), 1u);
    EXPECT_EQ(failing.failures[0].property, "tie_rule");
    EXPECT_EQ(failing.failures[0].engine, "fixed8");
    EXPECT_EQ(failing.failures[0].detail, outcome.detail);
    EXPECT_EQ(failing.line, "FAIL " + file.string() + " tie_rule [fixed8]: " + outcome.detail);
    // The first differing sample is the centre (0.5, 1.5): on the shared line, owned by the lower triangle.
    EXPECT_NE(failing.line.find("at (0.5, 1.5)"), std::string::npos) << failing.line;

    const CaseReport fixed = rast::cli::replay_case(file, rast::all_engines());
    EXPECT_EQ(fixed.status, CaseReport::Status::pass) << fixed.line;
    // tie_rule applies to the exact engines: the reference and the three fixed modes.
    EXPECT_EQ(fixed.line,
              "PASS " + file.string() + " (1 property x 6 engines: 4 checks, 0 not applicable, 2 outside a contract)");
}

// corpus/filters keeps scenes on which a weakened error bound changes a framebuffer (docs/filters.md). The
// coplanar twins pass on every engine, and fail on the fast path with its depth planes' bounds halved:
// triangle 1 drawn at the centre (16.5, 17.5), where the depth tie belongs to triangle 0.
TEST_F(Replay, HalvedDepthBoundFailsTheCoplanarTwins) {
    const fs::path file = fs::path(RAST_CORPUS_DIR) / "filters" / "depth-halved-orders-coplanar-twins.tri";
    const CaseReport sound = rast::cli::replay_case(file, rast::all_engines());
    EXPECT_EQ(sound.status, CaseReport::Status::pass) << sound.line;
    const std::vector<rast::Engine> with_bug{rast::reference_engine(),
                                                        broken_fixed8(Fault::halved_depth_bound)};
    const CaseReport halved = rast::cli::replay_case(file, with_bug);
    ASSERT_EQ(halved.status, CaseReport::Status::fail) << halved.line;
    bool at_the_twins_sample = false;
    for (const auto& f : halved.failures)
        at_the_twins_sample =
            at_the_twins_sample ||
            (f.property == "fixed_matches_reference" && f.detail.find("(16.5, 17.5)") != std::string::npos);
    EXPECT_TRUE(at_the_twins_sample) << halved.line;
}

TEST_F(Replay, HeaderErrorsNameTheLine) {
    std::ofstream(dir / "unknown.tri") << "# why: a typo\n# properties: tie_rule watertigt\nviewport 2 2\n";
    std::ofstream(dir / "twice.tri") << "# properties: tie_rule tie_rule\nviewport 2 2\n";
    std::ofstream(dir / "none.tri") << "# why: forgot the properties\nviewport 2 2\n";
    std::ofstream(dir / "late.tri") << "viewport 2 2\n# properties: tie_rule\ntri 0 0 0  2 0 0  0 2 0\n";
    const auto engines = rast::all_engines();

    const CaseReport unknown = rast::cli::replay_case(dir / "unknown.tri", engines);
    EXPECT_EQ(unknown.status, CaseReport::Status::error);
    EXPECT_EQ(unknown.line.rfind("ERROR " + (dir / "unknown.tri").string() + ":2: unknown property 'watertigt'", 0),
              0u)
        << unknown.line;
    EXPECT_EQ(rast::cli::replay_case(dir / "twice.tri", engines).line,
              "ERROR " + (dir / "twice.tri").string() + ":1: property 'tie_rule' is named twice");
    EXPECT_EQ(rast::cli::replay_case(dir / "none.tri", engines).line,
              "ERROR " + (dir / "none.tri").string() +
                  ":1: no '# properties:' header naming the properties that apply");
    EXPECT_EQ(rast::cli::replay_case(dir / "late.tri", engines).line,
              "ERROR " + (dir / "late.tri").string() +
                  ":2: the '# properties:' header must come before the first statement");
}

// A case claims what its header names: a named property that no engine can check (translation by whole
// pixels with a vertex at 2^60, where no shift is exact), or a scene without triangles, tests nothing.
TEST_F(Replay, CasesThatTestNothingAreErrors) {
    std::ofstream(dir / "unchecked.tri") << "# why: a vertex at 2^60\n# properties: tie_rule translation_invariance\n"
                                            "viewport 8 8\ntri 0.5 0.5 0  7.5 0.5 0  0x1p+60 0x1.0000000000001p+60 0\n";
    std::ofstream(dir / "empty.tri") << "# properties: tie_rule\nviewport 2 2\n";
    const auto engines = rast::all_engines();
    EXPECT_EQ(rast::cli::replay_case(dir / "unchecked.tri", engines).line,
              "ERROR " + (dir / "unchecked.tri").string() +
                  ":2: a named property checks nothing (translation_invariance [reference]: no whole-pixel shift "
                  "keeps every coordinate exact)");
    EXPECT_EQ(rast::cli::replay_case(dir / "empty.tri", engines).line,
              "ERROR " + (dir / "empty.tri").string() + ": has no triangle and no line: it tests nothing");
    // Replayed on the reference alone, a float mode's property applies to no engine.
    std::ofstream(dir / "float.tri") << "# properties: float_within_bound\nviewport 2 2\ntri 0 0 0  2 0 0  0 2 0\n";
    EXPECT_EQ(rast::cli::replay_case(dir / "float.tri", std::vector{rast::reference_engine()}).line,
              "ERROR " + (dir / "float.tri").string() + ":1: checks nothing: no named property applies to any engine");
    // A folder given as a case (corpus_files lists folders, replay_case reads files).
    EXPECT_EQ(rast::cli::replay_case(dir, engines).line, "ERROR " + dir.string() + ": is a folder, not a case");
}

TEST_F(Replay, AFolderContributesItsCasesInPathOrder) {
    fs::create_directories(dir / "b");
    for (const char* name : {"b/z.tri", "b/a.tri", "a.tri", "notes.txt"}) std::ofstream(dir / name) << "\n";
    const std::vector<fs::path> given{dir / "b", dir / "a.tri"};
    EXPECT_EQ(rast::cli::corpus_files(given),
              (std::vector<rast::cli::CorpusEntry>{{dir / "b/a.tri", {}}, {dir / "b/z.tri", {}}, {dir / "a.tri", {}}}));
}

// In a child process that drops root (root may list any folder) to the user nobody: a folder it may not
// list is among the cases, in path order, with the reason, and replays as an error, and so do a case in a
// folder it may list but not enter, found there or given itself, a link to a case there and a link to
// nothing; a link to a folder and a FIFO are not cases. Exit code 0 means all of that held.
void list_beside_locked_folders(const fs::path& dir) {
    using rast::cli::CorpusEntry;
    if (::geteuid() == 0 && ::setuid(65534) != 0) std::_Exit(3);
    const std::vector<fs::path> given{dir};
    const fs::path locked = dir / "locked", unentered = dir / "unentered" / "case.tri";
    const std::vector<CorpusEntry> entries = rast::cli::corpus_files(given);
    if (entries != std::vector<CorpusEntry>{{dir / "a.tri", {}},
                                            {dir / "gone.tri", {}},
                                            {dir / "link.tri", {}},
                                            {locked, "Permission denied"},
                                            {unentered, {}},
                                            {dir / "z.tri", {}}})
        std::_Exit(1);
    const std::vector<fs::path> unentered_given{unentered};
    if (rast::cli::corpus_files(unentered_given) != std::vector<CorpusEntry>{{unentered, {}}}) std::_Exit(2);
    const auto engines = rast::all_engines();
    const std::string expected[] = {
        "ERROR " + (dir / "gone.tri").string() + ": cannot open: No such file or directory",
        "ERROR " + (dir / "link.tri").string() + ": cannot open: Permission denied",
        "ERROR " + locked.string() + ": cannot list the folder: Permission denied",
        "ERROR " + unentered.string() + ": cannot open: Permission denied"};
    for (std::size_t k = 0; k < std::size(expected); ++k) {
        const CaseReport report = rast::cli::replay_entry(entries[k + 1], engines);
        if (report.status != CaseReport::Status::error || report.line != expected[k]) std::_Exit(4);
    }
    std::_Exit(0);
}

TEST_F(Replay, FoldersThatCannotBeListedOrEnteredAreErrorsAndTheOthersStillRun) {
    for (const char* name : {"a.tri", "z.tri", "locked/hidden.tri", "unentered/case.tri"}) {
        fs::create_directories((dir / name).parent_path());
        std::ofstream(dir / name) << "\n";
    }
    fs::create_symlink("locked/hidden.tri", dir / "link.tri");
    fs::create_symlink("nowhere.tri", dir / "gone.tri");
    fs::create_directory_symlink("unentered", dir / "folder-link.tri");
    ASSERT_EQ(::mkfifo((dir / "pipe.tri").c_str(), 0644), 0);
    fs::permissions(dir / "locked", fs::perms::none);
    fs::permissions(dir / "unentered", fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    EXPECT_EXIT(list_beside_locked_folders(dir), ::testing::ExitedWithCode(0), "");
    for (const char* folder : {"locked", "unentered"}) fs::permissions(dir / folder, fs::perms::owner_all);
}

}  // namespace
