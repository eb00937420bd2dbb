// Coordinates, single triangles, overlapping triangles and the regions built without CGAL: closed fans
// around a sample, strips and perturbed grids.
#include <rast/exact_geometry.h>
#include <rast/property_generators.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>

namespace rast::gen {

namespace {

// RapidCheck scales the span of inRange and the bits of an arbitrary integer with the test's size, which
// it spreads from 0 to max_size over the cases: below size 90 or so a uniform double came out as lo plus a
// sliver, a coordinate as the viewport's lower margin (most scenes covered nothing) and a shuffle as one
// fixed order. The public generators draw at the nominal size whatever the test's: their scenes are
// bounded anyway, and shrinking, not size, makes a counterexample small.
template <class T>
rc::Gen<T> at_full_size(rc::Gen<T> g) {
    return rc::gen::resize(rc::kNominalSize, std::move(g));
}

// A scene generator at full size whose shrinking, once the values have shrunk, may also drop any of the
// triangles: a counterexample keeps only those that play a part. (A count drawn first shrinks only the
// last triangles away, and a shrunk case once kept two zero-area triangles that changed nothing.)
rc::Gen<Scene> scenes_at_full_size(rc::Gen<Scene> g) {
    return at_full_size(rc::Gen<Scene>([g = std::move(g)](const rc::Random& random, int size) {
        return rc::shrinkable::postShrink(g(random, size), [](const Scene& scene) {
            return rc::seq::map(rc::shrink::removeChunks(scene.triangles), [scene](std::vector<Triangle> kept) {
                Scene smaller = scene;
                smaller.triangles = std::move(kept);
                return smaller;
            });
        });
    }));
}

// k * 2^-bits with k drawn so that the value lies in [lo, hi].
rc::Gen<double> on_grid(double lo, double hi, int bits) {
    const auto k0 = static_cast<std::int64_t>(std::ceil(std::ldexp(lo, bits)));
    const auto k1 = static_cast<std::int64_t>(std::floor(std::ldexp(hi, bits)));
    return rc::gen::map(rc::gen::inRange<std::int64_t>(k0, k1 + 1),
                        [bits](std::int64_t k) { return std::ldexp(static_cast<double>(k), -bits); });
}

// Uniform in [lo, hi] with all 53 bits of the fraction random: almost never on any grid.
rc::Gen<double> arbitrary(double lo, double hi) {
    return rc::gen::map(rc::gen::arbitrary<std::uint64_t>(), [lo, hi](std::uint64_t bits) {
        const double u = std::ldexp(static_cast<double>(bits >> 11), -53);
        return std::clamp(lo + (hi - lo) * u, lo, hi);
    });
}

rc::Gen<int> grid_bits() { return rc::gen::element(0, 1, 2, 4, 8, 16); }

double ulps_off(double value, int ulps) {
    const double toward = ulps < 0 ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    for (int k = 0; k < std::abs(ulps); ++k) value = std::nextafter(value, toward);
    return value;
}

Vertex vertex_in(Viewport vp) {
    return {*coordinate(-2, vp.width + 2.0), *coordinate(-2, vp.height + 2.0), *depth()};
}

// A number of huge magnitude: 2^e times a random significand in [1, 2), e up to 60.
double huge() {
    const int e = *rc::gen::inRange(20, 61);
    const double sign = *rc::gen::element(-1.0, 1.0);
    return sign * std::ldexp(1 + *arbitrary(0, 1), e);
}

double subnormal() {
    const double sign = *rc::gen::element(-1.0, 1.0);
    return sign * std::numeric_limits<double>::denorm_min() * *rc::gen::inRange(1, 1 << 20);
}

Triangle ordinary(Viewport vp) { return {{vertex_in(vp), vertex_in(vp), vertex_in(vp)}}; }

// Two vertices close together: the third is 2^-k (k up to 40) from the second.
Triangle needle(Viewport vp) {
    Triangle t = ordinary(vp);
    const int k = *rc::gen::inRange(4, 41);
    t.v[2].x = t.v[1].x + std::ldexp(*rc::gen::inRange(-3, 4), -k);
    t.v[2].y = t.v[1].y + std::ldexp(*rc::gen::inRange(-3, 4), -k);
    return t;
}

// Three nearly collinear vertices: the third is on the segment, then nudged off it by 2^-k.
Triangle sliver(Viewport vp) {
    Triangle t = ordinary(vp);
    const double s = *on_grid(0, 1, 8);
    const int k = *rc::gen::inRange(8, 60);
    t.v[2].x = t.v[0].x + s * (t.v[1].x - t.v[0].x) - std::ldexp(*rc::gen::inRange(-2, 3), -k) * (t.v[1].y - t.v[0].y);
    t.v[2].y = t.v[0].y + s * (t.v[1].y - t.v[0].y) + std::ldexp(*rc::gen::inRange(-2, 3), -k) * (t.v[1].x - t.v[0].x);
    return t;
}

// Exactly zero area: a repeated vertex, or three collinear grid points a, a + d, a + m d.
Triangle degenerate(Viewport vp) {
    Triangle t = ordinary(vp);
    if (*rc::gen::arbitrary<bool>()) {
        t.v[2].x = t.v[0].x;
        t.v[2].y = t.v[0].y;
        return t;
    }
    const double ax = *on_grid(-1, vp.width + 1.0, 4), ay = *on_grid(-1, vp.height + 1.0, 4);
    const double dx = *on_grid(-4, 4, 4), dy = *on_grid(-4, 4, 4);
    const double m = *rc::gen::inRange(-3, 4);
    t.v[0].x = ax, t.v[0].y = ay;
    t.v[1].x = ax + dx, t.v[1].y = ay + dy;
    t.v[2].x = ax + m * dx, t.v[2].y = ay + m * dy;
    return t;
}

Triangle reaching_far(Viewport vp) {
    Triangle t = ordinary(vp);
    const int far = *rc::gen::inRange(1, 3);
    for (int k = 0; k < far; ++k) {
        if (*rc::gen::arbitrary<bool>()) t.v[k].x = huge();
        if (*rc::gen::arbitrary<bool>()) t.v[k].y = huge();
    }
    return t;
}

Triangle touching_subnormals(Viewport vp) {
    Triangle t = ordinary(vp);
    t.v[0].x = subnormal();
    t.v[0].y = *rc::gen::arbitrary<bool>() ? subnormal() : 0.0;
    if (*rc::gen::arbitrary<bool>()) t.v[1].y = subnormal();
    return t;
}

// A scene of the given triangles with a viewport that holds them (the viewport was drawn first).
Scene scene_of(Viewport vp, std::vector<Triangle> triangles) { return {vp, *sample_count(), std::move(triangles)}; }

// On a 2^-bits grid when bits >= 0; otherwise left as computed.
double round_to(double value, int bits) { return bits < 0 ? value : properties::snap(value, bits); }

bool all_counter_clockwise(const std::vector<Triangle>& triangles) {
    return std::all_of(triangles.begin(), triangles.end(),
                       [](const Triangle& t) { return properties::orientation(t) > 0; });
}

// A closed fan around a sample position: spokes at jittered, evenly spread angles, so that no gap
// between neighbours reaches a half turn and the centre is interior.
std::vector<Triangle> closed_fan(Viewport vp, int samples, int bits) {
    const auto pattern = sample_pattern(samples);
    const SamplePoint offset = pattern[*rc::gen::inRange<std::size_t>(0, pattern.size())];
    const Vertex centre{*rc::gen::inRange(0, vp.width) + offset.x, *rc::gen::inRange(0, vp.height) + offset.y,
                        *depth()};
    const int spokes = *rc::gen::inRange(3, 10);
    const double min_radius = bits >= 0 && bits < 2 ? 2.0 : 0.05;
    std::vector<Vertex> rim;
    for (int k = 0; k < spokes; ++k) {
        const double turn = (k + *on_grid(0, 0.45, 8)) / spokes;
        const double radius = *arbitrary(min_radius, 6);
        rim.push_back({round_to(centre.x + radius * std::cos(2 * std::numbers::pi * turn), bits),
                       round_to(centre.y + radius * std::sin(2 * std::numbers::pi * turn), bits), *depth()});
    }
    std::vector<Triangle> fan;
    for (int k = 0; k < spokes; ++k) fan.push_back({{centre, rim[k], rim[(k + 1) % spokes]}});
    return fan;
}

// A triangle strip zigzagging between a lower and an upper chain, each increasing in x.
std::vector<Triangle> strip(Viewport vp, int bits) {
    const int columns = *rc::gen::inRange(2, 9);
    const double mid = *on_grid(0, vp.height, 1);
    const int step_bits = std::max(bits, 0);
    std::vector<Vertex> chain;
    double bottom_x = *on_grid(-2, vp.width / 2.0, step_bits), top_x = bottom_x + *on_grid(-1, 1, step_bits);
    for (int k = 0; k < columns; ++k) {
        chain.push_back({bottom_x, mid - *on_grid(0.25, 3, step_bits), *depth()});
        chain.push_back({top_x, mid + *on_grid(0.25, 3, step_bits), *depth()});
        bottom_x += *on_grid(0.25, 4, step_bits);
        top_x += *on_grid(0.25, 4, step_bits);
    }
    if (bits < 0)
        for (Vertex& v : chain) v.x += *arbitrary(-0.1, 0.1), v.y += *arbitrary(-0.1, 0.1);
    std::vector<Triangle> triangles;
    for (std::size_t k = 0; k + 2 < chain.size(); ++k) {
        // Alternate the vertex order so that every triangle is counter-clockwise.
        Triangle t{{chain[k], chain[k + 1], chain[k + 2]}};
        if (k % 2 == 0) std::swap(t.v[1], t.v[2]);
        triangles.push_back(t);
    }
    return triangles;
}

// A lattice of cells, its points moved by less than a third of a cell, each cell cut along a random diagonal.
std::vector<Triangle> grid(Viewport vp, int bits) {
    const int columns = *rc::gen::inRange(1, 6), rows = *rc::gen::inRange(1, 6);
    const int step_bits = std::max(bits, 0);
    const double cell_x = *on_grid(0.5, 4, step_bits), cell_y = *on_grid(0.5, 4, step_bits);
    const double x0 = *on_grid(-2, vp.width / 2.0, step_bits), y0 = *on_grid(-2, vp.height / 2.0, step_bits);
    std::vector<Vertex> points;
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= columns; ++c)
            points.push_back({round_to(x0 + c * cell_x + *arbitrary(-0.3, 0.3) * cell_x, bits),
                              round_to(y0 + r * cell_y + *arbitrary(-0.3, 0.3) * cell_y, bits), *depth()});
    const auto at = [&](int r, int c) { return points[static_cast<std::size_t>(r * (columns + 1) + c)]; };
    std::vector<Triangle> triangles;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            const Vertex a = at(r, c), b = at(r, c + 1), d = at(r + 1, c), e = at(r + 1, c + 1);
            if (*rc::gen::arbitrary<bool>()) {
                triangles.push_back({{a, b, e}});
                triangles.push_back({{a, e, d}});
            } else {
                triangles.push_back({{a, b, d}});
                triangles.push_back({{b, e, d}});
            }
        }
    return triangles;
}

