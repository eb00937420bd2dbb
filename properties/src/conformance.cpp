#include <rast/conformance.h>
#include <rast/exact_geometry.h>
#include <rast/reference.h>

#include <array>
#include <optional>

#include "checks.h"
#include "samples.h"

namespace rast::properties {

namespace {

// The values a coordinate may take under the contract: itself, its one snapping, or (rounding=any) its
// two grid neighbours, one when it is on the grid.
std::vector<double> choices(double value, const Contract& c) {
    if (!c.snap) return {value};
    if (c.rounding != Contract::Rounding::any) return {snap(value, *c.snap, c.rounding)};
    const double down = snap(value, *c.snap, Contract::Rounding::floor);
    const double up = -snap(-value, *c.snap, Contract::Rounding::floor);
    return down == up ? std::vector<double>{down} : std::vector<double>{down, up};
}

double& coordinate(Vertex& v, int axis) { return axis == 0 ? v.x : v.y; }

// Every snapping of `t` the contract allows. Equal values on one axis are snapped alike: an engine snaps
// by a function of the coordinate (which may differ between x and y, as for an engine that flips y).
std::vector<Triangle> snappings(Triangle t, const Contract& c) {
    struct Value {
        double value;
        std::vector<double> options;
    };
    std::vector<Value> values;
    std::array<std::size_t, 6> value_of{};  // per axis and vertex
    for (int axis = 0; axis < 2; ++axis) {
        const std::size_t first = values.size();
        for (int k = 0; k < 3; ++k) {
            const double v = coordinate(t.v[k], axis);
            std::size_t m = first;
            while (m < values.size() && values[m].value != v) ++m;
            if (m == values.size()) values.push_back({v, choices(v, c)});
            value_of[static_cast<std::size_t>(axis * 3 + k)] = m;
        }
    }
    std::size_t total = 1;
    for (const Value& v : values) total *= v.options.size();
    std::vector<Triangle> out;
    out.reserve(total);
    for (std::size_t combination = 0; combination < total; ++combination) {
        std::array<double, 6> chosen{};
        std::size_t rest = combination;
        for (std::size_t m = 0; m < values.size(); ++m) {
            chosen[m] = values[m].options[rest % values[m].options.size()];
            rest /= values[m].options.size();
        }
        for (int axis = 0; axis < 2; ++axis)
            for (int k = 0; k < 3; ++k) coordinate(t.v[k], axis) = chosen[value_of[static_cast<std::size_t>(axis * 3 + k)]];
        out.push_back(t);
    }
    return out;
}

// Whether one snapped triangle covers a sample: yes, no, or (ties=none, on its boundary) either.
Demand covers(const Triangle& t, const Sample& at, const Contract& c) {
    if (c.top_left) return rule_covers(t, at.x, at.y) ? Demand::required : Demand::forbidden;
    switch (locate(t, at.x, at.y)) {
        case Location::inside: return Demand::required;
        case Location::outside: return Demand::forbidden;
        default: return Demand::free;
    }
}

// A triangle's demand at one sample, and its exact depth range there over its snappings.
struct Claim {
    std::size_t triangle;
    Demand demand;
};

// Per sample, the triangles that may cover it (required or free), in id order.
struct Claims {
    std::vector<std::vector<Claim>> at;  // per framebuffer sample
    std::vector<std::vector<Triangle>> snapped;  // per triangle, its snappings
};

Claims claims(const Scene& scene, const Contract& c) {
    Claims out;
    out.at.resize(sample_count(scene.viewport, scene.samples));
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) {
        out.snapped.push_back(snappings(scene.triangles[id], c));
        const std::vector<Triangle>& ways = out.snapped.back();
        PixelRange r = pixel_range(ways[0], scene.viewport);
        for (const Triangle& w : ways) {
            const PixelRange q = pixel_range(w, scene.viewport);
            if (q.i0 > q.i1 || q.j0 > q.j1) continue;
            if (r.i0 > r.i1 || r.j0 > r.j1) r = q;
            r = {std::min(r.i0, q.i0), std::max(r.i1, q.i1), std::min(r.j0, q.j0), std::max(r.j1, q.j1)};
        }
        if (r.i0 > r.i1 || r.j0 > r.j1) continue;
        for_each_sample(r, scene.viewport, scene.samples, [&](const Sample& at) {
            bool some = false, all = true;
            for (const Triangle& w : ways) {
                const Demand d = covers(w, at, c);
                some = some || d != Demand::forbidden;
                all = all && d == Demand::required;
            }
            if (some) out.at[at.index].push_back({id, all ? Demand::required : Demand::free});
        });
    }
    return out;
}

// The exact depth range of a triangle's planes over its snappings at a sample (zero-area snappings have
// no plane and are left out); none when every snapping is degenerate.
std::optional<std::pair<reference::Rational, reference::Rational>> depth_range(const std::vector<Triangle>& ways,
                                                                                const Sample& at) {
    std::optional<std::pair<reference::Rational, reference::Rational>> range;
    for (const Triangle& w : ways) {
        if (orientation(w) == 0) continue;
        const reference::Rational z = reference::depth_at(w, at.x, at.y);
        if (!range) range = std::pair{z, z};
        else range = std::pair{std::min(range->first, z), std::max(range->second, z)};
    }
    return range;
}

// Whether triangle a precedes triangle b in the (z, id) order at the sample under every snapping.
bool certainly_before(const Claims& claims, std::size_t a, std::size_t b, const Sample& at) {
    const auto za = depth_range(claims.snapped[a], at), zb = depth_range(claims.snapped[b], at);
    if (!za || !zb) return false;
    return za->second < zb->first || (za->second == zb->first && a < b);
}

const char* demand_word(Demand d) {
    return d == Demand::required ? "required" : d == Demand::free ? "free" : "forbidden";
}

}  // namespace

