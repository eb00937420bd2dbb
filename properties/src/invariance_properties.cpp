// winding_invariance and translation_invariance: the same geometry, presented differently, rasterizes
// the same.
#include <array>
#include <cmath>
#include <utility>

#include "checks.h"
#include "samples.h"

namespace rast::properties {

namespace {

// The five vertex orders other than the given one: two rotations and three reflections.
constexpr std::array<std::array<int, 3>, 5> kOtherOrders{{{1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};

Triangle reorder(const Triangle& t, const std::array<int, 3>& order) {
    return {{t.v[order[0]], t.v[order[1]], t.v[order[2]]}};
}

std::string order_name(const std::array<int, 3>& order) {
    return "(v" + std::to_string(order[0]) + ", v" + std::to_string(order[1]) + ", v" +
           std::to_string(order[2]) + ")";
}

}  // namespace

// Every vertex order of a triangle covers the same samples, and reversing every triangle's winding
// leaves the rendered id buffer (and the reference's depths) unchanged.
Outcome winding_invariance(const Scene& scene, const Engine& engine) {
    const Viewport vp = scene.viewport;
    const int n = scene.samples;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const Triangle& t = scene.triangles[k];
        const auto base = engine.covered_samples(t, vp, n);
        for (const auto& order : kOtherOrders)
            if (auto diff = first_difference(base, "(v0, v1, v2)", engine.covered_samples(reorder(t, order), vp, n),
                                             order_name(order), vp, n))
                return Outcome::fail(engine.name + ", triangle " + describe(t, k) + ", " + *diff);
    }
    Scene reversed = scene;
    for (Triangle& t : reversed.triangles) std::swap(t.v[1], t.v[2]);
    Framebuffer given = engine.render(scene), turned = engine.render(reversed);
    // Under depth=none an engine promises which samples are covered, not by which triangle (id 0 here).
    if (engine.contract && !engine.contract->zid)
        for (Framebuffer* fb : {&given, &turned})
            for (std::int32_t& id : fb->ids) id = id == Framebuffer::kNoTriangle ? id : 0;
    if (auto diff = first_difference(given, "the scene", turned, "the scene with every winding reversed",
                                     engine.exact_depth()))
        return Outcome::fail(engine.name + ", " + *diff);
    return Outcome::pass();
}

namespace {

bool exact_sum(double a, double b) {
    // Knuth's two-sum: the rounding error of a + b, zero exactly when the sum is exact.
    const double s = a + b;
    const double bb = s - a;
    return (a - (s - bb)) + (b - bb) == 0 && std::isfinite(s);
}

struct Shift {
    int dx, dy;
};

// Shifts by whole pixels, each paired with a viewport grown by the same amount so that every pixel of
// the original has its image. The last one crosses the fast path's 64-pixel tile boundaries.
constexpr std::array<Shift, 4> kShifts{{{1, 0}, {0, 1}, {5, 3}, {67, 61}}};

std::optional<Scene> shifted(const Scene& scene, Shift d) {
    Scene moved = scene;
    moved.viewport = {scene.viewport.width + d.dx, scene.viewport.height + d.dy};
    for (Triangle& t : moved.triangles)
        for (Vertex& v : t.v) {
            if (!exact_sum(v.x, d.dx) || !exact_sum(v.y, d.dy)) return std::nullopt;
            v.x += d.dx;
            v.y += d.dy;
        }
    return moved;
}

}  // namespace

// Moving the scene by whole pixels moves its rasterization by the same pixels: per-triangle coverage
// and the rendered ids (and the reference's depths) are unchanged. Shifts that would round a
// coordinate are skipped: they change the geometry.
Outcome translation_invariance(const Scene& scene, const Engine& engine) {
    const Viewport vp = scene.viewport;
    const int n = scene.samples;
    bool any = false;
    for (const Shift d : kShifts) {
        const auto moved = shifted(scene, d);
        if (!moved) continue;
        any = true;
        const auto image = [&](std::size_t index) {
            const Sample at = sample_at(vp, n, index);
            return (static_cast<std::size_t>(at.j + d.dy) * static_cast<std::size_t>(moved->viewport.width) +
                    static_cast<std::size_t>(at.i + d.dx)) * static_cast<std::size_t>(n) +
                   static_cast<std::size_t>(at.s);
        };
        const std::string name = "moved by (" + std::to_string(d.dx) + ", " + std::to_string(d.dy) + ")";
        for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
            std::vector<std::size_t> expected;
            for (std::size_t index : engine.covered_samples(scene.triangles[k], vp, n)) expected.push_back(image(index));
            std::vector<std::size_t> actual;
            for (std::size_t index : engine.covered_samples(moved->triangles[k], moved->viewport, n)) {
                const Sample at = sample_at(moved->viewport, n, index);
                if (at.i >= d.dx && at.j >= d.dy) actual.push_back(index);
            }
            if (auto diff = first_difference(actual, name, expected, "the original, moved", moved->viewport, n))
                return Outcome::fail(engine.name + ", triangle " + describe(scene.triangles[k], k) + " " + *diff);
        }
        const Framebuffer original = engine.render(scene);
        Framebuffer expected(moved->viewport, n);
        for (std::size_t index = 0; index < original.ids.size(); ++index) {
            expected.ids[image(index)] = original.ids[index];
            expected.depth[image(index)] = original.depth[index];
        }
        Framebuffer actual = engine.render(*moved);
        for (std::size_t index = 0; index < actual.ids.size(); ++index) {
            const Sample at = sample_at(moved->viewport, n, index);
            if (at.i < d.dx || at.j < d.dy) {
                actual.ids[index] = expected.ids[index];
                actual.depth[index] = expected.depth[index];
            }
        }
        if (auto diff = first_difference(actual, engine.name + " " + name, expected, "the original, moved",
                                         engine.exact_depth()))
            return Outcome::fail(*diff);
    }
    if (!any) return Outcome::not_applicable("no whole-pixel shift keeps every coordinate exact");
    return Outcome::pass();
}

}  // namespace rast::properties
