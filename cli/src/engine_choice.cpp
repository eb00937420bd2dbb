#include "engine_choice.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <iostream>
#include <limits>
#include <utility>

namespace rast::cli {

Engine EngineChoice::make(reference::Stats* stats, Progress progress) const {
    if (is_reference()) return reference_engine(stats, std::move(progress));
    // The option's validator has already accepted the name.
    return fast_engine(*fast::parse_precision(precision), threads);
}

void add_engine_options(CLI::App& command, EngineChoice& choice) {
    command.add_option("--engine", choice.engine, "Rasterizer: the exact reference or the fast path")
        ->check(CLI::IsMember({"reference", "fast"}))
        ->capture_default_str();
    // The reference would ignore the fast path's settings. Parsing has read every argument before any option
    // is checked, so --engine's value is there to look at; a command without --engine has a fixed engine.
    const auto for_fast_only = [&command, &choice](const std::string&) -> std::string {
        const CLI::Option* engine = command.get_option_no_throw("--engine");
        const std::string chosen = engine && engine->count() > 0 ? engine->results().back() : choice.engine;
        return chosen == "fast" ? std::string{} : "applies to --engine fast only";
    };
    command
        .add_option("--precision", choice.precision,
                    "Fast path precision: fixed4|fixed8|fixed16 (vertices snapped to 1/2^N pixel, exact integer "
                    "edge functions) or float32|float64 (floating-point edge functions)")
        ->check([](const std::string& s) {
            return fast::parse_precision(s) ? std::string{}
                                            : "unknown precision '" + s +
                                                  "' (expected fixed4, fixed8, fixed16, float32 or float64)";
        })
        ->check(for_fast_only)
        ->capture_default_str();
    command
        .add_option("--threads", choice.threads,
                    "Fast path threads (0: all cores; at most the cores); the result is the same")
        ->check(CLI::Range(0, 1024))
        ->check(for_fast_only)
        ->capture_default_str();
}

void note_unbounded_triangles(const Scene& scene, const Engine& engine) {
    if (engine.exact() || !engine.precision) return;
    std::size_t count = 0, first = 0;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k)
        if (!(fast::edge_error_bound(scene.triangles[k], *engine.precision, scene.viewport) <
              std::numeric_limits<double>::infinity()))
            first = count++ == 0 ? k : first;
    if (count > 0)
        std::cerr << "rast: note: " << engine.name << " cannot bound the edge functions of " << count
                  << (count == 1 ? " triangle" : " triangles") << " (the first: triangle " << first
                  << "), whose coordinates may overflow it: it may draw them wrongly or not at all\n";
}

}  // namespace rast::cli
