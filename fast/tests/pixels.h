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

inline constexpr Precision kAllPrecisions[] = {Precision::fixed4, Precision::fixed8, Precision::fixed16,
                                               Precision::float32, Precision::float64};

inline Triangle tri(double x0, double y0, double x1, double y1, double x2, double y2, double z = 0.5) {
    return {{{{x0, y0, z}, {x1, y1, z}, {x2, y2, z}}}};
}

}  // namespace rast::fast::testing
