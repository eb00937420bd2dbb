// rast — choosing a rasterizer on the command line: the exact reference or the fast path in one precision.
#pragma once

#include <rast/fast.h>
#include <rast/reference.h>
#include <rast/scene.h>

#include <CLI/App.hpp>

#include <string>

namespace rast::cli {

struct EngineChoice {
    std::string engine = "reference";  // "reference" or "fast"
    std::string precision = "fixed8";  // fast only
    int threads = 1;                   // fast only; 0: all hardware threads

    bool is_reference() const { return engine == "reference"; }
    fast::Options fast_options() const;
    // "reference (exact)" or "fast fixed8, 2 threads", with the threads that run (fast::max_threads)
    std::string describe() const;
};

// Registers --engine, --precision and --threads on a subcommand; --precision and --threads are refused
// unless the engine is the fast path (`choice.engine` as given, for a command that then removes --engine).
void add_engine_options(CLI::App& command, EngineChoice& choice);

// Renders with the chosen engine; `stats` receives the reference's exact-arithmetic counts.
Framebuffer render(const Scene& scene, const EngineChoice& choice, reference::Stats* stats = nullptr);

}  // namespace rast::cli