rc::Gen<std::vector<Triangle>> region(Viewport vp, int samples, int bits) {
    const auto valid = [](const std::vector<Triangle>& ts) { return !ts.empty() && all_counter_clockwise(ts); };
    const auto source = rc::gen::weightedOneOf<std::vector<Triangle>>({
        {3, rc::gen::exec([=] { return closed_fan(vp, samples, bits); })},
        {2, rc::gen::exec([=] { return strip(vp, bits); })},
        {2, rc::gen::exec([=] { return grid(vp, bits); })},
        {2, detail::delaunay(vp, bits)},
        {2, detail::insertion_order_triangulation(vp, bits)},
        {2, detail::polygon_triangulation(vp, bits)},
        {bits < 0 ? 2u : 0u, detail::mesh_front(vp)},
    });
    return rc::gen::suchThat(source, valid);
}

rc::Gen<Scene> region_scene(rc::Gen<int> grid) {
    return scenes_at_full_size(rc::gen::exec([grid] {
        const int bits = *grid;
        const Viewport vp = *viewport();
        const int samples = *sample_count();
        return Scene{vp, samples, *detail::shuffled(*region(vp, samples, bits))};
    }));
}

}  // namespace

rc::Gen<double> coordinate(double lo, double hi) {
    return at_full_size(rc::gen::exec([lo, hi] {
        switch (*rc::gen::inRange(0, 5)) {
            case 0: return *on_grid(lo, hi, 0);
            case 1: return *on_grid(std::floor(lo), std::floor(hi) - 1, 0) + 0.5;
            case 2: return *on_grid(lo, hi, *rc::gen::inRange(1, 17));
            case 3: return ulps_off(*on_grid(lo, hi, *grid_bits()), *rc::gen::inRange(-3, 4));
            default: return *arbitrary(lo, hi);
        }
    }));
}

