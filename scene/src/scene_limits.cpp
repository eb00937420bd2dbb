#include "rast/scene_limits.h"

#include <stdexcept>
#include <string>

namespace rast {

namespace {
void check_side(const char* name, int value) {
    if (value <= 0)
        throw std::invalid_argument(std::string("viewport ") + name + " must be positive, got " +
                                    std::to_string(value));
    if (value > kMaxViewportSide)
        throw std::invalid_argument(std::string("viewport ") + name + " " + std::to_string(value) +
                                    " exceeds the limit " + std::to_string(kMaxViewportSide));
}
}  // namespace

void check_viewport(Viewport viewport) {
    check_side("width", viewport.width);
    check_side("height", viewport.height);
}

void check_sample_count(int samples) {
    if (!is_supported_sample_count(samples))
        throw std::invalid_argument("samples must be 1, 4, 8 or 16, got " + std::to_string(samples));
}

void check_scene_size(Viewport viewport, int samples) {
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
