// rast properties — the exact conformance verdict: what an engine's contract (rast/contract.h) demands of
// every sample of a scene, and where a framebuffer departs from it. docs/design.md states the definitions.
//
// Each triangle is snapped as the contract allows: not at all, to nearest (ties to even), down, or, for
// rounding=any, every way at once (each distinct coordinate value to either grid neighbour: at most 2^6
// snapped triangles, all enumerated). A sample is *required* for a triangle that covers it in every
// snapping, *forbidden* for one that covers it in none, *free* otherwise; with ties=none a sample on a
// snapped triangle's edge is free too. Coverage is decided exactly, by the tie rule.
#pragma once

#include <rast/contract.h>
#include <rast/scene.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rast::properties {

enum class Demand : std::uint8_t { forbidden, free, required };

// What a sample is for the scene as a whole: required when some triangle requires it, forbidden when every
// triangle forbids it, free otherwise. One per framebuffer sample (Framebuffer::index order).
std::vector<Demand> coverage_demands(const Scene& scene, const Contract& contract);

struct ConformanceViolation {
    std::size_t sample;        // Framebuffer::index
    std::int32_t engine_id;    // what the engine wrote there
    std::string what;          // "pixel (i, j) sample s at (x, y): ..." what the contract demands, what it got
};

// Every sample where `fb` departs from what `contract` demands of `scene`, in sample order:
//   - a required sample left empty (-1), or a covered sample that every triangle forbids;
//   - under depth=zid, an id that may not cover the sample, or one that a triangle requiring the sample
//     certainly precedes in the (z, id) order (for rounding=any: nearer under every snapping of both).
std::vector<ConformanceViolation> conformance_violations(const Scene& scene, const Contract& contract,
                                                         const Framebuffer& fb);

}  // namespace rast::properties
