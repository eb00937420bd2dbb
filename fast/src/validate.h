// The checks of the public functions' input: bad input is a std::invalid_argument saying what is wrong
// (when, fast.h says).
#pragma once

#include <rast/fast.h>
#include <rast/scene_limits.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace rast::fast::detail {

inline void validate(Viewport vp, int samples) { check_framebuffer(vp, samples, "rast::fast"); }

inline bool is_finite(const Vertex& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

inline bool is_finite(const Triangle& t) { return is_finite(t.v[0]) && is_finite(t.v[1]) && is_finite(t.v[2]); }

inline void validate(const Triangle& t, std::size_t id) {
    for (int k = 0; k < 3; ++k)
        if (!is_finite(t.v[k]))
            throw std::invalid_argument("rast::fast: triangle " + std::to_string(id) + ", vertex " +
                                        std::to_string(k) + ": coordinate is not a finite number");
}

inline void validate(Precision p) {
    if (name(p) == "unknown")
        throw std::invalid_argument("rast::fast: precision " + std::to_string(static_cast<int>(p)) +
                                    " is not one of the enum's values");
}

// TBB's arena does not survive a count in the tens of thousands.
inline void validate_threads(int threads) {
    constexpr int kMaxThreads = 1024;
    if (threads < 0 || threads > kMaxThreads)
        throw std::invalid_argument("rast::fast: thread count " + std::to_string(threads) + " is not 0..1024");
}

inline void validate_sample(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y))
        throw std::invalid_argument("rast::fast: sample coordinate is not a finite number");
}

}  // namespace rast::fast::detail
