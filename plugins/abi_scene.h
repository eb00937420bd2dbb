// rast — what the plugins built on rast's own code do around their work: the ABI's scene as a rast::Scene,
// and the ids and errors handed back.
#pragma once

#include <rast/plugin.h>
#include <rast/scene.h>

#include <algorithm>
#include <cstdio>
#include <exception>

namespace rast::plugins {

inline Scene scene_of(const rast_plugin_scene& given) {
    Scene scene{{given.width, given.height}, given.samples, {}};
    scene.triangles.resize(given.triangle_count);
    const double* v = given.vertices;
    for (Triangle& t : scene.triangles)
        for (Vertex& corner : t.v) {
            corner = {v[0], v[1], v[2]};
            v += 3;
        }
    return scene;
}

// rast_plugin_render's answer: the ids of the framebuffer `render()` makes, or its exception as the error.
template <class Render>
int answer(std::int32_t* ids, char* err, std::size_t errlen, Render render) noexcept {
    try {
        const Framebuffer fb = render();
        std::copy(fb.ids.begin(), fb.ids.end(), ids);
        return 0;
    } catch (const std::exception& e) {
        std::snprintf(err, errlen, "%s", e.what());
        return 1;
    }
}

}  // namespace rast::plugins
