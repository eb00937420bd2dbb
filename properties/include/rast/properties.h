// rast — the properties that hold the engines to docs/design.md, as plain functions of a scene and an
// engine. The property tests (RapidCheck) feed them generated scenes; `rast replay` feeds them the corpus.
//
// Every property is checkable from a Scene alone. Where the fast path rasterizes snapped geometry (the
// fixed modes), the exact expectations are computed on the snapped scene, the geometry it promises to
// rasterize exactly.
#pragma once

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

// One rasterizer under test: the exact reference or the fast path in one precision mode. The functions
// are replaceable so that the bite tests can substitute a deliberately broken fast path.
struct Engine {
    std::string name;                          // "reference", "fixed8", "float32", ...
    std::optional<fast::Precision> precision;  // none for the reference
    std::function<Framebuffer(const Scene&)> render;
    std::function<std::vector<std::size_t>(const Triangle&, Viewport, int samples)> covered_samples;
    // Float modes: fast::edge_error_bound_at, the slack each edge function of the engine may have at a sample.
    std::function<std::array<double, 3>(const Triangle&, double x, double y)> edge_error_bound_at;

    // Exact engines classify every sample exactly on the geometry they rasterize (reference, fixed N).
    bool exact() const;
    // Only the reference promises depths bit for bit (the exact depth rounded to nearest); the fast
    // path writes its double plane value, within a few ulps. Every engine decides the (z, id) order
    // exactly, so the id buffer is exact everywhere.
    bool exact_depth() const { return !precision; }
    // The fixed modes' grid, 2^-bits of a pixel; none for the others.
    std::optional<int> snap_bits() const;
    // The geometry whose samples this engine must classify exactly: the scene itself, or its vertices
    // snapped to the engine's grid.
    Scene rasterized_geometry(const Scene& scene) const;
};

Engine reference_engine();
Engine fast_engine(fast::Precision precision);
// The reference followed by the fast path in every precision mode.
std::vector<Engine> all_engines();

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

    // check, where an engine that throws on the scene (valid input) fails the property instead of ending
    // the run: what the property tests keep and replay reports, like any other failure.
    Outcome verdict_on(const Scene& scene, const Engine& engine) const;
};

// Every property, in a fixed order: watertight, tie_rule, winding_invariance, translation_invariance,
// order_independence, fixed_matches_reference, float_within_bound, msaa_counts, area_tiling.
std::span<const Property> all_properties();
// Throws std::invalid_argument naming the unknown property and the known ones.
const Property& property(std::string_view name);

struct Failure {
    std::string property;
    std::string engine;
    std::string detail;
};

// Runs each named property on every engine it applies to; the failures, in property then engine order.
std::vector<Failure> check_case(const Scene& scene, std::span<const std::string> property_names);

}  // namespace rast::properties
