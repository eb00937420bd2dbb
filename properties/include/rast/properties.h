// rast — the properties that hold the engines to docs/design.md, as plain functions of a scene and an
// engine. The property tests (RapidCheck) feed them generated scenes; `rast replay` feeds them the corpus.
//
// Every property is checkable from a Scene alone. Where the fast path rasterizes snapped geometry (the
// fixed modes), the exact expectations are computed on the snapped scene, the geometry it promises to
// rasterize exactly.
#pragma once

#include <rast/engine.h>
#include <rast/fast.h>
#include <rast/scene.h>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rast::properties {

// The engines under test are rast::Engine (rast/engine.h): the reference, the fast path in each
// precision, or a deliberately broken fast path in the bite tests.
using rast::Engine;

// The geometry whose samples `engine` must classify exactly: the scene itself, or its vertices (and its
// lines' ends) snapped to the engine's grid as its contract rounds, by the oracle's own snap (exact_geometry.h), not the fast
// path's. Throws std::invalid_argument for a contract with rounding=any, which has no one geometry.
Scene rasterized_geometry(const Engine& engine, const Scene& scene);
Triangle rasterized_geometry(const Engine& engine, const Triangle& t);

// What a property concluded. `detail` says, for a failure, what differs and where (pixel i, j, sample s,
// what each side said); for `not_applicable`, which precondition the scene does not meet.
struct Outcome {
    enum class Verdict { pass, fail, not_applicable };
    Verdict verdict = Verdict::pass;
    std::string detail;

    static Outcome pass() { return {}; }
    static Outcome fail(std::string detail) { return {Verdict::fail, std::move(detail)}; }
    static Outcome not_applicable(std::string why) { return {Verdict::not_applicable, std::move(why)}; }
    bool failed() const { return verdict == Verdict::fail; }
};

struct Property {
    std::string_view name;       // stable: corpus headers name properties by it
    std::string_view statement;  // one sentence
    bool (*applies_to)(const Engine&);
    Outcome (*check)(const Scene&, const Engine&);
    // Whether check judges a scene's lines: a property about triangles alone does not apply to a scene
    // that has lines (its ids are not the triangles' indices, and its lines would go unjudged).
    bool judges_lines = false;

    // check, where an engine that throws on the scene (valid input) fails the property instead of ending
    // the run: what the property tests keep and replay reports, like any other failure.
    Outcome verdict_on(const Scene& scene, const Engine& engine) const;
};

// Every property, in a fixed order: watertight, tie_rule, winding_invariance, translation_invariance,
// order_independence, fixed_matches_reference, float_within_bound, msaa_counts, area_tiling, conforms,
// visible_area, msaa_visible_bound, lines_zbuffer.
std::span<const Property> all_properties();
// Throws std::invalid_argument naming the unknown property and the known ones.
const Property& property(std::string_view name);

struct Failure {
    std::string property;
    std::string engine;
    std::string detail;
};

// What properties concluded on one scene, each on every engine it applies to.
struct CaseCheck {
    std::vector<Failure> failures;   // in property then engine order
    std::size_t checks = 0;          // property and engine pairs that passed or failed
    std::size_t not_applicable = 0;  // pairs whose scene the property does not apply to
    // The first property that applies to some engine but could check the scene on none of them, as
    // "name [engine]: why": a case that names it claims what it does not test. Empty when there is none.
    std::string unchecked;
};

CaseCheck check_case(const Scene& scene, std::span<const Property* const> properties, std::span<const Engine> engines);

// Each named property on every engine of all_engines() it applies to; the failures.
std::vector<Failure> check_case(const Scene& scene, std::span<const std::string> property_names);

}  // namespace rast::properties
