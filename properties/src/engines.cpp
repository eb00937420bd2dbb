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
    const auto& contract = engine.contract;
    if (contract && contract->snap)
        for (Line& line : geometry.lines) line.segment = snap(line.segment, *contract->snap, contract->rounding);
    return geometry;
}

}  // namespace rast::properties
