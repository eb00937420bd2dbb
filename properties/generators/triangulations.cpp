// Triangulations by CGAL (the one translation unit that includes it): of random point sets, Delaunay
// and in insertion order, and of random simple polygons, constrained.
#include <rast/exact_geometry.h>
#include <rast/property_generators.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <set>

namespace rast::gen::detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
// Each CGAL vertex carries its index into our point list, so that its depth travels with it and two
// faces sharing it get the bit-identical Vertex.
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel>;

template <typename Triangulation, typename Keep>
std::vector<Triangle> faces_of(const Triangulation& t, const std::vector<Vertex>& points, Keep keep) {
    std::vector<Triangle> triangles;
    for (auto f : t.finite_face_handles())
        if (keep(f))
            triangles.push_back({{points[f->vertex(0)->info()], points[f->vertex(1)->info()],
                                  points[f->vertex(2)->info()]}});
    return triangles;
}

// Distinct points only: a repeated point would be one vertex to CGAL but two to us.
std::vector<Vertex> distinct(std::vector<Vertex> points) {
    std::vector<Vertex> unique;
    for (const Vertex& p : points)
        if (std::none_of(unique.begin(), unique.end(), [&](const Vertex& q) { return q.x == p.x && q.y == p.y; }))
            unique.push_back(p);
    return unique;
}

template <typename Triangulation>
std::vector<Triangle> triangulate(const std::vector<Vertex>& points) {
    Triangulation t;
    for (std::size_t k = 0; k < points.size(); ++k) t.insert(Point(points[k].x, points[k].y))->info() = k;
    return faces_of(t, points, [](auto) { return true; });
}

// Points of the viewport and a pixel beyond it: on a 2^-bits grid, or arbitrary when bits < 0.
rc::Gen<std::vector<Vertex>> points_for(Viewport vp, int bits) {
    return rc::gen::map(point_set(-1, std::max(vp.width, vp.height) + 1.0, bits), distinct);
}

}  // namespace

rc::Gen<std::vector<Triangle>> delaunay(Viewport vp, int bits) {
    using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
    return rc::gen::map(points_for(vp, bits), triangulate<CGAL::Delaunay_triangulation_2<Kernel, Tds>>);
}

rc::Gen<std::vector<Triangle>> insertion_order_triangulation(Viewport vp, int bits) {
    using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
    return rc::gen::map(points_for(vp, bits), triangulate<CGAL::Triangulation_2<Kernel, Tds>>);
}

rc::Gen<std::vector<Triangle>> polygon_triangulation(Viewport vp, int bits) {
    return rc::gen::exec([vp, bits] {
        // A star-shaped polygon: corners at increasing angles around a centre, at random distances.
        const double cx = *rc::gen::inRange(0, vp.width + 1), cy = *rc::gen::inRange(0, vp.height + 1);
        const int corners = *rc::gen::inRange(3, 13);
        std::vector<Vertex> points;
        for (int k = 0; k < corners; ++k) {
            const double turn = (k + *rc::gen::inRange(0, 90) / 100.0) / corners;
            const double radius = *rc::gen::inRange(5, 80) / 10.0;
            double x = cx + radius * std::cos(2 * std::numbers::pi * turn);
            double y = cy + radius * std::sin(2 * std::numbers::pi * turn);
            if (bits >= 0) x = properties::snap(x, bits), y = properties::snap(y, bits);
            points.push_back({x, y, *depth()});
        }
        points = distinct(points);
        std::vector<Point> corners_seen;
        for (const Vertex& p : points) corners_seen.emplace_back(p.x, p.y);
        if (points.size() < 3 || !CGAL::is_simple_2(corners_seen.begin(), corners_seen.end(), Kernel()))
            return std::vector<Triangle>{};

        using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel>;
        using Tds = CGAL::Triangulation_data_structure_2<VertexBase, Fb>;
        using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;
        Cdt cdt;
        std::vector<Cdt::Vertex_handle> handles;
        for (std::size_t k = 0; k < points.size(); ++k) {
            handles.push_back(cdt.insert(Point(points[k].x, points[k].y)));
            handles.back()->info() = k;
        }
        for (std::size_t k = 0; k < handles.size(); ++k)
            cdt.insert_constraint(handles[k], handles[(k + 1) % handles.size()]);

        // Outside is what the infinite face reaches without crossing the polygon; the rest is inside.
        std::set<Cdt::Face_handle> outside{cdt.infinite_face()};
        std::queue<Cdt::Face_handle> frontier;
        frontier.push(cdt.infinite_face());
        while (!frontier.empty()) {
            const auto f = frontier.front();
            frontier.pop();
            for (int e = 0; e < 3; ++e) {
                const auto n = f->neighbor(e);
                if (!cdt.is_constrained({f, e}) && outside.insert(n).second) frontier.push(n);
            }
        }
        return faces_of(cdt, points, [&](Cdt::Face_handle f) { return !outside.count(f); });
    });
}

}  // namespace rast::gen::detail