rc::Gen<double> depth() {
    return rc::gen::weightedOneOf<double>({{2, rc::gen::element(0.0, 0.5, 1.0)}, {1, coordinate(-1, 2)}});
}

rc::Gen<Viewport> viewport() {
    return at_full_size(
        rc::gen::exec([] { return Viewport{*rc::gen::inRange(1, 25), *rc::gen::inRange(1, 25)}; }));
}

rc::Gen<int> sample_count() { return rc::gen::weightedElement<int>({{3, 1}, {1, 4}, {1, 8}, {1, 16}}); }

rc::Gen<Triangle> triangle(Viewport vp) {
    return at_full_size(rc::gen::exec([vp] {
        switch (*rc::gen::weightedElement<int>({{4, 0}, {1, 1}, {1, 2}, {1, 3}, {1, 4}, {1, 5}})) {
            case 0: return ordinary(vp);
            case 1: return needle(vp);
            case 2: return sliver(vp);
            case 3: return degenerate(vp);
            case 4: return reaching_far(vp);
            default: return touching_subnormals(vp);
        }
    }));
}

rc::Gen<Scene> loose_triangles() {
    return scenes_at_full_size(rc::gen::exec([] {
        const Viewport vp = *viewport();
        return scene_of(vp, *rc::gen::container<std::vector<Triangle>>(*rc::gen::inRange(1, 7), triangle(vp)));
    }));
}

