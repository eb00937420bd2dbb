// rast — how large a scene may be: every buffer of a rendered scene must fit in memory.
#pragma once

#include <cstdint>

#include "rast/scene.h"

namespace rast {

// Width and height are each at most 32768, and width * height * samples at most 2^28 (a 16384^2 image
// with one sample, or 4096^2 with 16): the id and depth buffers then take at most 3 GiB.
inline constexpr int kMaxViewportSide = 32768;
inline constexpr std::int64_t kMaxSamplesPerImage = std::int64_t{1} << 28;

// Each throws std::invalid_argument saying what is wrong. check_viewport: both sides positive and at
// most kMaxViewportSide; check_sample_count: 1, 4, 8 or 16; check_scene_size: both, and the product
// within kMaxSamplesPerImage.
void check_viewport(Viewport viewport);
void check_sample_count(int samples);
void check_scene_size(Viewport viewport, int samples);

}  // namespace rast
