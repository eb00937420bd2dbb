#include "engine_choice.h"

#include <CLI/CLI.hpp>

#include <algorithm>

namespace rast::cli {

fast::Options EngineChoice::fast_options() const {
    // The option's validator has already accepted the name.
    return {.precision = *fast::parse_precision(precision), .threads = threads};
}

std::string EngineChoice::describe() const {
    if (is_reference()) return "reference (exact)";
    // What runs: a count above the machine's is not what the user would see in the time taken.
    const int limit = fast::max_threads(), runs = threads == 0 ? limit : std::min(threads, limit);
    std::string text = "fast " + precision + ", " + std::to_string(runs) + (runs == 1 ? " thread" : " threads");
    if (threads == 0) text += " (all)";
    else if (threads > limit) text += " (" + std::to_string(threads) + " asked; the most this machine runs)";
    return text;
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

Framebuffer render(const Scene& scene, const EngineChoice& choice, reference::Stats* stats) {
    if (choice.is_reference()) return reference::render(scene, stats);
    return fast::render(scene, choice.fast_options());
}

}  // namespace rast::cli
