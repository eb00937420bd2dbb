#include <rast/exact_geometry.h>
#include <rast/properties.h>

namespace rast::properties {

Triangle rasterized_geometry(const Engine& engine, const Triangle& t) {
    const auto& contract = engine.contract;
    return contract && contract->snap ? snap(t, *contract->snap, contract->rounding) : t;
}

Scene rasterized_geometry(const Engine& engine, const Scene& scene) {
    Scene geometry = scene;
    for (Triangle& t : geometry.triangles) t = rasterized_geometry(engine, t);
    return geometry;
}

}  // namespace rast::properties
