// The checks of the public functions' input: bad input is a std::invalid_argument saying what is wrong
// (when, fast.h says).
#pragma once

#include <rast/fast.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace rast::fast::detail {

inline void validate(Viewport vp, int samples) {
    constexpr int kMaxSide = 1 << 24;  // pixel indices convert exactly to float in the float32 kernel
    if (vp.width < 1 || vp.height < 1 || vp.width > kMaxSide || vp.height > kMaxSide)
        throw std::invalid_argument("rast::fast: viewport " + std::to_string(vp.width) + "x" +
                                    std::to_string(vp.height) + " is not 1..2^24 pixels on each side");
    if (!is_supported_sample_count(samples))
        throw std::invalid_argument("rast::fast: unsupported sample count " + std::to_string(samples) +
                                    " (expected 1, 4, 8 or 16)");
    // Checked before anything is sized for it: a framebuffer of 2^48 samples is no allocation to attempt.
    constexpr std::uint64_t kMaxSamples = std::uint64_t{1} << 32;
    const std::uint64_t total = std::uint64_t(vp.width) * std::uint64_t(vp.height) * std::uint64_t(samples);
    if (total > kMaxSamples)
        throw std::invalid_argument("rast::fast: viewport " + std::to_string(vp.width) + "x" +
                                    std::to_string(vp.height) + " with " + std::to_string(samples) +
                                    " samples per pixel has " + std::to_string(total) +
                                    " samples, more than 2^32");
}

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
