// lines_zbuffer: lines and triangles share one z-buffer and one (z, id) order. The judge is brute force,
// sample by sample, apart from any engine's traversal and z-buffer: every triangle covering the sample
// (reference::covers) at its plane's exact depth there, and every line lighting the pixel
// (reference::lights) at its exact depth at the pixel (reference::line_depth), the least by (z, id)
// owning it.
#include <rast/line.h>
#include <rast/reference.h>

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
    for (int j = 0; j < scene.viewport.height; ++j)
        for (int i = 0; i < scene.viewport.width; ++i) {
            std::vector<Owner> lit;
            for (const Line& line : geometry.lines)
                if (reference::lights(line.segment, i, j)) lit.push_back({reference::line_depth(line.segment, i, j), line.id});
            for (int s = 0; s < scene.samples; ++s) {
                const double x = i + pattern[static_cast<std::size_t>(s)].x, y = j + pattern[static_cast<std::size_t>(s)].y;
                std::optional<Owner> best;
                for (const Owner& line : lit) offer(best, line.z, line.id);
                for (std::size_t k = 0; k < geometry.triangles.size(); ++k)
                    if (reference::covers(geometry.triangles[k], x, y))
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
