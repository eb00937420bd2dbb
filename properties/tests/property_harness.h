// rast property tests — what the property tests and the bite tests share: which scenes each property is
// fed, how a property is held against engines inside a RapidCheck case, and where a failing case is kept.
#pragma once

#include <rast/properties.h>
#include <rast/property_generators.h>  // also how RapidCheck shows a Scene: every file that draws one needs it

#include <rapidcheck.h>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace rast::harness {

// Inside a RapidCheck case: checks the property on every engine it applies to. On a failure, keeps the
// scene (keep_counterexample) and fails the case with the property's description; when the property
// applies to none of the engines for this scene, discards the case.
void hold(std::string_view property, const Scene& scene, std::span<const Engine> engines);

// Writes the scene atomically to <dir>/<property>-<seed>.tri, dir being $RAST_CORPUS_OUT or else the
// source tree's corpus/found, with a header naming the property, the engine, the seed, what failed and
// the command that reruns the search. RapidCheck re-runs a failing property while it shrinks, so the
// file is overwritten until it holds the minimal counterexample. Returns the path.
std::filesystem::path keep_counterexample(std::string_view property, const std::string& engine, const Scene& scene,
                                          const std::string& why);

}  // namespace rast::harness
