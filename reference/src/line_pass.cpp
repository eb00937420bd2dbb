// rast — the scene's lines in the reference's z-buffer (line_pass.h).
//
// A lit pixel's samples all take the line's one depth (rast/line.h). The framebuffer keeps each depth
// rounded to nearest, which is monotone: a rounded line depth above or below the stored one decides, and
// only equal rounded depths need the stored fragment's exact depth, a triangle's plane at the sample or
// another line's depth at the pixel.
#include "line_pass.h"

#include "exact_depth.h"
#include "nearest_double.h"

#include <rast/line.h>

#include <cstddef>
#include <optional>
#include <unordered_map>

namespace rast::reference::detail {

void draw_lines(const Scene& scene, const std::vector<std::int32_t>& ids, Framebuffer& fb) {
    rename_triangles(fb, ids);
    const std::vector<Primitive> named = primitives_by_id(scene, ids);
    std::unordered_map<std::size_t, ExactDepth> planes;  // the stored triangles an exact comparison needed

    const auto pattern = sample_pattern(fb.samples);
    const auto width = static_cast<std::size_t>(fb.viewport.width);
    for (const Line& line : scene.lines)
        for (const std::size_t pixel : lit_pixels(line.segment, fb.viewport)) {
            const int i = static_cast<int>(pixel % width), j = static_cast<int>(pixel / width);
            const Rational z = line_depth(line.segment, i, j);
            const double rounded = nearest_double(z);
            for (int s = 0; s < fb.samples; ++s) {
                const std::size_t at = fb.index(i, j, s);
                const std::int32_t stored = fb.ids[at];
                if (stored != Framebuffer::kNoTriangle) {
                    if (rounded > fb.depth[at]) continue;
                    if (rounded == fb.depth[at]) {
                        const Primitive other = named[static_cast<std::size_t>(stored)];
                        const Rational other_z = [&] {
                            if (other.line) return line_depth(scene.lines[other.index].segment, i, j);
                            auto plane = planes.find(other.index);
                            if (plane == planes.end())
                                plane = planes.emplace(other.index, ExactDepth(scene.triangles[other.index])).first;
                            return plane->second.at(i + pattern[s].x, j + pattern[s].y);
                        }();
                        if (z > other_z || (z == other_z && stored < line.id)) continue;
                    }
                }
                fb.ids[at] = line.id;
                fb.depth[at] = rounded;
            }
        }
}

}  // namespace rast::reference::detail
