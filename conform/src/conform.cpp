#include <rast/conform.h>
#include <rast/property_generators.h>
#include <rast/tri_format.h>

#include <rapidcheck.h>
#include <rapidcheck/detail/Configuration.h>
#include <rapidcheck/detail/TestListenerAdapter.h>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <utility>

#include "kept_case.h"

namespace rast::conform {

namespace {

using properties::Outcome;
using properties::Property;

// The property's outcome, or the engine's outright failure with the case kept for a rerun.
Outcome verdict(const Property& p, const Scene& scene, const Engine& engine, const Options& options) {
    try {
        return p.verdict_on(scene, engine);
    } catch (const EngineError& e) {
        std::filesystem::path kept;
        if (options.found)
            kept = detail::keep_case(*options.found, scene,
                                     {engine.name, "engine-error", e.what(),
                                      engine.contract ? engine.contract->text() : "", options.engine_option,
                                      std::string(p.name)});
        throw EngineFailure(e, kept);
    }
}

bool fails(const Property& p, const Scene& scene, const Engine& engine, const Options& options) {
    return verdict(p, scene, engine, options).failed();
}

// The failure shrunk by dropping triangles, described again on the smaller scene, and kept.
Finding finding(const Property& p, const Engine& engine, std::string origin, std::size_t original_triangles,
                Scene scene, const Options& options) {
    Finding f;
    f.origin = std::move(origin);
    f.original_triangles = original_triangles;
    f.scene = drop_triangles(std::move(scene), [&](const Scene& s) { return fails(p, s, engine, options); });
    f.detail = verdict(p, f.scene, engine, options).detail;
    if (options.found)
        f.kept = detail::keep_case(*options.found, f.scene,
                                   {engine.name, std::string(p.name), f.detail,
                                    engine.contract ? engine.contract->text() : "", options.engine_option});
    return f;
}

bool claims(const Case& c, const Property& p) {
    return p.name == "conforms" || std::find(c.claims.begin(), c.claims.end(), p.name) != c.claims.end();
}

// RapidCheck announces its global configuration (a random seed) on std::cerr when it first loads it. The
// battery sets every parameter itself, so that line would only mislead: it is loaded here, unheard.
void load_rapidcheck_quietly() {
    std::ostringstream unheard;
    std::streambuf* const cerr = std::cerr.rdbuf(unheard.rdbuf());
    rc::detail::configuration();
    std::cerr.rdbuf(cerr);
}

// Counts the cases RapidCheck runs, for the progress report.
class CaseCounter : public rc::detail::TestListenerAdapter {
public:
    CaseCounter(const Options& options, const std::string& property) : options_(options), property_(property) {
        if (options_.progress) options_.progress(property_, 0, static_cast<std::size_t>(options_.cases));
    }
    void onTestCaseFinished(const rc::detail::CaseDescription&) override {
        if (options_.progress)
            options_.progress(property_, std::min<std::size_t>(++done_, static_cast<std::size_t>(options_.cases)),
                              static_cast<std::size_t>(options_.cases));
    }

private:
    const Options& options_;
    const std::string& property_;
    std::size_t done_ = 0;
};

// options.cases generated scenes for one property; RapidCheck shrinks a failure, dropping triangles too.
void generate(const Engine& engine, const Property& p, PropertyVerdict& pv, const Options& options) {
    rc::detail::TestParams params;
    params.seed = case_seed(options.seed, options.shard, p.name);
    params.maxSuccess = options.cases;
    std::optional<Scene> last_failing;  // RapidCheck reruns a failing case as it shrinks: the last is minimal
    std::size_t original = 0;           // the triangles of the first failing case
    CaseCounter counter(options, pv.property);
    rc::detail::TestMetadata metadata;
    metadata.id = "rast conform " + pv.property;
    // RapidCheck takes any exception in a case for a failure of the property, and goes on shrinking. An
    // engine that failed outright gave no answer to judge: the first such failure is kept and thrown
    // after the search, which runs on without calling the engine again.
    std::optional<EngineFailure> engine_failure;
    const auto result = rc::detail::checkTestable(
        [&] {
            const Scene scene = *gen::scenes_for(p.name);
            if (engine_failure) return;
            Outcome o;
            try {
                o = verdict(p, scene, engine, options);
            } catch (const EngineFailure& e) {
                engine_failure = e;
                return;
            }
            RC_PRE(o.verdict != Outcome::Verdict::not_applicable);
            if (!o.failed()) return;
            if (!last_failing) original = scene.triangles.size();
            last_failing = scene;
            RC_FAIL(o.detail);
        },
        metadata, params, counter);
    rc::detail::SuccessResult success;
    rc::detail::GaveUpResult gave_up;
    rc::detail::FailureResult failure;
    pv.checked += result.match(success)   ? static_cast<std::size_t>(success.numSuccess)
                  : result.match(gave_up) ? static_cast<std::size_t>(gave_up.numSuccess)
                  : result.match(failure) ? static_cast<std::size_t>(failure.numSuccess) + 1
                                          : 0;
    if (engine_failure) throw *engine_failure;
    if (last_failing)
        pv.failure = finding(p, engine,
                             "generated (seed " + std::to_string(params.seed) + ", shrunk by RapidCheck)", original,
                             *last_failing, options);
}

}  // namespace

Case read_case(const std::filesystem::path& file) {
    const TriDocument doc = read_tri_document_file(file);
    Case c{doc.scene, file.string(), {}};
    for (const auto& [key, value] : doc.header)
        if (key == "properties") {
            std::istringstream names(value);
            for (std::string name; names >> name;) c.claims.push_back(name);
        }
    return c;
}

bool Verdict::conforms() const {
    return std::none_of(properties.begin(), properties.end(), [](const PropertyVerdict& p) { return p.failure; });
}

EngineFailure::EngineFailure(const EngineError& error, std::filesystem::path kept_case)
    : EngineError(error), kept(std::move(kept_case)) {}

std::vector<const Property*> implied_properties(const Engine& engine) {
    std::vector<const Property*> out;
    for (const Property& p : properties::all_properties())
        if (p.applies_to(engine)) out.push_back(&p);
    return out;
}

Verdict judge(const Engine& engine, std::span<const Case> cases, const Options& options) {
    Verdict v{engine.name, engine.contract, {}};
    for (const Property* p : implied_properties(engine)) {
        PropertyVerdict pv{std::string(p->name), 0, 0, std::nullopt};
        std::size_t done = 0;
        for (const Case& c : cases) {
            if (options.progress) options.progress(pv.property, done++, cases.size());
            if (!claims(c, *p)) continue;
            const Outcome o = verdict(*p, c.scene, engine, options);
            if (o.verdict == Outcome::Verdict::not_applicable) {
                ++pv.not_applicable;
                continue;
            }
            ++pv.checked;
            if (o.failed()) {
                pv.failure = finding(*p, engine, c.origin, c.scene.triangles.size(), c.scene, options);
                break;
            }
        }
        if (options.progress) options.progress(pv.property, cases.size(), cases.size());
        v.properties.push_back(std::move(pv));
    }
    return v;
}

Verdict battery(const Engine& engine, std::span<const Case> corpus, const Options& options) {
    load_rapidcheck_quietly();
    Verdict v = judge(engine, corpus, options);
    for (std::size_t k = 0; k < v.properties.size(); ++k) {
        PropertyVerdict& pv = v.properties[k];
        if (pv.failure || options.cases <= 0) continue;
        generate(engine, properties::property(pv.property), pv, options);
    }
    return v;
}

Scene drop_triangles(Scene scene, const std::function<bool(const Scene&)>& fails) {
    for (std::size_t k = scene.triangles.size(); k-- > 0;) {
        // Without triangle k; the lines after it in file order move down one id.
        Scene without = scene;
        const std::int32_t id = triangle_ids(scene)[k];
        without.triangles.erase(without.triangles.begin() + static_cast<std::ptrdiff_t>(k));
        for (Line& line : without.lines)
            if (line.id > id) --line.id;
        if (!without.triangles.empty() && fails(without)) scene = std::move(without);
    }
    return scene;
}

std::uint64_t case_seed(std::uint64_t seed, int shard, std::string_view property) {
    // splitmix64 over the seed, the shard and the property's name.
    std::uint64_t x = seed;
    const auto mix = [&x](std::uint64_t v) {
        x += v + 0x9e3779b97f4a7c15ULL;
        std::uint64_t z = x;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        x = z ^ (z >> 31);
    };
    mix(static_cast<std::uint64_t>(shard));
    for (const char c : property) mix(static_cast<unsigned char>(c));
    return x;
}

}  // namespace rast::conform
