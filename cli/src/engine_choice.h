// rast — choosing a rasterizer on the command line: the exact reference or the fast path in one precision
// and thread count, as a rast::Engine.
#pragma once

#include <rast/engine.h>
#include <rast/fast.h>
#include <rast/progress.h>
#include <rast/reference.h>
#include <rast/scene.h>

#include <CLI/App.hpp>

#include <optional>
#include <string>

namespace rast::cli {

// What --engine, --precision, --threads and --plugin-timeout said.
struct EngineChoice {
    std::string engine = "reference";  // "reference", "fast" or "plugin:PATH"
    std::string precision = "fixed8";  // fast only
    int threads = 1;                   // fast only; 0: all hardware threads
    double plugin_timeout = 60;        // plugin only: seconds to load, and to render a scene

    bool is_reference() const { return engine == "reference"; }
    // The library of --engine plugin:PATH; none for the others.
    std::optional<std::string> plugin() const;
    // The engine chosen; for the reference, `stats` receives its exact-arithmetic counts and `progress`
    // hears how far a render has come (the fast path is quick enough to need no word).
    Engine make(reference::Stats* stats = nullptr, Progress progress = {}) const;
};

// A float mode has no error bound for a triangle whose edge functions may overflow its type (coordinates
// near the type's largest values): its coverage there is whatever IEEE arithmetic gives, and may be
// nothing. Says so on stderr, naming the first such triangle; nothing for the exact engines.
void note_unbounded_triangles(const Scene& scene, const Engine& engine);

// Registers --engine, --precision, --threads and --plugin-timeout on a subcommand; --precision and
// --threads are refused unless the engine is the fast path, --plugin-timeout unless it is a plugin
// (`choice.engine` as given, for a command that then removes --engine).
void add_engine_options(CLI::App& command, EngineChoice& choice);

}  // namespace rast::cli