rc::Gen<Scene> long_rows() {
    return scenes_at_full_size(rc::gen::exec([] {
        const Viewport vp{*rc::gen::inRange(64, 257), *rc::gen::inRange(1, 5)};
        std::vector<Triangle> triangles;
        for (int k = *rc::gen::inRange(1, 4); k > 0; --k) {
            Triangle t = ordinary(vp);
            const double far = std::ldexp(1 + *arbitrary(0, 1), *rc::gen::inRange(8, 25));
            if (*rc::gen::arbitrary<bool>()) {
                t.v[0].x = *rc::gen::element(-far, far + vp.width);
                t.v[0].y = *arbitrary(-far, far);
            } else {
                // An edge from a pixel centre along a line of pixel centres to a far vertex, nudged a few
                // ulps off it: samples near the line have tiny but nonzero edge functions, where an error
                // that grows along the row shows against the small bound near the edge's start.
                const Vertex a{*rc::gen::inRange(0, vp.width) + 0.5, *rc::gen::inRange(0, vp.height) + 0.5, *depth()};
                const double dx = *rc::gen::inRange(1, 4), dy = *rc::gen::inRange(-1, 2);
                const double m = std::floor(far / dx) * *rc::gen::element(-1.0, 1.0);
                t.v[0] = {a.x + m * dx, ulps_off(a.y + m * dy, *rc::gen::inRange(-64, 65)), t.v[0].z};
                t.v[*rc::gen::inRange(1, 3)] = a;
            }
            triangles.push_back(t);
        }
        return Scene{vp, *sample_count(), std::move(triangles)};
    }));
}

// Vertices on a pixel, centre or subpixel grid, or arbitrary doubles (bits < 0).
rc::Gen<Scene> triangulated_region() { return region_scene(rc::gen::element(-1, 0, 1, 2, 4, 8, 16)); }

rc::Gen<Scene> triangulated_region_on_grid(int bits) { return region_scene(rc::gen::just(bits)); }

rc::Gen<Scene> overlapping_triangles() {
    return scenes_at_full_size(rc::gen::exec([] {
        const Viewport vp = *viewport();
        // Depth on a plane z = a x + b y + c with dyadic coefficients: exact at grid vertices, so
        // triangles on one plane tie exactly wherever they overlap.
        const int planes = *rc::gen::inRange(1, 4);
        std::vector<std::array<double, 3>> plane;
        for (int p = 0; p < planes; ++p)
            plane.push_back({*on_grid(-1, 1, 4), *on_grid(-1, 1, 4), *on_grid(-4, 4, 2)});
        std::vector<Vertex> shared;
        for (int k = *rc::gen::inRange(3, 7); k > 0; --k)
            shared.push_back({*on_grid(-1, vp.width + 1.0, 4), *on_grid(-1, vp.height + 1.0, 4), 0});
        std::vector<Triangle> triangles;
        for (int k = *rc::gen::inRange(2, 7); k > 0; --k) {
            Triangle t;
            if (!triangles.empty() && *rc::gen::inRange(0, 4) == 0) {
                t = *rc::gen::elementOf(triangles);  // a duplicate: the same fragments, tied everywhere
            } else {
                for (Vertex& v : t.v) v = *rc::gen::arbitrary<bool>() ? *rc::gen::elementOf(shared) : vertex_in(vp);
                const auto& [a, b, c] = *rc::gen::elementOf(plane);
                for (Vertex& v : t.v) v.z = a * v.x + b * v.y + c;
            }
            triangles.push_back(t);
        }
        return scene_of(vp, std::move(triangles));
    }));
}

