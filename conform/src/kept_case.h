// rast conform — writing a counterexample as a corpus case named by its content, so that shards of one
// battery write their findings into one folder without collisions.
#pragma once

#include <rast/scene.h>

#include <filesystem>
#include <string>

namespace rast::conform::detail {

struct KeptCase {
    std::string engine;         // the engine's name
    std::string property;       // "engine-error" for a case on which the engine failed outright
    std::string why;            // one line
    std::string contract;       // the contract text, or "" for none
    std::string engine_option;  // what --engine says to reproduce it
    // For an engine-error case, the property that was running: the engine may have failed on a scene
    // the property made from this one (shifted, reordered, one triangle alone).
    std::string running = {};
};

// Writes <folder>/<engine>-<property>-<16 hex digits>.tri atomically: the digits hash the scene's text.
std::filesystem::path keep_case(const std::filesystem::path& folder, const Scene& scene, const KeptCase& what);

}  // namespace rast::conform::detail
