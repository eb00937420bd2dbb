// The plan of `rast bench`: which scenes, which engines, how many runs; and the run itself. Timing is in
// timing.h, error against the reference in engine_error.h and aa_error.h, formatting in report_*.cpp.
#include <rast/bench_run.h>

#include "engine_error.h"
#include "line_bench.h"
#include "llvmpipe_timing.h"
#include "timing.h"

#include <rast/bench_scenes.h>
#include <rast/fast.h>
#include <rast/mesh.h>
#include <rast/reference.h>
#include <rast/visible_area.h>

#include <unistd.h>

#include <array>
#include <chrono>
#include <ctime>
#include <exception>
#include <fstream>
#include <functional>
#include <memory>
#include <ostream>
#include <span>
#include <string>

namespace rast::bench {
namespace {

constexpr std::array kModes{fast::Precision::fixed4, fast::Precision::fixed8, fast::Precision::fixed16,
                            fast::Precision::float32, fast::Precision::float64};
constexpr std::array kThreads{1, 2};
constexpr std::array kSampleCounts{1, 4, 8, 16};

// Sizes and repetitions: every engine renders exactly the same triangles, `runs` rounds of them.
struct Plan {
    Viewport viewport;
    std::size_t scale;  // triangle counts are multiples of this
    std::size_t runs;
    Viewport hard_viewport;
    std::size_t hard_triangles;
    Viewport aa_viewport;
    std::size_t aa_triangles;
    double line_budget;  // pixels of segment length per line scene
};

Plan plan_for(bool quick) {
    if (quick) return {{256, 256}, 1, 3, {64, 64}, 100, {64, 64}, 20, 2e4};
    return {{1024, 1024}, 20, 9, {256, 256}, 2000, {256, 256}, 300, 4e5};
}

struct BenchScene {
    SceneInfo info;
    Scene scene;
    bool shared_edges = false;  // a mesh, where watertightness is measured
};

BenchScene generated(std::string name, const SceneSpec& spec, int samples = 1) {
    Scene scene = make_scene(spec);
    scene.samples = samples;
    const bool shared = spec.shape == Shape::mesh || spec.shape == Shape::fan;
    return {{std::move(name), "generated " + describe(spec), scene.triangles.size(), spec.viewport, samples, {}},
            std::move(scene),
            shared};
}

// The exact visible area of a scene on two threads, timed once (it is exact: every run gives the same),
// its cost kept in the report.
reference::VisibleArea time_visible_area(const std::string& name, const Scene& scene, Report& report) {
    constexpr unsigned kVisibleThreads = 2;
    VisibleCostRow row{name, scene.viewport, scene.triangles.size(), {}, kVisibleThreads, 0};
    const auto start = std::chrono::steady_clock::now();
    reference::VisibleArea visible = reference::visible_area(scene, {}, kVisibleThreads, &row.stats);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report.visible_cost.push_back(row);
    return visible;
}

BenchScene mesh_scene(const std::filesystem::path& path, Viewport vp, int samples) {
    const Mesh mesh = read_mesh(path);
    Scene scene = project(mesh, frame(mesh, vp), vp, samples);
    return {{"bunny", path.filename().string() + ", projected by rast::frame's camera", scene.triangles.size(), vp,
             samples, {}},
            std::move(scene),
            true};
}

// Depths are separated (each triangle its own band of z) on the speed scenes: llvmpipe's 24-bit depth
// buffer would otherwise blur its id buffer with depth ties that have nothing to do with coverage.
std::vector<BenchScene> main_scenes(const Config& config, const Plan& plan) {
    const auto spec = [&](Shape shape, std::size_t triangles) {
        return SceneSpec{.shape = shape, .triangles = triangles * plan.scale, .viewport = plan.viewport,
                         .depth = Depth::separated};
    };
    std::vector<BenchScene> scenes;
    scenes.push_back(generated("tiny", spec(Shape::tiny, 5000)));
    scenes.push_back(generated("small", spec(Shape::small, 5000)));
    scenes.push_back(generated("medium", spec(Shape::medium, 500)));
    scenes.push_back(generated("large", spec(Shape::large, 50)));
    scenes.push_back(generated("needle", spec(Shape::needle, 500)));
    scenes.push_back(generated("huge", spec(Shape::huge, 100)));
    scenes.push_back(mesh_scene(config.mesh, plan.viewport, 1));
    scenes.push_back(generated("grid", spec(Shape::mesh, 5000)));
    scenes.push_back(generated("fans", spec(Shape::fan, 1000)));
    return scenes;
}

std::vector<BenchScene> hard_families(const Plan& plan) {
    const auto spec = [&](Shape shape) {
        return SceneSpec{.shape = shape, .triangles = plan.hard_triangles, .viewport = plan.hard_viewport,
                         .depth = Depth::separated};
    };
    return {generated("needles", spec(Shape::needle)), generated("huge coordinates", spec(Shape::huge)),
            generated("subnormals (16x)", spec(Shape::subnormal), 16),
            generated("vertices on centres", spec(Shape::centre_edges)),
            generated("near zero area", spec(Shape::sliver))};
}

SpeedRow speed_row(const SceneInfo& scene, std::string engine, int threads, std::vector<double> seconds) {
    const Spread s = spread(std::move(seconds));
    return {scene.name, std::move(engine), threads, s.median, s.min, s.max, s.runs,
            static_cast<double>(scene.triangles) / s.median, static_cast<double>(scene.fragments.value_or(0)) / s.median};
}

// `depths`: whether the engine writes depths to compare (a plugin does not).
ErrorRow error_row(const SceneInfo& scene, std::string engine, const BufferDifference& buffers, bool depths = true) {
    ErrorRow row;
    row.scene = scene.name;
    row.engine = std::move(engine);
    row.samples = static_cast<std::uint64_t>(scene.viewport.width) * static_cast<std::uint64_t>(scene.viewport.height) *
                  static_cast<std::uint64_t>(scene.samples);
    row.ids_differing = buffers.ids;
    if (depths) {
        row.depths_differing = buffers.depths;
        row.worst_depth_error = buffers.worst_depth;
    }
    return row;
}

// One engine at one thread count, timed on a scene: run() renders once and answers the seconds it took.
struct Contender {
    std::string engine;
    int threads;
    std::function<double()> run;
    std::vector<double> seconds;
    std::string failed;  // why it stopped (llvmpipe's child process can), or empty
};

// Timed in rounds, every contender once a round, so that the shared machine's drift over the minutes of a
// run weighs on all of them alike and their medians can be compared. llvmpipe's child process reports a
// failure as std::runtime_error, which stops that contender alone; anything else (the fast path's
// invalid_argument, bad_alloc) ends the run, as it did before the rounds.
void time_in_rounds(std::vector<Contender>& contenders, std::size_t rounds) {
    for (std::size_t k = 0; k < rounds; ++k)
        for (Contender& c : contenders) {
            if (!c.failed.empty()) continue;
            try {
                c.seconds.push_back(c.run());
            } catch (const std::runtime_error& e) {
                c.failed = e.what();
            }
        }
}

// Speed of every engine and thread count, then each one's error against the reference's framebuffer.
// With `time` false (the hard cases) every engine renders once, untimed.
void measure(BenchScene& s, const Plan& plan, std::span<const Engine> plugins, bool time, std::vector<SpeedRow>& speed,
             std::vector<ErrorRow>& errors, std::vector<std::string>& notes, std::ostream& progress) {
    const Scene& scene = s.scene;
    progress << "[" << s.info.name << "] " << scene.triangles.size() << " triangles: reference" << std::flush;
    // Rendered once untimed, the baseline of every error (and the warm-up); then timed in the rounds,
    // each time into a framebuffer of its own, as reference::render makes it.
    reference::Stats stats;
    const Framebuffer exact = reference_engine(&stats).render(scene);
    s.info.fragments = stats.samples_covered;

    const std::span<const int> thread_counts = time ? std::span<const int>(kThreads) : std::span<const int>();
    std::vector<Contender> contenders;
    if (time) {
        const Engine reference = reference_engine();
        contenders.push_back(
            {reference.name, 1, [&scene, reference] { return seconds_of([&] { reference.render(scene); }); }, {}, {}});
    }
    std::vector<ErrorRow> rows;
    // Each mode's result, rendered once untimed, then timed into it by an engine per thread count, which
    // keeps its working memory from round to round, as llvmpipe draws into its context's with the
    // context's memory. Each contender's first render is an untimed warm-up.
    std::vector<Engine> modes;
    std::vector<Framebuffer> results;
    results.reserve(kModes.size());
    for (const fast::Precision mode : kModes) {
        progress << ", " << fast::name(mode) << std::flush;
        const Engine& once = modes.emplace_back(fast_engine(mode));
        Framebuffer& result = results.emplace_back(once.render(scene));
        rows.push_back(error_row(s.info, once.name, compare_buffers(exact, result)));
        for (const int threads : thread_counts) {
            const Engine engine = fast_engine(mode, threads);
            engine.draw(scene, result);
            contenders.push_back({engine.name, threads,
                                  [&scene, &result, engine] { return seconds_of([&] { engine.draw(scene, result); }); },
                                  {}, {}});
        }
    }
    // Plugins (--engine plugin:PATH), one thread as far as rast knows: ids only, so no coverage columns.
    std::vector<Framebuffer> plugin_results;
    plugin_results.reserve(plugins.size());
    for (const Engine& plugin : plugins) {
        if (plugin.contract && !plugin.contract->renders(scene.samples)) continue;
        const std::string label = "plugin:" + plugin.name;  // apart from rast's own engine of that name
        progress << ", " << label << std::flush;
        Framebuffer& result = plugin_results.emplace_back(plugin.render(scene));
        rows.push_back(error_row(s.info, label, compare_buffers(exact, result), plugin.writes_depth()));
        if (time)
            contenders.push_back({label, 1,
                                  [&scene, &result, plugin] { return seconds_of([&] { plugin.draw(scene, result); }); },
                                  {}, {}});
    }
    // llvmpipe in child processes, one per thread count, each kept or skipped on its own; the first
    // thread count's draw gives the error (untimed, it is the only one).
    std::vector<std::unique_ptr<LlvmpipeChild>> llvmpipe;
    if (scene.samples == 1) {
        progress << ", llvmpipe" << std::flush;
        for (const int threads : time ? thread_counts : std::span<const int>(kThreads).first(1)) {
            try {
                LlvmpipeChild& child = *llvmpipe.emplace_back(std::make_unique<LlvmpipeChild>(scene, threads));
                if (threads == kThreads.front())
                    rows.push_back(error_row(s.info, "llvmpipe", compare_buffers(exact, child.result())));
                contenders.push_back({"llvmpipe", threads, [&child] { return child.draw(); }, {}, {}});
            } catch (const std::exception& e) {
                notes.push_back("llvmpipe on " + std::to_string(threads) + " threads skipped on " + s.info.name +
                                ": " + e.what());
                progress << " (skipped on " << threads << " threads: " << e.what() << ")";
            }
        }
    }
    if (time) {
        progress << ", timing" << std::flush;
        time_in_rounds(contenders, plan.runs);
        for (Contender& c : contenders) {
            if (c.failed.empty()) {
                speed.push_back(speed_row(s.info, c.engine, c.threads, std::move(c.seconds)));
            } else {
                notes.push_back(c.engine + " on " + std::to_string(c.threads) + " threads not timed on " + s.info.name +
                                ": " + c.failed);
            }
        }
    }
    progress << ", coverage" << std::flush;
    const auto coverage = compare_coverage(scene, modes, s.shared_edges);
    for (std::size_t m = 0; m < kModes.size(); ++m) {
        rows[m].misclassified = coverage[m].samples;
        rows[m].triangles_affected = coverage[m].triangles;
        rows[m].watertight_violations = coverage[m].watertight;
    }
    errors.insert(errors.end(), rows.begin(), rows.end());
    progress << '\n';
}

double load_average() {
    std::ifstream in("/proc/loadavg");
    double load = 0;
    in >> load;
    return load;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown";
}

std::string utc_now() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

}  // namespace

Report run_bench(const Config& config, std::ostream& progress) {
    const Plan plan = plan_for(config.quick);
    Report report;
    report.command = config.command;
    report.quick = config.quick;
    report.machine = {cpu_model(), static_cast<unsigned>(sysconf(_SC_NPROCESSORS_ONLN)), load_average(), 0,
                      utc_now()};
    if (config.speed) {
        // A render runs at most fast::max_threads() threads: on a smaller machine the rows for more name
        // the count asked, not the count that ran.
        if (fast::max_threads() < kThreads.back())
            report.notes.push_back("this machine runs " + std::to_string(fast::max_threads()) +
                                   " fast-path thread(s): its rows for more threads ran on that many");
        for (BenchScene& s : main_scenes(config, plan)) {
            measure(s, plan, config.plugins, true, report.speed, report.errors, report.notes, progress);
            report.scenes.push_back(s.info);
        }
    }
    if (config.hard) {
        for (BenchScene& s : hard_families(plan)) {
            measure(s, plan, config.plugins, false, report.speed, report.hard_cases, report.notes, progress);
            report.hard_families.push_back(s.info);
        }
    }
    if (config.aa) {
        // Fat triangles of two sizes and a real mesh. Every pixel of each triangle's bounding box gets an
        // exact area, so the thin, long shapes (needles, slivers) would cost far more than they tell.
        // Depths are random at each vertex, so triangles that overlap interpenetrate; the
        // "interpenetrating" scene piles up ten times as many medium ones. The bunny also at a quarter of
        // the size, where several triangles share each pixel.
        const SceneSpec small{.shape = Shape::small, .triangles = plan.aa_triangles, .viewport = plan.aa_viewport};
        const SceneSpec medium{.shape = Shape::medium, .triangles = plan.aa_triangles / 10, .viewport = plan.aa_viewport};
        const SceneSpec piled{.shape = Shape::medium, .triangles = plan.aa_triangles, .viewport = plan.aa_viewport};
        const Viewport quarter{plan.aa_viewport.width / 4, plan.aa_viewport.height / 4};
        BenchScene dense = mesh_scene(config.mesh, quarter, 1);
        dense.info.name += " " + std::to_string(quarter.width) + "x" + std::to_string(quarter.height);
        std::vector<BenchScene> scenes{generated("small", small), generated("medium", medium),
                                       generated("interpenetrating", piled),
                                       mesh_scene(config.mesh, plan.aa_viewport, 1), std::move(dense)};
        for (BenchScene& s : scenes) {
            progress << "[antialiasing] " << s.info.name << '\n';
            for (const PatternError& e : pattern_errors(s.scene, kSampleCounts)) report.aa.push_back({s.info.name, e});
            const reference::VisibleArea visible = time_visible_area(s.info.name, s.scene, report);
            for (const VisibleError& e : visible_errors(s.scene, visible, kSampleCounts))
                report.visible_aa.push_back({s.info.name, e});
            report.aa_scenes.push_back(s.info);
        }
        for (const int n : kSampleCounts) report.discrepancy.emplace_back(n, halfplane_discrepancy(sample_pattern(n)));
        // How the cost grows with the triangles reaching a pixel: the small scene 4 and 16 times as dense;
        // and the bunny at 512 x 512.
        for (const std::size_t times : {4, 16}) {
            SceneSpec denser = small;
            denser.triangles *= times;
            const BenchScene s = generated("small x" + std::to_string(times), denser);
            progress << "[antialiasing] visible area of " << s.info.name << '\n';
            time_visible_area(s.info.name, s.scene, report);
        }
        const Viewport large{plan.aa_viewport.width * 2, plan.aa_viewport.height * 2};
        const BenchScene bunny = mesh_scene(config.mesh, large, 1);
        progress << "[antialiasing] visible area of the bunny at " << large.width << "x" << large.height << '\n';
        time_visible_area(bunny.info.name + " " + std::to_string(large.width) + "x" + std::to_string(large.height),
                          bunny.scene, report);
    }
    if (config.lines) {
        // Segments of three lengths, random in position and direction, the same set for every engine.
        const Viewport vp = plan.viewport;
        const std::pair<const char*, double> lengths[] = {{"short lines (4 px)", 4}, {"medium lines (32 px)", 32},
                                                          {"long lines (256 px)", 256}};
        for (const auto& [name, length] : lengths) {
            const std::size_t n = static_cast<std::size_t>(plan.line_budget / length);
            const std::vector<Segment> segments = make_segments(n, length, vp);
            for (LineRow& row : measure_lines(name, segments, vp, plan.runs, progress))
                report.lines.push_back(std::move(row));
        }
    }
    report.machine.load_after = load_average();
    return report;
}

}  // namespace rast::bench
