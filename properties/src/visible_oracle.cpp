// The visible area by vertical slabs, and the boundaries of a pixel's visible regions; see
// rast/visible_oracle.h.
#include <rast/visible_oracle.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

namespace rast::properties {

namespace {

struct Point {
    Rational x, y;
};

// The line a x + b y + c = 0, or the half-plane a x + b y + c >= 0.
struct Line {
    Rational a, b, c;
    Rational at(const Rational& x, const Rational& y) const { return a * x + b * y + c; }
};

// A triangle of non-zero area: its edges as half-planes holding it, and its depth z = za x + zb y + zc.
struct Solid {
    std::size_t id;
    std::array<Point, 3> v;
    std::array<Line, 3> edges;
    Rational za, zb, zc;
    Rational z(const Rational& x, const Rational& y) const { return za * x + zb * y + zc; }
};

// The normal (p1 - p0) x (p2 - p0) of the plane through the vertices gives the depth's slopes.
std::optional<Solid> solid(const Triangle& t, std::size_t id) {
    const Rational x0(t.v[0].x), y0(t.v[0].y), z0(t.v[0].z);
    const Rational dx1 = Rational(t.v[1].x) - x0, dy1 = Rational(t.v[1].y) - y0, dz1 = Rational(t.v[1].z) - z0;
    const Rational dx2 = Rational(t.v[2].x) - x0, dy2 = Rational(t.v[2].y) - y0, dz2 = Rational(t.v[2].z) - z0;
    const Rational nx = dy1 * dz2 - dz1 * dy2, ny = dz1 * dx2 - dx1 * dz2, nz = dx1 * dy2 - dy1 * dx2;
    if (nz == 0) return std::nullopt;
    Solid s{id, {}, {}, -nx / nz, -ny / nz, 0};
    s.zc = z0 - s.za * x0 - s.zb * y0;
    for (int k = 0; k < 3; ++k) s.v[k] = {Rational(t.v[k].x), Rational(t.v[k].y)};
    // The edge from a to b, positive on its left: inside for a counter-clockwise triangle (nz > 0).
    for (int k = 0; k < 3; ++k) {
        const Point& a = s.v[k];
        const Point& b = s.v[(k + 1) % 3];
        Line e{a.y - b.y, b.x - a.x, 0};
        e.c = -(e.a * a.x + e.b * a.y);
        if (nz < 0) e = {-e.a, -e.b, -e.c};
        s.edges[k] = e;
    }
    return s;
}

// The triangles whose bounding box meets the open pixel square: the only ones that can have area in it.
std::vector<Solid> solids_near(const Scene& scene, int i, int j) {
    std::vector<Solid> near;
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) {
        const Triangle& t = scene.triangles[id];
        const auto [xmin, xmax] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
        const auto [ymin, ymax] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
        if (xmax <= i || xmin >= i + 1.0 || ymax <= j || ymin >= j + 1.0) continue;
        if (auto s = solid(t, id)) near.push_back(std::move(*s));
    }
    return near;
}

// Where the depths of s and t are equal: none when they never are or always are.
std::optional<Line> equal_depth(const Solid& s, const Solid& t) {
    Line d{s.za - t.za, s.zb - t.zb, s.zc - t.zc};
    if (d.a == 0 && d.b == 0) return std::nullopt;
    return d;
}

// The section of `s` on the vertical line at x, within [lo, hi]; none when it has no length.
std::optional<std::pair<Rational, Rational>> section(const Solid& s, const Rational& x, Rational lo, Rational hi) {
    for (const Line& e : s.edges) {
        // e.a x + e.b y + e.c >= 0; x is never that of a vertical edge (it is a slab's middle).
        const Rational offset = e.a * x + e.c;
        if (e.b > 0) lo = std::max(lo, Rational(-offset / e.b));
        else if (e.b < 0) hi = std::min(hi, Rational(-offset / e.b));
        else if (offset < 0) return std::nullopt;
    }
    if (lo >= hi) return std::nullopt;
    return std::pair{lo, hi};
}

void sort_unique(std::vector<Rational>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

// A segment p + t d, t in [lo, hi], clipped by half-planes; empty when lo > hi.
struct Segment {
    Point p, d;
    Rational lo, hi;

    void clip(const Line& h) {
        const Rational at_p = h.at(p.x, p.y), slope = h.a * d.x + h.b * d.y;
        if (slope > 0) lo = std::max(lo, Rational(-at_p / slope));
        else if (slope < 0) hi = std::min(hi, Rational(-at_p / slope));
        else if (at_p < 0) hi = lo - 1;
    }
    bool empty() const { return lo > hi; }
};

// The closed rectangle [x0, x1] x [y0, y1] as four half-planes.
std::array<Line, 4> rectangle(const Rational& x0, const Rational& y0, const Rational& x1, const Rational& y1) {
    return {Line{1, 0, -x0}, Line{-1, 0, x1}, Line{0, 1, -y0}, Line{0, -1, y1}};
}

}  // namespace

SlabPixel visible_by_slabs(const Scene& scene, int i, int j) {
    const std::vector<Solid> near = solids_near(scene, i, j);
    const Rational left(i), right(i + 1), bottom(j), top(j + 1);
    std::vector<Line> lines{{0, 1, -bottom}, {0, 1, -top}};
    for (const Solid& s : near) lines.insert(lines.end(), s.edges.begin(), s.edges.end());
    for (std::size_t a = 0; a < near.size(); ++a)
        for (std::size_t b = a + 1; b < near.size(); ++b)
            if (auto d = equal_depth(near[a], near[b])) lines.push_back(*d);

    std::vector<Rational> xs{left, right};
    for (const Line& l : lines) {
        if (l.b == 0 && l.a != 0) {
            const Rational x = -l.c / l.a;
            if (left < x && x < right) xs.push_back(x);
        }
    }
    for (std::size_t a = 0; a < lines.size(); ++a)
        for (std::size_t b = a + 1; b < lines.size(); ++b) {
            const Line &l = lines[a], &m = lines[b];
            const Rational det = l.a * m.b - m.a * l.b;
            if (det == 0) continue;
            const Rational x = (l.b * m.c - m.b * l.c) / det, y = (m.a * l.c - l.a * m.c) / det;
            if (left < x && x < right && bottom <= y && y <= top) xs.push_back(x);
        }
    sort_unique(xs);

    SlabPixel result;
    std::map<std::size_t, Rational> visible;
    for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
        const Rational width = xs[k + 1] - xs[k], x = (xs[k] + xs[k + 1]) / 2;
        std::vector<std::pair<const Solid*, std::pair<Rational, Rational>>> present;
        std::vector<Rational> ys{bottom, top};
        for (const Solid& s : near) {
            if (auto range = section(s, x, bottom, top)) {
                present.emplace_back(&s, *range);
                ys.push_back(range->first);
                ys.push_back(range->second);
            }
        }
        for (std::size_t a = 0; a < present.size(); ++a)
            for (std::size_t b = a + 1; b < present.size(); ++b) {
                const auto d = equal_depth(*present[a].first, *present[b].first);
                if (!d || d->b == 0) continue;
                const Rational y = -(d->a * x + d->c) / d->b;
                if (bottom < y && y < top) ys.push_back(y);
            }
        sort_unique(ys);
        for (std::size_t m = 0; m + 1 < ys.size(); ++m) {
            const Rational y = (ys[m] + ys[m + 1]) / 2;
            const Solid* winner = nullptr;
            Rational winner_z;
            for (const auto& [s, range] : present) {
                if (!(range.first < y && y < range.second)) continue;
                const Rational z = s->z(x, y);
                if (!winner || z < winner_z || (z == winner_z && s->id < winner->id)) {
                    winner = s;
                    winner_z = z;
                }
            }
            if (!winner) continue;
            const Rational area = width * (ys[m + 1] - ys[m]);
            visible[winner->id] += area;
            result.covered += area;
        }
    }
    for (auto& [id, area] : visible) result.visible.emplace_back(id, std::move(area));
    return result;
}

