// The exact cutting of one pixel square; see visible_pixel.h.
#include "visible_pixel.h"

#include "depth_plane.h"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

namespace rast::reference::detail {

namespace {

struct Region {
    Polygon polygon;  // convex, counter-clockwise, of non-zero area
    const Cutter* owner;  // nullptr: nothing is visible there
};

// Cuts a convex polygon along f = 0 into the closed parts f <= 0 and f >= 0, taking the polygon. A part
// is left empty when it would have no area: exactly when no vertex lies strictly on its side. A polygon
// wholly on one side moves there, uncopied: most cuts leave it whole.
void cut(Polygon&& polygon, const Affine& f, Polygon& below, Polygon& above) {
    below.clear();
    above.clear();
    // The values at the vertices, kept from cut to cut in this thread: their digits stay allocated.
    thread_local std::vector<Rational> value;
    if (value.size() < polygon.size()) value.resize(polygon.size());
    bool any_below = false, any_above = false;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        value[k] = f.at(polygon[k]);
        any_below = any_below || value[k] < 0;
        any_above = any_above || value[k] > 0;
    }
    if (!any_above) {
        below = std::move(polygon);
        return;
    }
    if (!any_below) {
        above = std::move(polygon);
        return;
    }
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const std::size_t next = (k + 1) % polygon.size();
        const RationalPoint& p = polygon[k];
        const int s = sign(value[k]), t = sign(value[next]);
        if (s <= 0) below.push_back(p);
        if (s >= 0) above.push_back(p);
        if (s * t < 0) {
            const RationalPoint& q = polygon[next];
            const Rational u = value[k] / (value[k] - value[next]);
            RationalPoint crossing{p.x + u * (q.x - p.x), p.y + u * (q.y - p.y)};
            below.push_back(crossing);
            above.push_back(std::move(crossing));
        }
    }
}

// z_front - z_back as one affine function.
Affine depth_difference(const Cutter& front, const Cutter& back) {
    return {front.depth.a - back.depth.a, front.depth.b - back.depth.b, front.depth.c - back.depth.c};
}

bool identically_zero(const Affine& f) { return f.a == 0 && f.b == 0 && f.c == 0; }

// Whether `owner` is ahead of `t` everywhere in the region, so that t can take none of it: the depth
// difference is affine, so its least value over a convex polygon is at a vertex.
bool hidden_by(const Cutter& t, const Cutter& owner, const Polygon& polygon) {
    const Affine d = depth_difference(t, owner);
    if (identically_zero(d)) return owner.id < t.id;
    return std::all_of(polygon.begin(), polygon.end(), [&](const RationalPoint& p) { return d.at(p) >= 0; });
}

// Inserts `t` into the map.
void insert(std::vector<Region>& map, const Cutter& t) {
    std::vector<Region> next;
    next.reserve(map.size() + 4);
    Polygon rest, outside, inside;
    for (Region& region : map) {
        if (region.owner && hidden_by(t, *region.owner, region.polygon)) {
            next.push_back(std::move(region));
            continue;
        }
        rest = std::move(region.polygon);
        for (const Affine& edge : t.edges) {
            cut(std::move(rest), edge, outside, inside);
            if (!outside.empty()) next.push_back({std::move(outside), region.owner});
            std::swap(rest, inside);
            if (rest.empty()) break;
        }
        if (rest.empty()) continue;
        if (!region.owner) {
            next.push_back({std::move(rest), &t});
            continue;
        }
        const Affine d = depth_difference(t, *region.owner);
        if (identically_zero(d)) {
            next.push_back({std::move(rest), t.id < region.owner->id ? &t : region.owner});
            continue;
        }
        cut(std::move(rest), d, inside, outside);  // inside: t is nearer
        if (!inside.empty()) next.push_back({std::move(inside), &t});
        if (!outside.empty()) next.push_back({std::move(outside), region.owner});
    }
    map = std::move(next);
}

}  // namespace

std::optional<Cutter> make_cutter(const Triangle& t, std::size_t id) {
    const auto rational = [](double v) { return Rational(v); };
    const DepthPlane<Rational> plane = depth_plane<Rational>(t, rational, rational);
    if (plane.w == 0) return std::nullopt;
    Cutter cutter{id, {}, {plane.a / plane.w, plane.b / plane.w, plane.c / plane.w}};
    // Edge k, from vertex k + 1 to k + 2, as depth_plane expands it: positive inside a counter-clockwise
    // triangle, so a clockwise one (w < 0) turns every sign.
    const int orientation = sign(plane.w);
    for (int k = 0; k < 3; ++k) {
        const Vertex& p = t.v[(k + 1) % 3];
        const Vertex& q = t.v[(k + 2) % 3];
        Affine& e = cutter.edges[k];
        e.a = Rational(p.y) - Rational(q.y);
        e.b = Rational(q.x) - Rational(p.x);
        e.c = Rational(p.x) * Rational(q.y) - Rational(q.x) * Rational(p.y);
        if (orientation < 0) {
            e.a = -e.a;
            e.b = -e.b;
            e.c = -e.c;
        }
    }
    return cutter;
}

std::vector<VisiblePiece> visible_in_square(int i, int j, std::span<const Cutter* const> cutters) {
    const Rational x0(i), y0(j), x1(i + 1), y1(j + 1);
    std::vector<Region> map{{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, nullptr}};
    for (const Cutter* t : cutters) insert(map, *t);
    std::map<std::size_t, Rational> areas;
    for (const Region& region : map) {
        if (region.owner) areas[region.owner->id] += signed_area(region.polygon);
    }
    std::vector<VisiblePiece> pieces;
    pieces.reserve(areas.size());
    for (auto& [id, a] : areas) pieces.push_back({id, std::move(a)});
    return pieces;
}

}  // namespace rast::reference::detail
