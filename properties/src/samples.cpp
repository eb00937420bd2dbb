#include "samples.h"

#include <algorithm>
#include <cmath>

namespace rast::properties {

std::size_t sample_count(Viewport vp, int samples) {
    return static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height) *
           static_cast<std::size_t>(samples);
}

Sample sample_at(Viewport vp, int samples, std::size_t index) {
    const auto pattern = sample_pattern(samples);
    const int s = static_cast<int>(index % static_cast<std::size_t>(samples));
    const std::size_t pixel = index / static_cast<std::size_t>(samples);
    const int i = static_cast<int>(pixel % static_cast<std::size_t>(vp.width));
    const int j = static_cast<int>(pixel / static_cast<std::size_t>(vp.width));
    return {i, j, s, i + pattern[s].x, j + pattern[s].y, index};
}

namespace {
// Pixel k holds samples in [k, k + 1], so a coordinate c reaches pixels floor(c) - 1 .. floor(c); the
// clamp happens in double so that coordinates far beyond int's range stay safe.
int clamp_pixel(double c, int size) {
    return static_cast<int>(std::clamp(c, -1.0, static_cast<double>(size)));
}
}  // namespace

PixelRange pixel_range(const Triangle& t, Viewport vp) {
    const auto [x0, x1] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [y0, y1] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    PixelRange r{clamp_pixel(std::floor(x0) - 1, vp.width), clamp_pixel(std::floor(x1), vp.width),
                 clamp_pixel(std::floor(y0) - 1, vp.height), clamp_pixel(std::floor(y1), vp.height)};
    r.i0 = std::max(r.i0, 0);
    r.j0 = std::max(r.j0, 0);
    r.i1 = std::min(r.i1, vp.width - 1);
    r.j1 = std::min(r.j1, vp.height - 1);
    return r;
}

std::string describe(const Sample& at) {
    return "pixel (" + std::to_string(at.i) + ", " + std::to_string(at.j) + ") sample " +
           std::to_string(at.s) + " at (" + shortest(at.x) + ", " + shortest(at.y) + ")";
}

std::string describe(const Triangle& t, std::size_t id) {
    std::string text = "#";
    text += std::to_string(id);
    for (int k = 0; k < 3; ++k)
        text += (k ? ", (" : " (") + shortest(t.v[k].x) + ", " + shortest(t.v[k].y) + ")";
    return text;
}

}  // namespace rast::properties
