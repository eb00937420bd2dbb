// rast_bench_micro: the fast path, llvmpipe and the exact reference on the same generated scenes, as
// triangles/s and pixels/s. Pixels are the pixel centres covered by the scene's triangles, counted before
// the depth test (every engine produces the same fragments); times are wall-clock.
#include "llvmpipe_timing.h"

#include <rast/bench_scenes.h>
#include <rast/fast.h>
#include <rast/reference.h>

#include <benchmark/benchmark.h>

#include <cstdint>
#include <exception>
#include <map>
#include <string>
#include <vector>

namespace rast::bench {
namespace {

// Each scene is generated once, on first use, and shared by every engine's benchmark.
const Scene& scene_for(const SceneSpec& spec) {
    static std::map<std::string, Scene> scenes;
    auto [it, inserted] = scenes.try_emplace(describe(spec));
    if (inserted) it->second = make_scene(spec);
    return it->second;
}

std::uint64_t fragments(const SceneSpec& spec) {
    static std::map<std::string, std::uint64_t> counts;
    auto [it, inserted] = counts.try_emplace(describe(spec), 0);
    if (inserted) {
        const Scene& scene = scene_for(spec);
        for (const Triangle& t : scene.triangles) {
            it->second += fast::covered_samples(t, scene.viewport, 1, fast::Precision::fixed8).size();
        }
    }
    return it->second;
}

void set_rates(benchmark::State& state, const SceneSpec& spec) {
    using benchmark::Counter;
    state.counters["triangles/s"] = Counter(static_cast<double>(scene_for(spec).triangles.size()),
                                            Counter::kIsIterationInvariantRate);
    state.counters["pixels/s"] =
        Counter(static_cast<double>(fragments(spec)), Counter::kIsIterationInvariantRate);
}

void fast_path(benchmark::State& state, SceneSpec spec, fast::Precision precision, int threads) {
    const Scene& scene = scene_for(spec);
    const fast::Options options{precision, threads};
    Framebuffer fb;
    fast::Renderer renderer;
    try {
        renderer.render(scene, fb, options);  // warm-up, and a clear skip for a scene the engine rejects
        set_rates(state, spec);
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    // Into the kept framebuffer, with the kept working memory, as llvmpipe draws into its context's.
    for (auto _ : state) {
        renderer.render(scene, fb, options);
        benchmark::DoNotOptimize(fb.ids.data());
    }
}

void reference(benchmark::State& state, SceneSpec spec) {
    const Scene& scene = scene_for(spec);
    set_rates(state, spec);
    for (auto _ : state) {
        const Framebuffer fb = reference::render(scene);
        benchmark::DoNotOptimize(fb.ids.data());
    }
}

void llvmpipe(benchmark::State& state, SceneSpec spec, int threads) {
    std::vector<double> seconds;
    try {
        seconds = time_llvmpipe_draws(scene_for(spec), threads,
                                      static_cast<std::size_t>(state.max_iterations))
                      .seconds;
        set_rates(state, spec);
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    std::size_t k = 0;
    for (auto _ : state) state.SetIterationTime(seconds[k++]);
}

void register_benchmarks() {
    const SceneSpec scenes[] = {
        {.shape = Shape::tiny, .triangles = 10'000},
        {.shape = Shape::tiny, .triangles = 100'000},
        {.shape = Shape::tiny, .triangles = 1'000'000},
        {.shape = Shape::small, .triangles = 10'000},
        {.shape = Shape::small, .triangles = 100'000},
        {.shape = Shape::small, .triangles = 100'000, .on_grid_256 = true},
        {.shape = Shape::small, .triangles = 100'000, .depth = Depth::separated},  // rast bench's small scene
        {.shape = Shape::small, .triangles = 1'000'000},
        {.shape = Shape::medium, .triangles = 10'000},
        {.shape = Shape::medium, .triangles = 10'000, .depth = Depth::separated},  // rast bench's medium scene
        {.shape = Shape::medium, .triangles = 100'000},
        // Large triangles stop at 10^4: each frame is already 10^8 covered samples.
        {.shape = Shape::large, .triangles = 10'000},
        // rast bench's large scene: depth complexity 10 rather than 100, so hierarchical z culls little.
        {.shape = Shape::large, .triangles = 1'000, .depth = Depth::separated},
        {.shape = Shape::needle, .triangles = 10'000},
        {.shape = Shape::huge, .triangles = 10'000},
        {.shape = Shape::huge, .triangles = 2'000, .depth = Depth::separated},  // rast bench's huge scene
        {.shape = Shape::mesh, .triangles = 100'000},
        // rast bench's fans scene: small triangles around pixel centres, where edges pass through samples.
        {.shape = Shape::fan, .triangles = 20'000, .depth = Depth::separated},
    };
    for (const SceneSpec& spec : scenes) {
        const std::string label = describe(spec);
        for (const fast::Precision precision : {fast::Precision::fixed8, fast::Precision::float32}) {
            for (const int threads : {1, 2}) {
                benchmark::RegisterBenchmark(("fast/" + std::string(fast::name(precision)) +
                                              "/threads:" + std::to_string(threads) + "/" + label)
                                                 .c_str(),
                                             fast_path, spec, precision, threads)
                    ->Unit(benchmark::kMillisecond)
                    ->UseRealTime();
            }
        }
        for (const int threads : {1, 2}) {
            benchmark::RegisterBenchmark(
                ("llvmpipe/threads:" + std::to_string(threads) + "/" + label).c_str(), llvmpipe, spec,
                threads)
                ->Unit(benchmark::kMillisecond)
                ->UseManualTime();
        }
        benchmark::RegisterBenchmark(("reference/threads:1/" + label).c_str(), reference, spec)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

}  // namespace
}  // namespace rast::bench

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    rast::bench::register_benchmarks();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