std::vector<Demand> coverage_demands(const Scene& scene, const Contract& contract) {
    const Claims all = claims(scene, contract);
    std::vector<Demand> out(all.at.size(), Demand::forbidden);
    for (std::size_t k = 0; k < all.at.size(); ++k)
        for (const Claim& claim : all.at[k]) out[k] = std::max(out[k], claim.demand);
    return out;
}

std::vector<ConformanceViolation> conformance_violations(const Scene& scene, const Contract& contract,
                                                         const Framebuffer& fb) {
    const Claims all = claims(scene, contract);
    std::vector<ConformanceViolation> out;
    for (std::size_t k = 0; k < all.at.size(); ++k) {
        const std::vector<Claim>& here = all.at[k];
        const std::int32_t id = fb.ids[k];
        const auto required = std::find_if(here.begin(), here.end(),
                                           [](const Claim& c) { return c.demand == Demand::required; });
        const auto violation = [&](const std::string& what) {
            out.push_back({k, id, describe(sample_at(scene.viewport, scene.samples, k)) + ": " + what});
        };
        if (id == Framebuffer::kNoTriangle) {
            if (required != here.end())
                violation("required (triangle " + std::to_string(required->triangle) +
                          " covers it under the contract), the engine left it empty");
            continue;
        }
        const auto mine = std::find_if(here.begin(), here.end(),
                                       [id](const Claim& c) { return c.triangle == static_cast<std::size_t>(id); });
        if (!contract.zid) {
            if (here.empty()) violation("forbidden (no triangle may cover it), the engine covered it");
            continue;
        }
        if (mine == here.end()) {
            violation("forbidden to triangle " + std::to_string(id) +
                      " (outside it under every snapping), the engine wrote " + std::to_string(id));
            continue;
        }
        const Sample at = sample_at(scene.viewport, scene.samples, k);
        for (const Claim& c : here)
            if (c.demand == Demand::required && c.triangle != mine->triangle &&
                certainly_before(all, c.triangle, mine->triangle, at)) {
                violation("triangle " + std::to_string(c.triangle) + " covers it (" + demand_word(c.demand) +
                          ") and precedes triangle " + std::to_string(id) +
                          " in the (z, id) order, the engine wrote " + std::to_string(id));
                break;
            }
    }
    return out;
}

}  // namespace rast::properties

namespace rast::properties {

Outcome conforms(const Scene& scene, const Engine& engine) {
    const auto violations = conformance_violations(scene, *engine.contract, engine.render(scene));
    if (violations.empty()) return Outcome::pass();
    std::string detail = violations.front().what;
    if (violations.size() > 1) detail += " (and " + std::to_string(violations.size() - 1) + " more samples)";
    return Outcome::fail(detail);
}

}  // namespace rast::properties
