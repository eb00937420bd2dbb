#include "default_scene.h"

#include <cmath>
#include <numbers>

namespace rast::cli {

// 192 x 128 pixels, chosen so that every case of Lecture 05 is visible and the exact reference renders it in
// well under a second:
//   - a far background triangle larger than the viewport (bounding box clamped to the viewport);
//   - a square split on its diagonal, all vertices on pixel centres (the tie rule owns each diagonal
//     centre exactly once);
//   - a closed fan of 8 triangles around a pixel centre (covered exactly once);
//   - two interpenetrating triangles whose depth order flips along a line (the z-buffer, not a painter);
//   - a coplanar pair at equal depth, decided by id;
//   - needles thinner than a pixel (aliasing: jaggies and gaps at one sample per pixel).
Scene default_scene() {
    Scene scene;
    scene.viewport = {192, 128};
    auto& t = scene.triangles;

    t.push_back({{{{-200, -100, 0.95}, {400, -100, 0.95}, {96, 400, 0.95}}}});

    t.push_back({{{{8.5, 8.5, 0.5}, {56.5, 8.5, 0.5}, {56.5, 56.5, 0.5}}}});
    t.push_back({{{{8.5, 8.5, 0.5}, {56.5, 56.5, 0.5}, {8.5, 56.5, 0.5}}}});

    const Vertex centre{96.5, 60.5, 0.4};
    constexpr int kFan = 8;
    for (int k = 0; k < kFan; ++k) {
        const double a0 = 2 * std::numbers::pi * k / kFan, a1 = 2 * std::numbers::pi * (k + 1) / kFan;
        // Rim vertices rounded to pixel centres, so fan edges pass through samples.
        const Vertex p0{std::round(28 * std::cos(a0)) + centre.x, std::round(28 * std::sin(a0)) + centre.y, 0.4};
        const Vertex p1{std::round(28 * std::cos(a1)) + centre.x, std::round(28 * std::sin(a1)) + centre.y, 0.4};
        t.push_back({{{centre, p0, p1}}});
    }

    t.push_back({{{{132, 12, 0.2}, {186, 30, 0.8}, {146, 104, 0.2}}}});
    t.push_back({{{{188, 14, 0.2}, {134, 60, 0.8}, {184, 110, 0.3}}}});

    t.push_back({{{{20, 70, 0.3}, {60, 70, 0.3}, {40, 110, 0.3}}}});
    t.push_back({{{{30, 80, 0.3}, {70, 90, 0.3}, {30, 120, 0.3}}}});

    t.push_back({{{{4, 122.2, 0.1}, {188, 119.6, 0.1}, {4, 121.7, 0.1}}}});
    t.push_back({{{{140, 4, 0.1}, {141.3, 124, 0.1}, {140.6, 4, 0.1}}}});
    return scene;
}

}  // namespace rast::cli
