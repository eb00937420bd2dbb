// Input checks shared by the reference's entry points: bad input is an exception naming what is wrong,
// never undefined behaviour inside the exact arithmetic (a NaN has no rational value).
#pragma once

#include <rast/scene.h>
#include <rast/scene_limits.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rast::reference::detail {

// The engines' limits (rast/scene_limits.h), checked before anything is sized for them.
inline void require_valid(Viewport vp, int samples) { check_framebuffer(vp, samples, "rast::reference"); }

// `id` names the triangle in the message when the caller knows it.
inline void require_finite(const Triangle& t, std::optional<std::size_t> id = std::nullopt) {
    for (std::size_t k = 0; k < t.v.size(); ++k) {
        const Vertex& v = t.v[k];
        if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) continue;
        std::ostringstream msg;
        msg << "triangle ";
        if (id) msg << *id << " ";
        msg << "vertex " << k << " (" << v.x << ", " << v.y << ", " << v.z
            << ") has a coordinate that is not finite";
        throw std::invalid_argument(msg.str());
    }
}

// `id` names the line in the message when the caller knows it.
inline void require_finite(const Segment& s, std::optional<std::size_t> id = std::nullopt) {
    for (std::size_t e = 0; e < s.v.size(); ++e) {
        const Vertex& v = s.v[e];
        if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) continue;
        std::ostringstream msg;
        msg << (id ? "line " + std::to_string(*id) + " " : std::string("segment ")) << "end " << e << " (" << v.x
            << ", " << v.y << ", " << v.z << ") has a coordinate that is not finite";
        throw std::invalid_argument(msg.str());
    }
}

}  // namespace rast::reference::detail
