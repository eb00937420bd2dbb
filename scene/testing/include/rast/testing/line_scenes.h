// rast, for tests — the small scenes the engines' hand-worked line tests share: each engine's tests hold
// the same cases, and fast_tests does not link the reference.
#pragma once

#include <rast/scene.h>

#include <cstdint>
#include <vector>

namespace rast::testing {

inline Segment segment(Vertex a, Vertex b) { return {{a, b}}; }

// A triangle covering the whole of a viewport of up to 16 pixels a side, of depth z = a x + b y + c.
inline Triangle backdrop(double a, double b, double c) {
    const auto at = [&](double x, double y) { return Vertex{x, y, a * x + b * y + c}; };
    return {{at(-8, -8), at(24, -8), at(-8, 24)}};
}

// The ids of row j, one per pixel (sample 0).
inline std::vector<std::int32_t> row(const Framebuffer& fb, int j) {
    std::vector<std::int32_t> ids;
    for (int i = 0; i < fb.viewport.width; ++i) ids.push_back(fb.id(i, j));
    return ids;
}

}  // namespace rast::testing
