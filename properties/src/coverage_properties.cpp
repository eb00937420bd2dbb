// watertight and tie_rule: coverage judged sample by sample against exact geometry.
#include <map>
#include <utility>

#include "checks.h"
#include <rast/exact_geometry.h>
#include "samples.h"

namespace rast::properties {

namespace {

using Point = std::pair<double, double>;
using EdgeKey = std::pair<Point, Point>;

EdgeKey edge_key(const Vertex& a, const Vertex& b) {
    Point p{a.x, a.y}, q{b.x, b.y};
    if (q < p) std::swap(p, q);
    return {p, q};
}

}  // namespace

std::optional<Outcome> folded_by_snapping(const Scene& scene, const Scene& geometry, const Engine& engine) {
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const int before = orientation(scene.triangles[k]);
        const int after = orientation(geometry.triangles[k]);
        if (after != 0 && after != before)
            return Outcome::not_applicable("snapping to the " + engine.name + " grid folds triangle " +
                                           describe(scene.triangles[k], k));
    }
    return std::nullopt;
}

// A triangulated region with exactly shared vertices: every sample in the closed union and on no
// boundary edge (an edge of only one non-degenerate triangle) is covered exactly once; no sample is
// covered twice; no sample outside the union is covered.
Outcome watertight(const Scene& scene, const Engine& engine) {
    const Scene geometry = rasterized_geometry(engine, scene);
    if (auto folded = folded_by_snapping(scene, geometry, engine)) return *folded;
    const Viewport vp = scene.viewport;
    const int n = scene.samples;

    std::map<EdgeKey, int> edge_uses;
    for (const Triangle& t : geometry.triangles)
        if (orientation(t) != 0)
            for (int e = 0; e < 3; ++e) ++edge_uses[edge_key(t.v[e], t.v[(e + 1) % 3])];

    std::vector<char> in_union(sample_count(vp, n), 0), on_boundary(sample_count(vp, n), 0);
    for (const Triangle& t : geometry.triangles) {
        if (orientation(t) == 0) continue;
        for_each_sample(pixel_range(t, vp), vp, n, [&](const Sample& at) {
            const Location where = locate(t, at.x, at.y);
            if (where == Location::outside) return;
            in_union[at.index] = 1;
            if (where == Location::inside) return;
            for (int e = 0; e < 3; ++e) {
                const Vertex& a = t.v[e];
                const Vertex& b = t.v[(e + 1) % 3];
                if (edge_uses.at(edge_key(a, b)) == 1 && edge_sign(a, b, at.x, at.y) == 0) on_boundary[at.index] = 1;
            }
        });
    }

    std::vector<int> owner(sample_count(vp, n), -1);
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const int id = static_cast<int>(k);
        for (std::size_t index : engine.covered_samples(scene.triangles[k], vp, n)) {
            const Sample at = sample_at(vp, n, index);
            if (owner[index] >= 0)
                return Outcome::fail(describe(at) + ": " + engine.name + " covers it twice, by triangle " +
                                     std::to_string(owner[index]) + " and triangle " + std::to_string(id));
            if (!in_union[index])
                return Outcome::fail(describe(at) + ": outside every triangle, yet " + engine.name +
                                     " covers it by triangle " + describe(scene.triangles[k], k));
            owner[index] = id;
        }
    }
    for (std::size_t index = 0; index < owner.size(); ++index)
        if (in_union[index] && !on_boundary[index] && owner[index] < 0)
            return Outcome::fail(describe(sample_at(vp, n, index)) +
                                 ": inside the triangulated region, off its boundary, yet " + engine.name +
                                 " covers it by no triangle");
    return Outcome::pass();
}

// Each triangle covers exactly the samples docs/design.md's rule gives it: strictly inside, or on a
// left or top edge, or on a vertex whose two edges are both left or top.
Outcome tie_rule(const Scene& scene, const Engine& engine) {
    const Scene geometry = rasterized_geometry(engine, scene);
    const Viewport vp = scene.viewport;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const Triangle& t = geometry.triangles[k];
        std::vector<std::size_t> expected;
        for_each_sample(pixel_range(t, vp), vp, scene.samples, [&](const Sample& at) {
            if (rule_covers(t, at.x, at.y)) expected.push_back(at.index);
        });
        if (auto diff = first_difference(engine.covered_samples(scene.triangles[k], vp, scene.samples),
                                         engine.name, expected, "the tie rule", vp, scene.samples))
            return Outcome::fail("triangle " + describe(t, k) + ", " + *diff);
    }
    return Outcome::pass();
}

}  // namespace rast::properties
