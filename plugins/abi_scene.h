// rast — a plugin's scene (rast/plugin.h) as a rast::Scene, for the plugins built on rast's own code.
#pragma once

#include <rast/plugin.h>
#include <rast/scene.h>

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

}  // namespace rast::plugins
