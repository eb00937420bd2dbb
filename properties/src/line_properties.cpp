// lines_zbuffer: lines and triangles share one z-buffer and one (z, id) order. The judge is brute force,
// sample by sample, apart from any engine's traversal and z-buffer: every triangle covering the sample
// at its plane's exact depth there, and every line lighting the pixel at its exact depth at the pixel
// (reference::line_depth), the least by (z, id) owning it. Which samples a triangle covers and which
// pixels a line lights are the exact rule's on the geometry an exact engine rasterizes
// (reference::covers, reference::lights); a float mode is held to its own coverage and its own DDA
// (covered_samples, fast::dda), for only its order is exact.
#include <rast/fast.h>
#include <rast/line.h>
#include <rast/reference.h>

#include <algorithm>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checks.h"

namespace rast::properties {

namespace {

using reference::Rational;

struct Owner {
    Rational z;
    std::int32_t id;
};

void offer(std::optional<Owner>& best, Rational z, std::int32_t id) {
    if (!best || z < best->z || (z == best->z && id < best->id)) best = Owner{std::move(z), id};
}

}  // namespace

Outcome lines_zbuffer(const Scene& scene, const Engine& engine) {
    if (scene.lines.empty()) return Outcome::not_applicable("the scene has no lines");
    const Scene geometry = rasterized_geometry(engine, scene);
    const std::vector<std::int32_t> ids = triangle_ids(scene);
    const Framebuffer image = engine.render(scene);
    const auto pattern = sample_pattern(scene.samples);
    const Viewport vp = scene.viewport;
    // A float mode's own pixels and samples, ascending; none for the exact engines, which the rule judges.
    const bool own = !engine.exact();
    std::vector<std::vector<std::size_t>> lit_by(geometry.lines.size()), covered_by(geometry.triangles.size());
    if (own) {
        for (std::size_t k = 0; k < geometry.lines.size(); ++k) lit_by[k] = fast::dda(geometry.lines[k].segment, vp, *engine.precision);
        for (std::size_t k = 0; k < geometry.triangles.size(); ++k)
            covered_by[k] = engine.covered_samples(geometry.triangles[k], vp, scene.samples);
    }
    const auto holds = [](const std::vector<std::size_t>& sorted, std::size_t index) {
        return std::binary_search(sorted.begin(), sorted.end(), index);
    };
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            std::vector<Owner> lit;
            const std::size_t pixel = static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) + static_cast<std::size_t>(i);
            for (std::size_t k = 0; k < geometry.lines.size(); ++k) {
                const Segment& segment = geometry.lines[k].segment;
                if (own ? holds(lit_by[k], pixel) : reference::lights(segment, i, j))
                    lit.push_back({reference::line_depth(segment, i, j), geometry.lines[k].id});
            }
            for (int s = 0; s < scene.samples; ++s) {
                const double x = i + pattern[static_cast<std::size_t>(s)].x, y = j + pattern[static_cast<std::size_t>(s)].y;
                std::optional<Owner> best;
                for (const Owner& line : lit) offer(best, line.z, line.id);
                for (std::size_t k = 0; k < geometry.triangles.size(); ++k)
                    if (own ? holds(covered_by[k], image.index(i, j, s)) : reference::covers(geometry.triangles[k], x, y))
                        offer(best, reference::depth_at(geometry.triangles[k], x, y), ids[k]);
                const std::int32_t expected = best ? best->id : Framebuffer::kNoTriangle;
                if (image.id(i, j, s) != expected)
                    return Outcome::fail("pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") sample " +
                                         std::to_string(s) + ": " + engine.name + " drew id " +
                                         std::to_string(image.id(i, j, s)) + ", the (z, id) least is " +
                                         std::to_string(expected) +
                                         (best ? " at z = " + best->z.str() : std::string(" (nothing there)")));
            }
        }
    return Outcome::pass();
}

}  // namespace rast::properties
