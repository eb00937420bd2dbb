// rast — how large a scene may be, in one place: what the engines can represent, and what rast itself
// reads and makes. Header-only: the installed fast library checks its input with it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rast/scene.h"

namespace rast {

// The engines (rast::fast, rast::reference): each side at most 2^24, so that a pixel index converts
// exactly to float in the float32 kernel; at most 2^32 samples (a 48 GiB framebuffer), checked before
// anything is sized for them.
inline constexpr int kMaxEngineSide = 1 << 24;
inline constexpr std::uint64_t kMaxEngineSamples = std::uint64_t{1} << 32;

// Scenes read from files and made by the command line: width and height each at most 32768, and
// width * height * samples at most 2^28 (a 16384^2 image with one sample, or 4096^2 with 16), so that the
// id and depth buffers take at most 3 GiB.
inline constexpr int kMaxViewportSide = 32768;
inline constexpr std::int64_t kMaxSamplesPerImage = std::int64_t{1} << 28;

// An engine's framebuffer: throws std::invalid_argument, its message starting with `who`, for a side
// outside 1..kMaxEngineSide, a sample count other than 1, 4, 8 or 16, or more than kMaxEngineSamples.
inline void check_framebuffer(Viewport vp, int samples, std::string_view who) {
    const std::string name(who);
    if (vp.width < 1 || vp.height < 1 || vp.width > kMaxEngineSide || vp.height > kMaxEngineSide)
        throw std::invalid_argument(name + ": viewport " + std::to_string(vp.width) + "x" + std::to_string(vp.height) +
                                    " is not 1..2^24 pixels on each side");
    if (!is_supported_sample_count(samples))
        throw std::invalid_argument(name + ": unsupported sample count " + std::to_string(samples) +
                                    " (expected 1, 4, 8 or 16)");
    const std::uint64_t total = std::uint64_t(vp.width) * std::uint64_t(vp.height) * std::uint64_t(samples);
    if (total > kMaxEngineSamples)
        throw std::invalid_argument(name + ": viewport " + std::to_string(vp.width) + "x" + std::to_string(vp.height) +
                                    " with " + std::to_string(samples) + " samples per pixel has " +
                                    std::to_string(total) + " samples, more than 2^32");
}

// A scene's limits. Each throws std::invalid_argument saying what is wrong. check_viewport: both sides
// positive and at most kMaxViewportSide; check_sample_count: 1, 4, 8 or 16; check_scene_size: both, and
// the product within kMaxSamplesPerImage.
inline void check_viewport(Viewport viewport) {
    const auto side = [](const char* name, int value) {
        if (value <= 0)
            throw std::invalid_argument(std::string("viewport ") + name + " must be positive, got " +
                                        std::to_string(value));
        if (value > kMaxViewportSide)
            throw std::invalid_argument(std::string("viewport ") + name + " " + std::to_string(value) +
                                        " exceeds the limit " + std::to_string(kMaxViewportSide));
    };
    side("width", viewport.width);
    side("height", viewport.height);
}

inline void check_sample_count(int samples) {
    if (!is_supported_sample_count(samples))
        throw std::invalid_argument("samples must be 1, 4, 8 or 16, got " + std::to_string(samples));
}

inline void check_scene_size(Viewport viewport, int samples) {
    check_viewport(viewport);
    check_sample_count(samples);
    const std::int64_t total = std::int64_t{viewport.width} * viewport.height * samples;
    if (total > kMaxSamplesPerImage)
        throw std::invalid_argument("viewport " + std::to_string(viewport.width) + "x" +
                                    std::to_string(viewport.height) + " with " + std::to_string(samples) +
                                    " samples per pixel has " + std::to_string(total) +
                                    " samples, above the limit " + std::to_string(kMaxSamplesPerImage));
}

}  // namespace rast
