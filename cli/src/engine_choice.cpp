#include "engine_choice.h"
#include "wording.h"

#include <rast/plugin_engine.h>

#include <CLI/CLI.hpp>

#include <cstddef>
#include <iostream>
#include <limits>
#include <string_view>
#include <utility>

namespace rast::cli {

namespace {
constexpr std::string_view kPluginPrefix = "plugin:";
}

std::optional<std::string> EngineChoice::plugin() const {
    if (!engine.starts_with(kPluginPrefix)) return std::nullopt;
    return engine.substr(kPluginPrefix.size());
}

Engine EngineChoice::make(reference::Stats* stats, Progress progress) const {
    if (is_reference()) return reference_engine(stats, std::move(progress));
    if (const auto library = plugin()) return plugin_engine(*library, {plugin_timeout});
    // The option's validator has already accepted the name.
    return fast_engine(*fast::parse_precision(precision), threads);
}

void add_engine_options(CLI::App& command, EngineChoice& choice) {
    command
        .add_option("--engine", choice.engine,
                    "Rasterizer: the exact reference, the fast path, or plugin:PATH, a shared library with "
                    "the plugin ABI (rast/plugin.h)")
        ->type_name("reference|fast|plugin:PATH")
        ->check([](const std::string& s) -> std::string {
            if (s == "reference" || s == "fast") return {};
            if (s.starts_with(kPluginPrefix))
                return s.size() > kPluginPrefix.size() ? "" : "plugin: needs the library's path (plugin:PATH.so)";
            return "unknown engine '" + s + "' (expected reference, fast or plugin:PATH)";
        })
        ->capture_default_str();
    // The reference would ignore the fast path's settings. Parsing has read every argument before any option
    // is checked, so --engine's value is there to look at; a command without --engine has a fixed engine.
    const auto chosen = [&command, &choice] {
        const CLI::Option* engine = command.get_option_no_throw("--engine");
        return engine && engine->count() > 0 ? engine->results().back() : choice.engine;
    };
    const auto for_fast_only = [chosen](const std::string&) -> std::string {
        return chosen() == "fast" ? std::string{} : "applies to --engine fast only";
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
    command
        .add_option("--plugin-timeout", choice.plugin_timeout,
                    "Seconds a plugin may take to load, and to render one scene, before it is stopped")
        ->check(CLI::Range(0.001, 86400.0))
        ->check([chosen](const std::string&) -> std::string {
            return chosen().starts_with(kPluginPrefix) ? std::string{} : "applies to --engine plugin:PATH only";
        })
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
        std::cerr << "rast: note: " << engine.name << " cannot bound the edge functions of "
                  << counted(count, "triangle", "triangles") << " (the first: triangle " << triangle_ids(scene)[first]
                  << "), whose coordinates may overflow it: it may draw them wrongly or not at all\n";
}

}  // namespace rast::cli
