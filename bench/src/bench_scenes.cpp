// The scene generators of bench_scenes.h.
#include <rast/bench_scenes.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rast::bench {
namespace {

constexpr double kPi = std::numbers::pi;

// Portable random numbers: the engine's output is fixed by the standard, the mapping to doubles here.
class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }  // [0, 1)
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(unit() * static_cast<double>(n)); }
    std::int64_t between(std::int64_t lo, std::int64_t hi) {  // [lo, hi]
        return lo + static_cast<std::int64_t>(below(static_cast<std::size_t>(hi - lo + 1)));
    }

private:
    std::mt19937_64 engine_;
};

struct Point {
    double x, y;
};

Point polar(Point c, double radius, double angle) {
    return {c.x + radius * std::cos(angle), c.y + radius * std::sin(angle)};
}

Triangle triangle(Point a, Point b, Point c) { return Triangle{{Vertex{a.x, a.y, 0}, Vertex{b.x, b.y, 0}, Vertex{c.x, c.y, 0}}}; }

// A triangle with one side `length` long from a along `angle`, its apex `width` off that side's middle.
Triangle thin(Point a, double angle, double length, double width) {
    const Point b = polar(a, length, angle);
    const Point mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
    return triangle(a, b, polar(mid, width, angle + kPi / 2));
}

Point anywhere(Random& r, Viewport vp) { return {r.uniform(0, vp.width), r.uniform(0, vp.height)}; }

// Three vertices on a circle of the given diameter, about 120 degrees apart (fat triangles of similar
// area), wound either way at random: winding must not matter.
void round_triangles(const SceneSpec& spec, double across, Random& r, std::vector<Triangle>& out) {
    for (std::size_t k = 0; k < spec.triangles; ++k) {
        const Point c = anywhere(r, spec.viewport);
        const double start = r.uniform(0, 2 * kPi);
        std::array<Point, 3> p;
        for (int m = 0; m < 3; ++m) {
            const double angle = start + m * 2 * kPi / 3 + r.uniform(-kPi / 6, kPi / 6);
            p[m] = polar(c, across / 2 * r.uniform(0.5, 1), angle);
        }
        if (r.unit() < 0.5) std::swap(p[1], p[2]);
        out.push_back(triangle(p[0], p[1], p[2]));
    }
}

void needles(const SceneSpec& spec, Random& r, std::vector<Triangle>& out) {
    for (std::size_t k = 0; k < spec.triangles; ++k) {
        const Point a = anywhere(r, spec.viewport);
        const double angle = r.uniform(0, 2 * kPi);
        const double length = r.uniform(64, 512);
        out.push_back(thin(a, angle, length, r.uniform(0.125, 1)));
    }
}

void huge(const SceneSpec& spec, Random& r, std::vector<Triangle>& out) {
    for (std::size_t k = 0; k < spec.triangles; ++k) {
        const Point p = anywhere(r, spec.viewport);
        const Point a{p.x + r.uniform(-4, 4), p.y + r.uniform(-4, 4)};
        const Point b{p.x + r.uniform(-4, 4), p.y + r.uniform(-4, 4)};
        out.push_back(triangle(a, b, polar(p, r.uniform(0x1p20, 0x1p24), r.uniform(0, 2 * kPi))));
    }
}

