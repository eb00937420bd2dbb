// rast conform — what a verdict leaves behind besides its lines on stdout: a JSON and a Markdown report,
// and a picture of each shrunk counterexample.
#pragma once

#include <rast/conform.h>

#include <filesystem>
#include <string>

namespace rast::cli {

// What the run was, for the reports' heading.
struct ConformRun {
    std::string library;
    std::string battery;  // "the battery: 64 corpus cases, then 100 generated cases a property, seed 1, shard 1/1",
                          // or "3 scenes given"
};

std::string conform_json(const ConformRun& run, const conform::Verdict& verdict);
std::string conform_markdown(const ConformRun& run, const conform::Verdict& verdict);

// The counterexample as a PNG, three panels magnified: what the contract demands of each sample (white
// required, grey free, black forbidden; a pixel's samples averaged), the engine's ids, and the reference's
// ids on the same scene (the fixed modes' snapped geometry where the contract snaps to nearest or down).
std::string counterexample_png(const Engine& engine, const conform::Finding& finding);

}  // namespace rast::cli
