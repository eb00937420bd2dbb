// rast properties — the property checks, one function each (registered in registry.cpp), and the
// comparisons they share.
#pragma once

#include <rast/properties.h>
#include <rast/visible_area.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rast::properties {

Outcome watertight(const Scene& scene, const Engine& engine);
Outcome tie_rule(const Scene& scene, const Engine& engine);
Outcome winding_invariance(const Scene& scene, const Engine& engine);
Outcome translation_invariance(const Scene& scene, const Engine& engine);
Outcome order_independence(const Scene& scene, const Engine& engine);
Outcome fixed_matches_reference(const Scene& scene, const Engine& engine);
Outcome float_within_bound(const Scene& scene, const Engine& engine);
Outcome msaa_counts(const Scene& scene, const Engine& engine);
Outcome area_tiling(const Scene& scene, const Engine& engine);
Outcome conforms(const Scene& scene, const Engine& engine);
Outcome visible_area(const Scene& scene, const Engine& engine);
// What visible_area concludes of `computed`: the reference's visible area, or a broken one in the bite tests.
Outcome visible_area_of(const Scene& scene, const std::function<reference::VisibleArea(const Scene&)>& computed);
Outcome msaa_visible_bound(const Scene& scene, const Engine& engine);
Outcome lines_zbuffer(const Scene& scene, const Engine& engine);

// Not applicable, naming the first triangle that snapping to the engine's grid turns over (or gives area
// it did not have), where `geometry` (rasterized_geometry) has one: the snapped scene is then no longer
// the tiling the original was.
std::optional<Outcome> folded_by_snapping(const Scene& scene, const Scene& geometry, const Engine& engine);

// The first sample at which two ascending sample lists differ, described with what each side said;
// nullopt when they are equal.
std::optional<std::string> first_difference(const std::vector<std::size_t>& a, const std::string& a_name,
                                            const std::vector<std::size_t>& b, const std::string& b_name,
                                            Viewport vp, int samples);

// The first sample whose id (and, when `depths`, whose depth bit pattern) differs; nullopt when equal.
std::optional<std::string> first_difference(const Framebuffer& a, const std::string& a_name,
                                            const Framebuffer& b, const std::string& b_name, bool depths);

}  // namespace rast::properties
