#include "property_harness.h"

#include <rast/property_generators.h>
#include <rast/tri_format.h>

#include <rapidcheck/detail/Configuration.h>

#include <cstdlib>
#include <stdexcept>

namespace rast::harness {

void hold(std::string_view name, const Scene& scene, std::span<const Engine> engines) {
    const properties::Property& p = properties::property(name);
    bool checked = false;
    for (const Engine& engine : engines) {
        if (!p.applies_to(engine)) continue;
        // An engine that throws is a failure whose scene is kept too.
        const properties::Outcome outcome = p.verdict_on(scene, engine);
        if (outcome.failed()) {
            const auto kept = keep_counterexample(name, engine.name, scene, outcome.detail);
            RC_FAIL(std::string(name) + " fails on " + engine.name + ": " + outcome.detail + " (kept in " +
                    kept.string() + ")");
        }
        checked = checked || outcome.verdict == properties::Outcome::Verdict::pass;
    }
    RC_PRE(checked);
}

namespace {

std::filesystem::path corpus_dir() {
    if (const char* dir = std::getenv("RAST_CORPUS_OUT"); dir && *dir) return dir;
    return RAST_DEFAULT_CORPUS_OUT;
}

}  // namespace

std::filesystem::path keep_counterexample(std::string_view property, const std::string& engine, const Scene& scene,
                                          const std::string& why) {
    // The run's parameters (RC_PARAMS, or RapidCheck's random seed) reproduce the search: RapidCheck
    // derives every case of a property from the seed and the property's name alone.
    const auto& params = rc::detail::configuration().testParams;
    const std::string seed = std::to_string(params.seed);
    const std::filesystem::path dir = corpus_dir();
    std::filesystem::create_directories(dir);
    const auto path = dir / (std::string(property) + "-" + seed + ".tri");
    write_tri_file(path, scene,
                   {{"properties", std::string(property)},
                    {"engine", engine},
                    {"why", header_value(why)},
                    {"seed", seed},
                    {"found-by", "property_tests"},
                    {"reproduce", "RC_PARAMS=\"seed=" + seed + " max_success=" + std::to_string(params.maxSuccess) +
                                      " max_size=" + std::to_string(params.maxSize) +
                                      "\" property_tests --gtest_filter=Properties." + std::string(property)}});
    return path;
}

}  // namespace rast::harness
