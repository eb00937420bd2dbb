// rast — the buffers and exact areas as text files (docs/design.md): H lines, top row first. The id and
// depth buffers give W x N values a line, each pixel's N samples together in the order of the pattern.
#pragma once

#include <rast/reference.h>
#include <rast/scene.h>
#include <rast/visible_area.h>

#include <string>
#include <vector>

namespace rast::cli {

// Each sample's owning triangle id, or -1.
std::string format_ids(const Framebuffer& fb);
// Each sample's depth as a decimal that reads back to the same double, or "inf" where empty.
std::string format_depth(const Framebuffer& fb);
// Each pixel's exact covered area (bottom row first in `area`) as p/q in lowest terms, an integer when q = 1.
std::string format_area(Viewport vp, const std::vector<reference::Rational>& area);
// Each pixel's visible triangles as id:area pairs joined by ',', ids ascending; '-' where none is seen.
std::string format_visible(const reference::VisibleArea& visible);

}  // namespace rast::cli