rc::Gen<Scene> stamped_runs() {
    return scenes_at_full_size(rc::gen::exec([] {
        const Viewport vp{*rc::gen::inRange(8, 25), *rc::gen::inRange(8, 25)};
        // Depth magnitudes whose planes' error bounds lie hundreds of orders apart; 1.7e308 overflows them.
        const double scale = *rc::gen::element(1e-300, 1e-12, 1.0, 1e12, 1e300, 1.7e308);
        const double cx = *arbitrary(2, vp.width - 2.0), cy = *arbitrary(2, vp.height - 2.0);
        std::vector<Triangle> triangles;
        for (int k = *rc::gen::inRange(4, 20); k > 0; --k) {
            Triangle t;
            if (!triangles.empty() && *rc::gen::inRange(0, 3) == 0) {
                // A twin: an earlier triangle from another first corner, the same plane, tied everywhere.
                t = *rc::gen::elementOf(triangles);
                std::rotate(t.v.begin(), t.v.begin() + *rc::gen::inRange(1, 3), t.v.end());
            } else {
                const double s = *rc::gen::element(scale, 1.0, 1e-12, 1.7e308);
                for (Vertex& v : t.v)
                    v = {cx + *arbitrary(-2, 2), cy + *arbitrary(-2, 2), s * *arbitrary(-1, 1)};
            }
            triangles.push_back(t);
        }
        return scene_of(vp, std::move(triangles));
    }));
}

rc::Gen<Scene> layered_triangles() {
    return scenes_at_full_size(rc::gen::exec([] {
        const Viewport vp{*rc::gen::inRange(1, 4), *rc::gen::inRange(1, 4)};
        std::vector<std::array<double, 3>> planes;
        for (int p = *rc::gen::inRange(2, 5); p > 0; --p)
            planes.push_back({*on_grid(-1, 1, 3), *on_grid(-1, 1, 3), *on_grid(-2, 2, 2)});
        std::vector<Triangle> triangles;
        for (int k = *rc::gen::inRange(1, 6); k > 0; --k) {
            Triangle t;
            if (*rc::gen::inRange(0, 3) > 0) {
                // Its corners far enough out that it holds the viewport whole.
                t = {{Vertex{-2, -2, 0}, Vertex{3.0 * vp.width + 4, -2, 0}, Vertex{-2, 3.0 * vp.height + 4, 0}}};
                std::rotate(t.v.begin(), t.v.begin() + *rc::gen::inRange(0, 3), t.v.end());
            } else {
                t = ordinary(vp);
            }
            const auto& [a, b, c] = *rc::gen::elementOf(planes);
            for (Vertex& v : t.v) v.z = a * v.x + b * v.y + c;
            triangles.push_back(t);
        }
        return scene_of(vp, std::move(triangles));
    }));
}