void mesh(const SceneSpec& spec, Random& r, std::vector<Triangle>& out) {
    if (spec.triangles == 0) return;
    const Viewport vp = spec.viewport;
    const double cell = std::sqrt(2.0 * vp.width * vp.height / static_cast<double>(spec.triangles));
    const auto cols = static_cast<int>(std::max(1.0, std::round(vp.width / cell)));
    const auto rows = static_cast<int>(std::max(1.0, std::round(vp.height / cell)));
    const double w = static_cast<double>(vp.width) / cols, h = static_cast<double>(vp.height) / rows;
    // Inner grid points move by up to a quarter cell; those on the border stay, so the mesh covers
    // exactly the viewport.
    std::vector<Point> grid;
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= cols; ++i) {
            const bool inner = i > 0 && i < cols && j > 0 && j < rows;
            grid.push_back({i * w + (inner ? r.uniform(-w / 4, w / 4) : 0),
                            j * h + (inner ? r.uniform(-h / 4, h / 4) : 0)});
        }
    }
    const auto at = [&](int i, int j) { return grid[static_cast<std::size_t>(j * (cols + 1) + i)]; };
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < cols; ++i) {
            const Point a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (r.unit() < 0.5) {
                out.push_back(triangle(a, b, c));
                out.push_back(triangle(a, c, d));
            } else {
                out.push_back(triangle(a, b, d));
                out.push_back(triangle(b, c, d));
            }
        }
    }
}

void fans(const SceneSpec& spec, Random& r, std::vector<Triangle>& out) {
    while (true) {
        const std::size_t spokes = 3 + r.below(6);
        if (out.size() + spokes > spec.triangles) return;
        const Point c{static_cast<double>(r.below(static_cast<std::size_t>(spec.viewport.width))) + 0.5,
                      static_cast<double>(r.below(static_cast<std::size_t>(spec.viewport.height))) + 0.5};
        const double radius = r.uniform(2, 8), start = r.uniform(0, 2 * kPi);
        const double step = 2 * kPi / static_cast<double>(spokes);
        // Jitter below step / 8 keeps every gap under 5/4 * 2pi/3 < pi: each triangle stays convex
        // towards the centre and the fan closes without overlap.
        std::vector<Point> rim;
        for (std::size_t m = 0; m < spokes; ++m) {
            rim.push_back(polar(c, radius * r.uniform(0.5, 1),
                                start + static_cast<double>(m) * step + r.uniform(-step / 8, step / 8)));
        }
        for (std::size_t m = 0; m < spokes; ++m) out.push_back(triangle(c, rim[m], rim[(m + 1) % spokes]));
    }
}

void centre_edges(const SceneSpec& spec, Random& r, std::vector<Triangle>& out) {
    for (std::size_t k = 0; k < spec.triangles; ++k) {
        const std::int64_t ci = r.between(0, 2 * spec.viewport.width);
        const std::int64_t cj = r.between(0, 2 * spec.viewport.height);
        std::array<Point, 3> p;
        for (Point& v : p) {
            v = {static_cast<double>(ci + r.between(-16, 16)) / 2,
                 static_cast<double>(cj + r.between(-16, 16)) / 2};
        }
        out.push_back(triangle(p[0], p[1], p[2]));
    }
}

void subnormals(const SceneSpec& spec, Random& r, std::vector<Triangle>& out) {
    const auto subnormal = [&r] {
        const double magnitude = std::ldexp(1 + r.unit(), -1023 - static_cast<int>(r.between(0, 50)));
        return r.unit() < 0.5 ? -magnitude : magnitude;
    };
    const double top = spec.viewport.height;
    for (std::size_t k = 0; k < spec.triangles; ++k) {
        const Point apex{r.uniform(1, 8), r.uniform(0, top)};
        out.push_back(triangle({subnormal(), 0}, {subnormal(), top}, apex));
    }
}

void slivers(const SceneSpec& spec, Random& r, std::vector<Triangle>& out) {
    for (std::size_t k = 0; k < spec.triangles; ++k) {
        const Point a = anywhere(r, spec.viewport);
        const double angle = r.uniform(0, 2 * kPi);
        const double length = r.uniform(16, 256);
        const double width = std::ldexp(1 + r.unit(), -static_cast<int>(r.between(10, 50)));
        out.push_back(thin(a, angle, length, width));
    }
}