int cells_met_by_boundaries(const Scene& scene, int i, int j, int columns, int rows) {
    const std::vector<Solid> near = solids_near(scene, i, j);
    const auto square = rectangle(Rational(i), Rational(j), Rational(i + 1), Rational(j + 1));
    std::vector<Segment> boundaries;
    for (const Solid& s : near)
        for (int k = 0; k < 3; ++k) {
            const Point& a = s.v[k];
            const Point& b = s.v[(k + 1) % 3];
            boundaries.push_back({a, {b.x - a.x, b.y - a.y}, 0, 1});
        }
    for (std::size_t a = 0; a < near.size(); ++a)
        for (std::size_t b = a + 1; b < near.size(); ++b) {
            const auto d = equal_depth(near[a], near[b]);
            if (!d) continue;
            // The whole line, bounded below by the pixel's sides and the two triangles' edges.
            const Point on = d->b != 0 ? Point{0, -d->c / d->b} : Point{-d->c / d->a, 0};
            Segment s{on, {-d->b, d->a}, 0, 0};
            // Any t beyond the pixel is outside it: start from a range that holds the whole square.
            const Rational reach = 4 * (abs(on.x - i) + abs(on.y - j) + 2) / (abs(d->a) + abs(d->b));
            s.lo = -reach;
            s.hi = reach;
            for (const Line& e : near[a].edges) s.clip(e);
            for (const Line& e : near[b].edges) s.clip(e);
            boundaries.push_back(std::move(s));
        }
    for (Segment& s : boundaries)
        for (const Line& h : square) s.clip(h);
    std::erase_if(boundaries, [](const Segment& s) { return s.empty(); });

    int met = 0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            const auto cell = rectangle(i + Rational(c, columns), j + Rational(r, rows), i + Rational(c + 1, columns),
                                        j + Rational(r + 1, rows));
            met += std::any_of(boundaries.begin(), boundaries.end(), [&](Segment s) {
                for (const Line& h : cell) s.clip(h);
                return !s.empty();
            });
        }
    return met;
}

