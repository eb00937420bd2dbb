// A plugin runs as an engine, and every way a plugin can go wrong ends in an EngineError that names the
// library and says what happened, with rast (this test process) unharmed.
#include <rast/engine.h>
#include <rast/plugin_engine.h>

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace rast {
namespace {

std::string misbehaving(const std::string& way) {
    return std::string(RAST_TEST_PLUGINS) + "/misbehaving-" + way + ".so";
}

Scene one_triangle(int samples = 1) {
    return {{4, 3}, samples, {Triangle{{Vertex{0, 0, 0.5}, Vertex{4, 0, 0.5}, Vertex{0, 3, 0.5}}}}};
}

// The EngineError's message from loading `library` and rendering one_triangle() with it; "" if none.
std::string failure(const std::string& library, double timeout = 60, int samples = 1) {
    try {
        plugin_engine(library, {timeout}).render(one_triangle(samples));
    } catch (const EngineError& e) {
        return e.what();
    }
    return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(PluginEngine, RendersWhatTheFastPathRenders) {
    const Engine plugin = plugin_engine(RAST_FIXED8_PLUGIN);
    EXPECT_EQ(plugin.kind, Engine::Kind::plugin);
    EXPECT_EQ(plugin.name, "fixed8");
    EXPECT_EQ(plugin.contract->text(), "name=fixed8 samples=1,4,8,16 snap=8 rounding=nearest-even ties=top-left depth=zid");
    EXPECT_TRUE(plugin.exact());
    EXPECT_FALSE(plugin.writes_depth());
    for (int samples : {1, 4, 16}) {
        Scene scene = one_triangle(samples);
        scene.triangles.push_back(Triangle{{Vertex{4, 3, 0.25}, Vertex{0.3, 1.7, 0.75}, Vertex{2.2, 0, 0.75}}});
        EXPECT_EQ(plugin.render(scene).ids, fast_engine(fast::Precision::fixed8).render(scene).ids);
    }
    // Inside x/4 + y/3 < 1: at y = 0.5 the centres x < 3.33, at 1.5 x < 2, at 2.5 x < 0.67.
    const std::vector<std::size_t> covered = plugin.covered_samples(one_triangle().triangles[0], {4, 3}, 1);
    EXPECT_EQ(covered, (std::vector<std::size_t>{0, 1, 2, 4, 5, 8}));
}

TEST(PluginEngine, ALibraryThatDoesNotLoadIsNamed) {
    const std::string missing = failure("/nonexistent/plugin.so");
    EXPECT_TRUE(has(missing, "plugin /nonexistent/plugin.so: cannot load it: ")) << missing;
    EXPECT_TRUE(has(failure(misbehaving("crash_on_load")),
                    "plugin " + misbehaving("crash_on_load") + ": crashed (signal 11, Segmentation fault) loading it"))
        << failure(misbehaving("crash_on_load"));
}

TEST(PluginEngine, AMissingSymbolOrAnotherVersionIsRefused) {
    EXPECT_EQ(failure(misbehaving("no_render")), "plugin " + misbehaving("no_render") +
                                                     ": it does not export rast_plugin_render (with C linkage: "
                                                     "extern \"C\")");
    EXPECT_EQ(failure(misbehaving("wrong_version")),
              "plugin " + misbehaving("wrong_version") +
                  ": rast_plugin_abi_version() returned 2; this rast speaks version 1");
}

TEST(PluginEngine, AMalformedContractIsRefusedNamingTheKey) {
    EXPECT_EQ(failure(misbehaving("null_contract")),
              "plugin " + misbehaving("null_contract") + ": rast_plugin_contract() returned NULL");
    EXPECT_EQ(failure(misbehaving("unknown_key")),
              "plugin " + misbehaving("unknown_key") +
                  ": rast_plugin_contract() \"name=bad samples=1 snap=none ties=top-left depth=zid colour=red\": "
                  "contract key 'colour': unknown (known: name, samples, snap, rounding, ties, depth)");
    EXPECT_TRUE(has(failure(misbehaving("bad_value")),
                    "contract key 'rounding': 'sideways' is not nearest-even, floor or any"));
}

TEST(PluginEngine, ARenderErrorCarriesThePluginsMessage) {
    EXPECT_EQ(failure(misbehaving("render_error")),
              "plugin " + misbehaving("render_error") +
                  " returned an error rendering a scene of 1 triangles, 4x3, 1 sample(s): the scene has 1 "
                  "triangles and I draw none");
}

TEST(PluginEngine, ACrashOrAnExitIsReportedAndRepeated) {
    const Engine crashing = plugin_engine(misbehaving("crash"));
    EXPECT_EQ(crashing.render(Scene{{2, 2}, 1, {}}).ids, Samples<std::int32_t>(4, -1));  // alive until a triangle
    const std::string expected = "plugin " + misbehaving("crash") +
                                 ": crashed (signal 11, Segmentation fault) rendering a scene of 1 triangles, "
                                 "4x3, 1 sample(s)";
    for (int k = 0; k < 2; ++k) {  // the process is gone: a second render repeats the error
        try {
            crashing.render(one_triangle());
            ADD_FAILURE() << "no error";
        } catch (const EngineError& e) {
            EXPECT_EQ(std::string(e.what()), expected);
        }
    }
    // 127 is also what a failed exec of the host gives; after loading, it is the plugin's.
    EXPECT_EQ(failure(misbehaving("exit")), "plugin " + misbehaving("exit") +
                                                ": exited with status 127 rendering a scene of 1 triangles, 4x3, 1 "
                                                "sample(s)");
}

TEST(PluginEngine, AHangIsStoppedAtTheTimeout) {
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(failure(misbehaving("hang"), 0.3),
              "plugin " + misbehaving("hang") +
                  ": no answer within 0.3 s rendering a scene of 1 triangles, 4x3, 1 sample(s); stopped it "
                  "(--plugin-timeout)");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

TEST(PluginEngine, APluginThatClosesItsSocketAndHangsIsStopped) {
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(failure(misbehaving("close_and_hang"), 0.3),
              "plugin " + misbehaving("close_and_hang") +
                  ": closed its socket rendering a scene of 1 triangles, 4x3, 1 sample(s) and did not end; stopped it");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

TEST(PluginEngine, AnIdOutOfRangeIsAnError) {
    EXPECT_EQ(failure(misbehaving("id_out_of_range")),
              "plugin " + misbehaving("id_out_of_range") +
                  " wrote id 1 at pixel (3, 2) sample 0 of a scene of 1 triangles (ids are -1..triangles-1)");
}

TEST(PluginEngine, ASampleCountOutsideTheContractIsAnError) {
    EXPECT_EQ(failure(misbehaving("prints"), 60, 8),
              "plugin " + misbehaving("prints") +
                  " (misbehaving) does not render 8 samples a pixel (its contract: name=misbehaving samples=1,4 "
                  "snap=none ties=top-left depth=zid)");
}

}  // namespace
}  // namespace rast
