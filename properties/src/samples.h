// rast properties — the samples of a viewport: where each one is, which of them a triangle can reach,
// and how a failure names one.
#pragma once

#include <rast/number_text.h>
#include <rast/scene.h>

#include <cstddef>
#include <string>

namespace rast::properties {

struct Sample {
    int i, j, s;     // pixel and sample number
    double x, y;     // screen position, exact
    std::size_t index;  // Framebuffer::index
};

Sample sample_at(Viewport vp, int samples, std::size_t index);
std::size_t sample_count(Viewport vp, int samples);

// The pixels whose samples can touch a triangle's bounding box, clipped to the viewport; empty
// (i1 < i0 or j1 < j0) when it lies outside.
struct PixelRange {
    int i0, i1, j0, j1;  // inclusive
};
PixelRange pixel_range(const Triangle& t, Viewport vp);

// Calls f(Sample) for every sample of every pixel in the range.
template <typename F>
void for_each_sample(PixelRange r, Viewport vp, int samples, F&& f) {
    const auto pattern = sample_pattern(samples);
    for (int j = r.j0; j <= r.j1; ++j)
        for (int i = r.i0; i <= r.i1; ++i)
            for (int s = 0; s < samples; ++s) {
                const Sample at{i, j, s, i + pattern[s].x, j + pattern[s].y,
                                (static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) +
                                 static_cast<std::size_t>(i)) * static_cast<std::size_t>(samples) +
                                    static_cast<std::size_t>(s)};
                f(at);
            }
}

inline PixelRange whole(Viewport vp) { return {0, vp.width - 1, 0, vp.height - 1}; }

using rast::shortest;

// "pixel (i, j) sample s at (x, y)"
std::string describe(const Sample& at);

// A triangle as "#id (x0, y0), (x1, y1), (x2, y2)" with shortest round-trip decimals.
std::string describe(const Triangle& t, std::size_t id);

}  // namespace rast::properties
