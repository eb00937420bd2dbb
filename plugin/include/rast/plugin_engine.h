// rast — a rasterizer plugin (rast/plugin.h) as a rast::Engine, so that every command, property and
// bench that takes an engine takes any rasterizer.
#pragma once

#include <rast/engine.h>

#include <string>

namespace rast {

struct PluginOptions {
    double timeout = 60;  // seconds the plugin may take to load, and to render each scene
};

// Loads `library` in a process of its own and reads its contract. A bare name of a file in the current
// folder ("mine.so") means that file, not one on the library search path. Throws EngineError naming the library
// when it cannot be loaded, lacks a symbol, speaks another ABI version or declares a malformed contract
// (naming the key). Its renders throw EngineError when the plugin returns an error, crashes, hangs past
// the timeout, writes an id outside -1..triangles-1, or is given a sample count its contract lacks.
Engine plugin_engine(const std::string& library, const PluginOptions& options = {});

}  // namespace rast
