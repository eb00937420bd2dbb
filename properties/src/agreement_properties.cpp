// fixed_matches_reference, float_within_bound and msaa_counts: the fast path held against the exact
// answer, as tightly as its precision mode promises.
#include <rast/reference.h>

#include <array>
#include <cmath>

#include "checks.h"
#include <rast/exact_geometry.h>
#include "samples.h"

namespace rast::properties {

// A fixed mode is the reference run on the snapped vertices: the same samples per triangle and the
// same rendered ids, bit for bit. (Depth values are the fast path's double plane values, not
// promised bit-exact; the (z, id) decisions they lead to are.)
Outcome fixed_matches_reference(const Scene& scene, const Engine& engine) {
    const Scene snapped = rasterized_geometry(engine, scene);
    const Viewport vp = scene.viewport;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k)
        if (auto diff = first_difference(engine.covered_samples(scene.triangles[k], vp, scene.samples), engine.name,
                                         reference::covered_samples(snapped.triangles[k], vp, scene.samples),
                                         "the reference on the snapped triangle", vp, scene.samples))
            return Outcome::fail("triangle " + describe(scene.triangles[k], k) + ", " + *diff);
    if (auto diff = first_difference(engine.render(scene), engine.name, reference::render(snapped),
                                     "the reference on the snapped scene", false))
        return Outcome::fail(*diff);
    return Outcome::pass();
}

// A float mode classifies a sample differently from the reference only where the sample is within
// the mode's stated error bound at that sample of one of the triangle's edges:
// |E_exact(p)| <= edge_error_bound_at(p)[e]. Per sample and edge, not the viewport's worst case, so that
// an error that grows along a row (accumulation) is caught near an edge's start, where its bound is small.
Outcome float_within_bound(const Scene& scene, const Engine& engine) {
    const Viewport vp = scene.viewport;
    const int n = scene.samples;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const Triangle& t = scene.triangles[k];
        const auto fast = engine.covered_samples(t, vp, n);
        const auto exact = reference::covered_samples(t, vp, n);
        std::size_t a = 0, b = 0;
        while (a < fast.size() || b < exact.size()) {
            if (a < fast.size() && b < exact.size() && fast[a] == exact[b]) {
                ++a, ++b;
                continue;
            }
            const bool only_fast = b == exact.size() || (a < fast.size() && fast[a] < exact[b]);
            const Sample at = sample_at(vp, n, only_fast ? fast[a++] : exact[b++]);
            const std::array<double, 3> bound = engine.edge_error_bound_at(t, at.x, at.y);
            bool near_an_edge = false;
            for (int e = 0; e < 3 && !near_an_edge; ++e) {
                const Rational value = edge_function(t.v[e], t.v[(e + 1) % 3], at.x, at.y);
                near_an_edge = !std::isfinite(bound[e]) || (value < 0 ? Rational(-value) : value) <= Rational(bound[e]);
            }
            if (!near_an_edge)
                return Outcome::fail("triangle " + describe(t, k) + ", " + describe(at) + ": " + engine.name +
                                     (only_fast ? " covers" : " does not cover") + ", the reference " +
                                     (only_fast ? "does not" : "does") + ", yet every edge function there exceeds " +
                                     "its error bound there (" + shortest(bound[0]) + ", " + shortest(bound[1]) + ", " +
                                     shortest(bound[2]) + ") in magnitude");
        }
    }
    return Outcome::pass();
}

// With several samples per pixel, the number of covered samples in each pixel of the rendered image
// equals the number the exact tie rule covers on the geometry the engine rasterizes.
Outcome msaa_counts(const Scene& scene, const Engine& engine) {
    const Scene geometry = rasterized_geometry(engine, scene);
    const Viewport vp = scene.viewport;
    const int n = scene.samples;
    std::vector<char> covered(sample_count(vp, n), 0);
    for (const Triangle& t : geometry.triangles)
        for_each_sample(pixel_range(t, vp), vp, n, [&](const Sample& at) {
            if (rule_covers(t, at.x, at.y)) covered[at.index] = 1;
        });
    const Framebuffer image = engine.render(scene);
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            int rendered = 0, expected = 0;
            for (int s = 0; s < n; ++s) {
                rendered += image.id(i, j, s) != Framebuffer::kNoTriangle;
                expected += covered[image.index(i, j, s)];
            }
            if (rendered != expected)
                return Outcome::fail("pixel (" + std::to_string(i) + ", " + std::to_string(j) + "): " + engine.name +
                                     " covers " + std::to_string(rendered) + " of its " + std::to_string(n) +
                                     " samples, the tie rule " + std::to_string(expected));
        }
    return Outcome::pass();
}

}  // namespace rast::properties
