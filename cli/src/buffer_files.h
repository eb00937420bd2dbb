// rast — the id and depth buffers as text files (docs/design.md): H lines, top row first, of W x N values,
// each pixel's N samples together in the order of the sample pattern.
#pragma once

#include <rast/scene.h>

#include <string>

namespace rast::cli {

// Each sample's owning triangle id, or -1.
std::string format_ids(const Framebuffer& fb);
// Each sample's depth as a decimal that reads back to the same double, or "inf" where empty.
std::string format_depth(const Framebuffer& fb);

}  // namespace rast::cli
