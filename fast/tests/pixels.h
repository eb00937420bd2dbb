// Test helpers: covered samples as a set of pixels, for single-sample hand cases.
#pragma once

#include <rast/fast.h>

#include <set>
#include <utility>

namespace rast::fast::testing {

using Pixels = std::set<std::pair<int, int>>;

inline Pixels covered_pixels(const Triangle& t, Viewport vp, Precision p) {
    Pixels out;
    for (std::size_t index : covered_samples(t, vp, 1, p))
        out.insert({static_cast<int>(index % vp.width), static_cast<int>(index / vp.width)});
    return out;
}

// The pixels render() gives to triangle 0 when it is drawn alone: the path a scene takes, where
// covered_pixels takes the one for a single triangle.
inline Pixels rendered_pixels(const Triangle& t, Viewport vp, Precision p) {
    Scene scene;
    scene.viewport = vp;
    scene.triangles = {t};
    const Framebuffer fb = render(scene, {p, 1});
    Pixels out;
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i)
            if (fb.id(i, j) == 0) out.insert({i, j});
    return out;
}

inline constexpr Precision kAllPrecisions[] = {Precision::fixed4, Precision::fixed8, Precision::fixed16,
                                               Precision::float32, Precision::float64};

inline Triangle tri(double x0, double y0, double x1, double y1, double x2, double y2, double z = 0.5) {
    return {{{{x0, y0, z}, {x1, y1, z}, {x2, y2, z}}}};
}

}  // namespace rast::fast::testing
