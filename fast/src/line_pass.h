// The scene's lines in the fast path's z-buffer: after the triangles, in the finished framebuffer.
#pragma once

#include "setup.h"

#include <rast/scene.h>

#include <cstdint>
#include <vector>

namespace rast::fast::detail {

// The ids of the scene's triangles (triangle_ids), having checked that every line is finite: throws
// std::invalid_argument naming the first bad line, before anything is drawn.
std::vector<std::int32_t> checked_lines(const Scene& scene);

// Draws the lines of `scene` into `fb`, whose triangles were drawn with their indices as ids: gives them
// their ids (`ids`, from checked_lines), then offers every sample of every pixel a line lights to the
// z-buffer. The pixels are Bresenham's on the mode's grid in the fixed modes, the DDA's in the float ones;
// a lit pixel's samples take the line's depth at the pixel (line_depth.h), and the (z, id) order is
// decided exactly: by the two depths' bounds where they can, in exact arithmetic where not. One thread.
void draw_lines(const Scene& scene, const Context& c, const std::vector<std::int32_t>& ids, Framebuffer& fb);

}  // namespace rast::fast::detail
