// The scene's lines in the reference's z-buffer.
#pragma once

#include <rast/reference.h>
#include <rast/scene.h>

#include <cstdint>
#include <vector>

namespace rast::reference::detail {

// Draws the lines of `scene` into `fb`, whose triangles were drawn with their indices in Scene::triangles
// as ids: gives the triangles their ids in the scene (rast/scene.h; `ids` is triangle_ids(scene)), then
// offers each sample of each pixel a line lights (lit_pixels) with the line's depth there (line_depth)
// under the (z, id) order, decided exactly.
void draw_lines(const Scene& scene, const std::vector<std::int32_t>& ids, Framebuffer& fb);

}  // namespace rast::reference::detail
