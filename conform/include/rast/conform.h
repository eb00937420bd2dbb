// rast — judging any rasterizer: the properties an engine's contract implies, held on scenes the user
// gives or on a battery (the corpus, then generated cases for each property), each failure shrunk to a
// minimal scene and kept as a corpus case that `rast replay --engine ...` reproduces.
#pragma once

#include <rast/engine.h>
#include <rast/progress.h>
#include <rast/properties.h>
#include <rast/scene.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rast::conform {

// The properties an engine's contract implies, in the registry's order: each one that applies to it.
std::vector<const properties::Property*> implied_properties(const Engine& engine);

// A scene to judge and where it came from ("corpus/fans/six.tri", "generated: seed 7").
struct Case {
    Scene scene;
    std::string origin;
    // The properties the case claims by construction (its "# properties:" header); conforms applies to
    // every case whatever its header says.
    std::vector<std::string> claims;
};

// A .tri file as a case: its scene, its path as the origin, its "# properties:" header as its claims.
// Throws ParseError for a file that does not read.
Case read_case(const std::filesystem::path& file);

// A property's failure: the smallest scene found and what went wrong on it.
struct Finding {
    Scene scene;                   // shrunk: no triangle can be dropped and the property still fail
    std::string detail;            // the property's words: the first violating sample, what each side said
    std::string origin;            // the case it was shrunk from
    std::size_t original_triangles = 0;
    std::filesystem::path kept;    // the corpus case written for it; empty when none was written
};

struct PropertyVerdict {
    std::string property;
    std::size_t checked = 0;         // scenes the property judged
    std::size_t not_applicable = 0;  // scenes whose precondition it does not meet on this engine
    std::optional<Finding> failure;
};

struct Verdict {
    std::string engine;  // the engine's name
    std::optional<Contract> contract;
    std::vector<PropertyVerdict> properties;  // implied_properties' order
    bool conforms() const;
};

struct Options {
    int cases = 100;          // generated scenes per property (the battery only)
    std::uint64_t seed = 1;   // the battery's seed
    int shard = 0, shards = 1;  // this run is shard `shard` of `shards`: its seeds are its own
    // Where shrunk counterexamples are written, as <engine>-<property>-<hash of the content>.tri; none:
    // not written. `engine_option` is what --engine says to reproduce them (plugin:PATH).
    std::optional<std::filesystem::path> found;
    std::string engine_option;
    // How far each property has come: (property, cases done, cases in all).
    std::function<void(const std::string&, std::size_t, std::size_t)> progress;
};

// Every implied property on every case: conforms on all of them, another property on the cases that
// claim it, each property until its first failure. No generated cases.
Verdict judge(const Engine& engine, std::span<const Case> cases, const Options& options);

// The battery: `corpus` first, then options.cases generated scenes per implied property.
Verdict battery(const Engine& engine, std::span<const Case> corpus, const Options& options);

// Drops triangles one at a time while `fails` still holds of the scene: the result fails, and dropping
// any one more of its triangles would not.
Scene drop_triangles(Scene scene, const std::function<bool(const Scene&)>& fails);

// The seed of one property's generated cases in one shard: distinct for every (seed, shard, property).
std::uint64_t case_seed(std::uint64_t seed, int shard, std::string_view property);

// Thrown when the engine fails outright (EngineError) on a case: the case is kept (as
// <engine>-engine-error-<hash>.tri) so that the failure can be rerun.
struct EngineFailure : EngineError {
    EngineFailure(const EngineError& error, std::filesystem::path kept);
    std::filesystem::path kept;
};

}  // namespace rast::conform
