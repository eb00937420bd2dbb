#include <rast/properties.h>
#include <rast/reference.h>

#include <rast/exact_geometry.h>

namespace rast::properties {

bool Engine::exact() const { return !precision || snap_bits().has_value(); }

std::optional<int> Engine::snap_bits() const {
    if (!precision) return std::nullopt;
    switch (*precision) {
        case fast::Precision::fixed4: return 4;
        case fast::Precision::fixed8: return 8;
        case fast::Precision::fixed16: return 16;
        case fast::Precision::float32:
        case fast::Precision::float64: return std::nullopt;
    }
    return std::nullopt;
}

Scene Engine::rasterized_geometry(const Scene& scene) const {
    const auto bits = snap_bits();
    if (!bits) return scene;
    Scene snapped = scene;
    for (Triangle& t : snapped.triangles) t = snap(t, *bits);
    return snapped;
}

Engine reference_engine() {
    return {"reference", std::nullopt, [](const Scene& s) { return reference::render(s); },
            [](const Triangle& t, Viewport vp, int n) { return reference::covered_samples(t, vp, n); },
            nullptr};
}

Engine fast_engine(fast::Precision p) {
    return {std::string(fast::name(p)), p,
            [p](const Scene& s) { return fast::render(s, {p, 1}); },
            [p](const Triangle& t, Viewport vp, int n) { return fast::covered_samples(t, vp, n, p); },
            [p](const Triangle& t, double x, double y) { return fast::edge_error_bound_at(t, p, x, y); }};
}

std::vector<Engine> all_engines() {
    std::vector<Engine> engines{reference_engine()};
    for (auto p : {fast::Precision::fixed4, fast::Precision::fixed8, fast::Precision::fixed16,
                   fast::Precision::float32, fast::Precision::float64})
        engines.push_back(fast_engine(p));
    return engines;
}

}  // namespace rast::properties