rc::Gen<Scene> lines_among_triangles() {
    return rc::gen::exec([] {
        const Viewport vp{*rc::gen::inRange(1, 9), *rc::gen::inRange(1, 9)};
        std::vector<std::array<double, 3>> planes;  // z = a x + b y + c
        for (int p = *rc::gen::inRange(1, 4); p > 0; --p)
            planes.push_back({*on_grid(-1, 1, 3), *on_grid(-1, 1, 3), *on_grid(-2, 2, 2)});
        if (*rc::gen::inRange(0, 2) == 0) planes[0][1] = 0;  // level along y: a row in it ties at every centre
        const auto plane = [&] { return *rc::gen::elementOf(planes); };
        const auto in_plane = [](const std::array<double, 3>& p, double x, double y) {
            return Vertex{x, y, p[0] * x + p[1] * y + p[2]};
        };
        std::vector<Triangle> triangles;
        for (int k = *rc::gen::inRange(0, 5); k > 0; --k) {
            Triangle t = *rc::gen::inRange(0, 2) == 0
                             ? Triangle{{Vertex{-2, -2, 0}, Vertex{3.0 * vp.width + 4, -2, 0}, Vertex{-2, 3.0 * vp.height + 4, 0}}}
                             : ordinary(vp);
            const auto p = plane();
            for (Vertex& v : t.v) v = in_plane(p, v.x, v.y);
            triangles.push_back(t);
        }
        std::vector<Segment> segments;
        for (int k = *rc::gen::inRange(1, 6); k > 0; --k) {
            Segment s;
            switch (*rc::gen::inRange(0, 4)) {
                case 0:  // anywhere
                    s = {{vertex_in(vp), vertex_in(vp)}};
                    break;
                case 3: {  // reaching out to 2^60: big integers in Bresenham, exact depths
                    Vertex far = vertex_in(vp);
                    (*rc::gen::inRange(0, 2) == 0 ? far.x : far.y) = huge();
                    s = {{vertex_in(vp), far}};
                    break;
                }
                case 1: {  // centre to centre along a row, a column, a diagonal or a knight's move
                    const auto [dx, dy] = *rc::gen::element(std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1},
                                                            std::pair{1, -1}, std::pair{2, 1}, std::pair{1, -2});
                    const int steps = *rc::gen::inRange(-4, 5);
                    const double x = *rc::gen::inRange(-1, vp.width + 1) + 0.5, y = *rc::gen::inRange(-1, vp.height + 1) + 0.5;
                    const auto p = plane();
                    s = {{in_plane(p, x, y), in_plane(p, x + steps * dx, y + steps * dy)}};
                    break;
                }
                default: {  // a row in a plane, ends on the quarter grid
                    const auto p = plane();
                    const double y = *on_grid(-1, vp.height + 1.0, 1);
                    s = {{in_plane(p, *on_grid(-2, vp.width + 2.0, 2), y), in_plane(p, *on_grid(-2, vp.width + 2.0, 2), y)}};
                }
            }
            segments.push_back(s);
        }
        // File order: the lines among the triangles at random places.
        Scene scene{vp, *rc::gen::element(1, 4), {}};
        std::size_t next_triangle = 0, next_line = 0;
        while (next_triangle < triangles.size() || next_line < segments.size()) {
            const std::size_t left = triangles.size() - next_triangle + segments.size() - next_line;
            if (*rc::gen::inRange<std::size_t>(0, left) < segments.size() - next_line)
                append_line(scene, segments[next_line++]);
            else
                scene.triangles.push_back(triangles[next_triangle++]);
        }
        return scene;
    });
}

rc::Gen<Scene> small_window(rc::Gen<Scene> scenes) {
    return rc::gen::exec([scenes] {
        Scene s = *scenes;
        const int w = std::min(s.viewport.width, 4), h = std::min(s.viewport.height, 4);
        const int di = *rc::gen::inRange(0, s.viewport.width - w + 1), dj = *rc::gen::inRange(0, s.viewport.height - h + 1);
        for (Triangle& t : s.triangles)
            for (Vertex& v : t.v) {
                v.x -= di;
                v.y -= dj;
            }
        s.viewport = {w, h};
        return s;
    });
}

rc::Gen<Scene> any_scene() {
    return rc::gen::oneOf(loose_triangles(), triangulated_region(), overlapping_triangles());
}

namespace detail {

rc::Gen<std::vector<Triangle>> shuffled(std::vector<Triangle> triangles) {
    return rc::gen::exec([input = std::move(triangles)] {
        std::vector<Triangle> triangles = input;
        for (Triangle& t : triangles) {
            std::rotate(t.v.begin(), t.v.begin() + *rc::gen::inRange(0, 3), t.v.end());
            if (*rc::gen::arbitrary<bool>()) std::swap(t.v[1], t.v[2]);
        }
        for (std::size_t k = triangles.size(); k > 1; --k)
            std::swap(triangles[k - 1], triangles[*rc::gen::inRange<std::size_t>(0, k)]);
        return triangles;
    });
}

rc::Gen<std::vector<Vertex>> point_set(double lo, double hi, int bits) {
    return rc::gen::exec([=] {
        const auto value = bits >= 0 ? on_grid(lo, hi, bits) : arbitrary(lo, hi);
        std::vector<Vertex> points;
        for (int k = *rc::gen::inRange(3, 26); k > 0; --k) points.push_back({*value, *value, *depth()});
        return points;
    });
}

}  // namespace detail

}  // namespace rast::gen
