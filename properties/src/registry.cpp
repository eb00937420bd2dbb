#include <stdexcept>
#include <string>

#include "checks.h"

namespace rast::properties {

namespace {

// A plugin's contract may promise less than rast's own engines keep: no tie rule (so no promise on an
// edge, whichever way a triangle winds), no (z, id) order, or a snapping chosen per vertex (so no one
// geometry whose exact depths decide the order).
bool keeps_ties(const Engine& e) { return !e.contract || e.contract->top_left; }
bool keeps_zid(const Engine& e) { return !e.contract || (e.contract->zid && e.contract->deterministic()); }
bool exact_engines(const Engine& e) { return e.exact(); }
bool contract_engines(const Engine& e) { return e.contract.has_value(); }
bool fixed_engines(const Engine& e) { return e.exact() && e.snap_bits().has_value(); }
bool float_engines(const Engine& e) { return e.edge_error_bound_at && !e.exact(); }
bool reference_only(const Engine& e) { return e.is_reference(); }
bool exact_zid_engines(const Engine& e) { return e.exact() && keeps_zid(e); }
// The plugin ABI (version 1) has no lines: rast's own engines draw them, the float modes held to their own
// coverage and DDA.
bool line_engines(const Engine& e) {
    return e.kind != Engine::Kind::plugin && (exact_zid_engines(e) || (e.kind == Engine::Kind::fast && e.precision));
}

// Float modes are bound only by float_within_bound: near an edge they may classify either way, so
// exact coverage claims (shared edges, ties, translations) are not theirs to keep.
constexpr Property kProperties[] = {
    {"watertight", "in a triangulated region every inner sample is covered exactly once, none outside",
     exact_engines, watertight},
    {"tie_rule", "samples on edges and vertices are owned by left and top edges only", exact_engines, tie_rule},
    {"winding_invariance", "every vertex order covers the same samples", keeps_ties, winding_invariance},
    {"translation_invariance", "a whole-pixel shift of the scene shifts its image", exact_engines,
     translation_invariance},
    {"order_independence", "every draw order gives the (z, id) minimum", keeps_zid, order_independence},
    {"fixed_matches_reference", "fixed N equals the reference on vertices snapped to N bits", fixed_engines,
     fixed_matches_reference},
    {"float_within_bound", "float modes differ from the reference only within their error bound of an edge",
     float_engines, float_within_bound},
    {"msaa_counts", "per-pixel covered-sample counts equal the exact rule's", exact_engines, msaa_counts},
    {"area_tiling", "exact pixel areas of a tiling sum exactly and decide full and empty pixels", exact_engines,
     area_tiling},
    {"conforms", "every sample is as the engine's contract demands: required ones covered, forbidden ones not, "
     "ids in the (z, id) order", contract_engines, conforms},
    {"visible_area", "the exact visible area per pixel equals an independent slab computation, sums to the "
     "union's area and does not depend on the order the triangles are cut in", reference_only, visible_area},
    {"msaa_visible_bound", "the resolved samples are within (cells a boundary meets) / N of the visible area",
     exact_zid_engines, msaa_visible_bound},
    {"lines_zbuffer", "every sample holds the (z, id) least of the triangles covering it and the lines lighting "
     "its pixel, judged exactly", line_engines, lines_zbuffer, true},
};

}  // namespace

Outcome Property::verdict_on(const Scene& scene, const Engine& engine) const {
    if (engine.contract && !engine.contract->renders(scene.samples))
        return Outcome::not_applicable("the engine does not render " + std::to_string(scene.samples) +
                                       " samples a pixel");
    if (!scene.lines.empty() && !judges_lines)
        return Outcome::not_applicable("the scene has lines, and " + std::string(name) + " judges triangles alone");
    try {
        return check(scene, engine);
    } catch (const EngineError&) {
        throw;
    } catch (const std::exception& e) {
        return Outcome::fail(engine.name + " threw: " + e.what());
    }
}

std::span<const Property> all_properties() { return kProperties; }

const Property& property(std::string_view name) {
    for (const Property& p : kProperties)
        if (p.name == name) return p;
    std::string known;
    for (const Property& p : kProperties) known += (known.empty() ? "" : ", ") + std::string(p.name);
    throw std::invalid_argument("unknown property '" + std::string(name) + "' (known: " + known + ")");
}

CaseCheck check_case(const Scene& scene, std::span<const Property* const> properties, std::span<const Engine> engines) {
    CaseCheck result;
    for (const Property* p : properties) {
        bool applies = false, checked = false;
        std::string why_not_here;
        for (const Engine& engine : engines) {
            if (!p->applies_to(engine)) continue;
            applies = true;
            Outcome outcome = p->verdict_on(scene, engine);
            if (outcome.verdict == Outcome::Verdict::not_applicable) {
                ++result.not_applicable;
                if (why_not_here.empty())
                    why_not_here = std::string(p->name) + " [" + engine.name + "]: " + outcome.detail;
                continue;
            }
            ++result.checks;
            checked = true;
            if (outcome.failed())
                result.failures.push_back({std::string(p->name), engine.name, std::move(outcome.detail)});
        }
        if (applies && !checked && result.unchecked.empty()) result.unchecked = why_not_here;
    }
    return result;
}

std::vector<Failure> check_case(const Scene& scene, std::span<const std::string> property_names) {
    std::vector<const Property*> selected;
    for (const std::string& name : property_names) selected.push_back(&property(name));
    return check_case(scene, selected, all_engines()).failures;
}

}  // namespace rast::properties
