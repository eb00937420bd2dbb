// rast — seeded, deterministic scene generators for benchmarks and cross-checks.
//
// Generation is kept apart from timing so that the micro-benchmarks, the llvmpipe cross-check and
// `rast bench` all measure the very same scenes. A scene is a pure function of its SceneSpec: the
// random numbers come from std::mt19937_64 (whose output the standard fixes) turned into doubles by
// bit arithmetic of our own, never by a std:: distribution (whose output is implementation-defined).
#pragma once

#include <rast/scene.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rast::bench {

// Sizes are "across": the diameter of the circle the three vertices lie on.
enum class Shape {
    tiny,          // 4 px across: a few pixels each, setup-bound
    small,         // 16 px across
    medium,        // 64 px across
    large,         // 256 px across, fill-bound
    needle,        // 64 to 512 px long, 1/8 to 1 px wide, any direction
    huge,          // one vertex 2^20 to 2^24 px away, two within 4 px of a point in the viewport:
                   // a sliver through the viewport with coordinates far beyond it
    mesh,          // a jittered grid of quads, two triangles each: every inner edge shared with
                   // bit-identical endpoints, the viewport covered once (count rounded to fit)
    fan,           // closed fans of 3 to 8 triangles around pixel centres, 4 to 16 px across
    centre_edges,  // vertices on the half-pixel lattice, up to 16 px across: many edges, horizontal
                   // and vertical ones included, run exactly through pixel centres
    subnormal,     // an edge from (s0, 0) to (s1, H), s0 and s1 subnormal of either sign, and an apex 1 to
                   // 8 px right of it: the edge passes the 16x pattern's samples on x = 0 at subnormal
                   // distances, on either side
    sliver,        // near zero area: 16 to 256 px long, the apex 2^-50 to 2^-9 px off the long edge (or, rounded, on it)
};

enum class Depth {
    random,     // every vertex its own z in [0, 1): tilted, interpenetrating triangles
    separated,  // triangle k lies in its own band [b, b + 1/4) of z with b a seeded permutation of
                // 0..n-1: any two triangles differ in depth by at least 3/4 everywhere, so every
                // rasterizer with a sane depth buffer agrees on the visible one
};

struct SceneSpec {
    Shape shape = Shape::small;
    std::size_t triangles = 10000;
    Viewport viewport{1024, 1024};
    bool on_grid_256 = false;  // round x and y to the nearest multiple of 1/256 (ties to even)
    Depth depth = Depth::random;
    std::uint64_t seed = 1;
};

Scene make_scene(const SceneSpec& spec);

std::string_view name(Shape shape);
std::optional<Shape> parse_shape(std::string_view s);
std::string_view name(Depth depth);

// A short, unique label, e.g. "small/n:10000/1024x1024/grid256/separated/seed:1".
std::string describe(const SceneSpec& spec);

// n segments of the given length in pixels, each in a uniformly random direction, starting uniformly
// inside the viewport (so some run out of it); arbitrary doubles, z 0.
std::vector<Segment> make_segments(std::size_t n, double length, Viewport viewport, std::uint64_t seed = 1);

}  // namespace rast::bench