std::pair<int, int> sample_cells(int samples) {
    switch (samples) {
        case 1: return {1, 1};
        case 4: return {2, 2};
        case 8: return {4, 2};
        case 16: return {2, 8};
        default: throw std::invalid_argument("no cell grid for " + std::to_string(samples) + " samples");
    }
}

std::optional<std::size_t> front_cover(const Scene& scene, int i, int j) {
    const std::vector<Solid> near = solids_near(scene, i, j);
    const std::array<Point, 4> corners{Point{i, j}, Point{i + 1, j}, Point{i + 1, j + 1}, Point{i, j + 1}};
    const auto holds = [&](const Solid& s) {
        return std::all_of(corners.begin(), corners.end(), [&](const Point& p) {
            return std::all_of(s.edges.begin(), s.edges.end(), [&](const Line& e) { return e.at(p.x, p.y) >= 0; });
        });
    };
    const auto before = [&](const Solid& s, const Solid& t) {
        bool all_equal = true;
        for (const Point& p : corners) {
            const Rational zs = s.z(p.x, p.y), zt = t.z(p.x, p.y);
            if (zs > zt) return false;
            all_equal = all_equal && zs == zt;
        }
        return !all_equal || s.id < t.id;
    };
    for (const Solid& s : near) {
        if (!holds(s)) continue;
        if (std::all_of(near.begin(), near.end(), [&](const Solid& t) { return &t == &s || before(s, t); }))
            return s.id;
    }
    return std::nullopt;
}

}  // namespace rast::properties