void assign_depths(const SceneSpec& spec, std::vector<Triangle>& triangles) {
    // Its own stream, so that the geometry is the same for every depth mode.
    Random r(spec.seed ^ 0x9e3779b97f4a7c15ull);
    if (spec.depth == Depth::random) {
        for (Triangle& t : triangles) {
            for (Vertex& v : t.v) v.z = r.unit();
        }
        return;
    }
    std::vector<std::size_t> band(triangles.size());
    for (std::size_t k = 0; k < band.size(); ++k) band[k] = k;
    for (std::size_t k = band.size(); k > 1; --k) std::swap(band[k - 1], band[r.below(k)]);
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        for (Vertex& v : triangles[k].v) v.z = static_cast<double>(band[k]) + 0.25 * r.unit();
    }
}

double snap_256(double c) { return std::nearbyint(c * 256) / 256; }

constexpr std::array<std::pair<Shape, std::string_view>, 11> kShapeNames{{
    {Shape::tiny, "tiny"},
    {Shape::small, "small"},
    {Shape::medium, "medium"},
    {Shape::large, "large"},
    {Shape::needle, "needle"},
    {Shape::huge, "huge"},
    {Shape::mesh, "mesh"},
    {Shape::fan, "fan"},
    {Shape::centre_edges, "centre_edges"},
    {Shape::subnormal, "subnormal"},
    {Shape::sliver, "sliver"},
}};

}  // namespace

Scene make_scene(const SceneSpec& spec) {
    if (spec.viewport.width <= 0 || spec.viewport.height <= 0) {
        throw std::invalid_argument("make_scene: the viewport must not be empty");
    }
    Scene scene{spec.viewport, 1, {}};
    scene.triangles.reserve(spec.triangles);
    Random r(spec.seed);
    switch (spec.shape) {
        case Shape::tiny: round_triangles(spec, 4, r, scene.triangles); break;
        case Shape::small: round_triangles(spec, 16, r, scene.triangles); break;
        case Shape::medium: round_triangles(spec, 64, r, scene.triangles); break;
        case Shape::large: round_triangles(spec, 256, r, scene.triangles); break;
        case Shape::needle: needles(spec, r, scene.triangles); break;
        case Shape::huge: huge(spec, r, scene.triangles); break;
        case Shape::mesh: mesh(spec, r, scene.triangles); break;
        case Shape::fan: fans(spec, r, scene.triangles); break;
        case Shape::centre_edges: centre_edges(spec, r, scene.triangles); break;
        case Shape::subnormal: subnormals(spec, r, scene.triangles); break;
        case Shape::sliver: slivers(spec, r, scene.triangles); break;
    }
    if (spec.on_grid_256) {
        for (Triangle& t : scene.triangles) {
            for (Vertex& v : t.v) {
                v.x = snap_256(v.x);
                v.y = snap_256(v.y);
            }
        }
    }
    assign_depths(spec, scene.triangles);
    return scene;
}

std::string_view name(Shape shape) {
    for (const auto& [s, n] : kShapeNames) {
        if (s == shape) return n;
    }
    throw std::invalid_argument("unknown shape");
}

std::optional<Shape> parse_shape(std::string_view s) {
    for (const auto& [shape, n] : kShapeNames) {
        if (n == s) return shape;
    }
    return std::nullopt;
}

std::string_view name(Depth depth) { return depth == Depth::random ? "random" : "separated"; }

std::string describe(const SceneSpec& spec) {
    return std::string(name(spec.shape)) + "/n:" + std::to_string(spec.triangles) + "/" +
           std::to_string(spec.viewport.width) + "x" + std::to_string(spec.viewport.height) +
           (spec.on_grid_256 ? "/grid256/" : "/") + std::string(name(spec.depth)) + "/seed:" +
           std::to_string(spec.seed);
}

std::vector<Segment> make_segments(std::size_t n, double length, Viewport viewport, std::uint64_t seed) {
    Random r(seed);
    std::vector<Segment> out;
    out.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double x = r.uniform(0, viewport.width), y = r.uniform(0, viewport.height);
        const double angle = r.uniform(0, 2 * kPi);
        out.push_back({{Vertex{x, y, 0}, Vertex{x + length * std::cos(angle), y + length * std::sin(angle), 0}}});
    }
    return out;
}

}  // namespace rast::bench
