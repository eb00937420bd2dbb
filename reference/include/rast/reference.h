// rast — the exact reference rasterizer.
//
// Every sample-versus-edge decision is a CGAL orientation predicate on the input doubles (filtered:
// exact arithmetic only where the floating-point filter cannot decide); samples exactly on an edge or a
// vertex follow the tie rule of docs/design.md; depths are compared exactly as rationals with the
// (z, id) total order. Any finite double coordinate is valid.
#pragma once

#include <rast/progress.h>
#include <rast/scene.h>

#include <boost/multiprecision/gmp.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rast::reference {

using Rational = boost::multiprecision::mpq_rational;

// How much work the exact arithmetic had to do; "exact" counts the decisions the filter could not make.
struct Stats {
    std::uint64_t triangles = 0;
    std::uint64_t degenerate_triangles = 0;  // zero area: cover nothing
    std::uint64_t orientation_tests = 0;
    std::uint64_t orientation_exact = 0;
    std::uint64_t samples_covered = 0;       // fragments, before the depth test
    std::uint64_t depth_tests = 0;           // comparisons against an already stored fragment
    std::uint64_t depth_exact = 0;
    std::uint64_t depth_nearest_exact = 0;   // samples that reached the z-buffer test (not certainly behind
                                             // the stored depth) whose depth needed exact rounding

    Stats& operator+=(const Stats& o);
};

// The lecture's inside(tri, x, y) indicator with the tie rule, decided exactly.
bool covers(const Triangle& t, double x, double y);

// The framebuffer indices (Framebuffer::index) of every sample of the viewport that `t` covers,
// ascending; no depth test.
std::vector<std::size_t> covered_samples(const Triangle& t, Viewport vp, int samples);

// The exact depth of the plane of `t` at (x, y): z interpolated affinely in screen space.
// Precondition: t has non-zero area.
Rational depth_at(const Triangle& t, double x, double y);

// Rasterizes the scene, its triangles and lines (rast/line.h), with the z-buffer's (z, id) order. Depths
// in the result are the exact depths rounded to the nearest double. `progress` counts triangles drawn.
Framebuffer render(const Scene& scene, Stats* stats = nullptr, const Progress& progress = {});

// Exact area coverage (the box-prefiltered ideal): for every pixel, bottom row first, the area of the
// pixel square covered by the scene's triangles, summed over triangles, depth ignored. `progress` counts
// triangles.
std::vector<Rational> coverage_area(const Scene& scene, const Progress& progress = {});

// The exact area of the part of `t` inside pixel square (i, j).
Rational pixel_area(const Triangle& t, int i, int j);

}  // namespace rast::reference
