// rast — the id and depth buffers as text files (docs/design.md: H lines of W values, top row first).
#pragma once

#include <rast/scene.h>

#include <string>

namespace rast::cli {

// Preconditions: fb.samples == 1 (the files describe pixel centres).
// Each pixel centre's owning triangle id, or -1.
std::string format_ids(const Framebuffer& fb);
// Each pixel centre's depth as a decimal that reads back to the same double, or "inf" where empty.
std::string format_depth(const Framebuffer& fb);

}  // namespace rast::cli
