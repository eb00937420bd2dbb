// rast conform's machinery on engines that keep their contracts and on one that does not: no false
// alarm on the fast path's plugins, and each of the tutorial rasterizer's faults caught on a small scene.
#include <rast/conform.h>
#include <rast/plugin_engine.h>
#include <rast/tri_format.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

namespace rast::conform {
namespace {

namespace fs = std::filesystem;

std::vector<Case> corpus() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(RAST_CORPUS_DIR))
        if (entry.path().extension() == ".tri" && entry.path().string().find("/found/") == std::string::npos)
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::vector<Case> cases;
    for (const auto& f : files) cases.push_back(read_case(f));
    return cases;
}

class Conform : public ::testing::Test {
protected:
    void SetUp() override {
        found = fs::temp_directory_path() /
                ("rast_conform_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(found);
    }
    void TearDown() override { fs::remove_all(found); }
    fs::path found;
};

// Six triangles told apart by their first x, 0 .. 5.
Scene six_triangles() {
    Scene s{{4, 4}, 1, {}};
    for (int k = 0; k < 6; ++k) s.triangles.push_back(Triangle{{Vertex{double(k), 0, 0}, Vertex{1, 0, 0}, Vertex{0, 1, 0}}});
    return s;
}

// Fails while triangles 1 and 4 are both there.
bool has_1_and_4(const Scene& scene) {
    int seen = 0;
    for (const Triangle& t : scene.triangles) seen += t.v[0].x == 1 || t.v[0].x == 4;
    return seen == 2;
}

TEST(DropTriangles, KeepsOnlyWhatTheFailureNeeds) {
    const Scene shrunk = drop_triangles(six_triangles(), has_1_and_4);
    ASSERT_EQ(shrunk.triangles.size(), 2u);
    EXPECT_EQ(shrunk.triangles[0].v[0].x, 1);
    EXPECT_EQ(shrunk.triangles[1].v[0].x, 4);
}

// Lines keep their place in file order: lines at ids 0, 3 and 7 among six triangles (ids 1, 2, 4, 5, 6,
// 8). With triangles 1 and 4 (ids 2 and 6) kept, the file reads line, triangle 1, line, triangle 4, line:
// the lines are ids 0, 2 and 4, the triangles 1 and 3.
TEST(DropTriangles, RenumbersTheLinesAfterWhatItDrops) {
    Scene s = six_triangles();
    s.lines = {{Segment{}, 0}, {Segment{}, 3}, {Segment{}, 7}};
    const Scene shrunk = drop_triangles(s, has_1_and_4);
    ASSERT_EQ(shrunk.triangles.size(), 2u);
    ASSERT_EQ(shrunk.lines.size(), 3u);
    EXPECT_EQ(shrunk.lines[0].id, 0);
    EXPECT_EQ(shrunk.lines[1].id, 2);
    EXPECT_EQ(shrunk.lines[2].id, 4);
    EXPECT_EQ(triangle_ids(shrunk), (std::vector<std::int32_t>{1, 3}));
}

TEST(CaseSeed, DiffersForEveryShardAndProperty) {
    std::set<std::uint64_t> seeds;
    for (int shard = 0; shard < 8; ++shard)
        for (const char* p : {"conforms", "watertight", "tie_rule"}) seeds.insert(case_seed(1, shard, p));
    EXPECT_EQ(seeds.size(), 24u);
    EXPECT_EQ(case_seed(5, 2, "conforms"), case_seed(5, 2, "conforms"));
}

TEST_F(Conform, TheFixedPathPluginsConformOnTheCorpusAndGeneratedCases) {
    const std::vector<Case> cases = corpus();
    for (const char* name : {"fixed4", "fixed8", "fixed16"}) {
        const Engine plugin = plugin_engine(std::string(RAST_PLUGINS) + "/rast-plugin-" + name + ".so");
        Options options;
        options.cases = 40;
        options.found = found;
        const Verdict v = battery(plugin, cases, options);
        EXPECT_TRUE(v.conforms()) << name;
        std::set<std::string> judged;
        for (const PropertyVerdict& p : v.properties) {
            judged.insert(p.property);
            EXPECT_FALSE(p.failure) << name << " " << p.property << ": " << p.failure->detail;
            EXPECT_GE(p.checked, 40u) << name << " " << p.property;
        }
        EXPECT_EQ(judged, (std::set<std::string>{"watertight", "tie_rule", "winding_invariance",
                                                 "translation_invariance", "order_independence",
                                                 "fixed_matches_reference", "msaa_counts", "area_tiling",
                                                 "conforms", "msaa_visible_bound"}))
            << name;
    }
    EXPECT_FALSE(fs::exists(found));  // nothing to keep
}

TEST_F(Conform, TheTutorialRasterizerFailsThreePropertiesOnSmallScenes) {
    const std::string library = std::string(RAST_PLUGINS) + "/rast-plugin-naive.so";
    const Engine naive = plugin_engine(library);
    Options options;
    options.cases = 100;
    options.found = found;
    options.engine_option = "plugin:" + library;
    const Verdict v = battery(naive, corpus(), options);
    EXPECT_FALSE(v.conforms());
    std::size_t failed = 0;
    for (const PropertyVerdict& p : v.properties) {
        if (!p.failure) continue;
        ++failed;
        EXPECT_LE(p.failure->scene.triangles.size(), 4u) << p.property << " from " << p.failure->origin;
        ASSERT_TRUE(fs::exists(p.failure->kept)) << p.property;
        // The kept case names the property and fails it again on the engine.
        const Case kept = read_case(p.failure->kept);
        EXPECT_EQ(kept.claims, (std::vector<std::string>{p.property}));
        EXPECT_TRUE(properties::property(p.property).verdict_on(kept.scene, naive).failed()) << p.property;
        EXPECT_EQ(p.failure->kept.filename().string().rfind("naive-" + p.property + "-", 0), 0u);
    }
    EXPECT_GE(failed, 3u);
}

// The careful engine was written from the lecture and the specs without rast's code (careful.c): it must
// pass the battery that catches each of its seeded defects.
TEST_F(Conform, AnIndependentEngineConformsAndEachSeededDefectIsCaught) {
    const std::vector<Case> cases = corpus();
    Options options;
    options.cases = 40;
    options.found = found;
    const Verdict careful = battery(plugin_engine(std::string(RAST_TEST_PLUGINS) + "/careful.so"), cases, options);
    for (const PropertyVerdict& p : careful.properties) {
        EXPECT_FALSE(p.failure) << p.property << ": " << p.failure->detail;
        EXPECT_GE(p.checked, 40u) << p.property;
    }
    for (const char* defect :
         {"ties_bottom_right", "snap_truncate", "last_wins_tie", "ids_off_by_one", "top_row_unwritten",
          "culls_clockwise"}) {
        const Verdict v =
            battery(plugin_engine(std::string(RAST_TEST_PLUGINS) + "/careful-" + defect + ".so"), cases, options);
        const auto conforms = std::find_if(v.properties.begin(), v.properties.end(),
                                           [](const PropertyVerdict& p) { return p.property == "conforms"; });
        ASSERT_NE(conforms, v.properties.end());
        ASSERT_TRUE(conforms->failure) << defect;
        EXPECT_LE(conforms->failure->scene.triangles.size(), 4u) << defect;
        EXPECT_TRUE(fs::exists(conforms->failure->kept)) << defect;
    }
}

// A plugin that crashes on a generated scene ends the battery with the failure, the scene kept: it does
// not pass for want of an answer.
TEST_F(Conform, AnEngineThatCrashesOnAGeneratedSceneEndsTheBattery) {
    const std::string library = std::string(RAST_TEST_PLUGINS) + "/misbehaving-crash.so";
    Options options;
    options.cases = 20;
    options.found = found;
    try {
        battery(plugin_engine(library), {}, options);
        ADD_FAILURE() << "the battery passed a plugin that crashes on every triangle";
    } catch (const EngineFailure& e) {
        EXPECT_NE(std::string(e.what()).find("crashed (signal 11"), std::string::npos) << e.what();
        ASSERT_TRUE(fs::exists(e.kept));
        const Case kept = read_case(e.kept);
        EXPECT_FALSE(kept.scene.triangles.empty());
        EXPECT_EQ(kept.claims.back(), "conforms");
    }
}

#ifdef RAST_LLVMPIPE_PLUGIN
// llvmpipe keeps snap=8 rounding=any ties=top-left depth=none wherever GL's float vertices resolve the
// 1/256 grid: on every corpus case whose coordinates stay below 2^15 pixels. (Past that, float rounding
// and GL's clipper move its edges further: README.md gives its verdict on the whole battery.)
TEST_F(Conform, LlvmpipeKeepsItsContractWhereFloatsResolveTheGrid) {
    std::vector<Case> within;
    for (Case& c : corpus()) {
        bool small = true;
        for (const Triangle& t : c.scene.triangles)
            for (const Vertex& v : t.v) small = small && std::abs(v.x) < 32768 && std::abs(v.y) < 32768;
        if (small) within.push_back(std::move(c));
    }
    ASSERT_GT(within.size(), 50u);
    const Engine llvmpipe = plugin_engine(RAST_LLVMPIPE_PLUGIN);
    Options options;
    options.found = found;
    const Verdict v = judge(llvmpipe, within, options);
    for (const PropertyVerdict& p : v.properties) {
        EXPECT_FALSE(p.failure) << p.property << ": " << p.failure->detail << " (" << p.failure->origin << ")";
        EXPECT_GT(p.checked, 0u) << p.property;
    }
}
#endif

}  // namespace
}  // namespace rast::conform
