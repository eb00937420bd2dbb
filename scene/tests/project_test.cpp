#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "rast/mesh.h"

namespace rast {
namespace {

double signed_area(const Triangle& t) {
    const Vertex &a = t.v[0], &b = t.v[1], &c = t.v[2];
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

double total_signed_area(const Scene& s) {
    double sum = 0;
    for (const Triangle& t : s.triangles) sum += signed_area(t);
    return sum;
}

// The cube [-1, 1]^3, triangles wound counter-clockwise seen from outside.
Mesh cube() {
    Mesh m;
    for (int k = 0; k < 8; ++k) m.positions.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
    // Corner k has x from bit 0, y from bit 1, z from bit 2.
    m.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
               {2, 6, 7}, {2, 7, 3}, {1, 3, 7}, {1, 7, 5}, {0, 4, 6}, {0, 6, 2}};
    m.closed = true;
    return m;
}

Camera looking(Vec3 eye, Vec3 target, double fov, double near_plane, double far_plane) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.fov_y_degrees = fov;
    c.near_plane = near_plane;
    c.far_plane = far_plane;
    return c;
}

void expect_vertex_near(const Vertex& v, double x, double y, double z) {
    EXPECT_NEAR(v.x, x, 1e-12);
    EXPECT_NEAR(v.y, y, 1e-12);
    EXPECT_NEAR(v.z, z, 1e-12);
}

TEST(Transforms, LectureMatrices) {
    Camera c;  // eye (0, 0, 1) looking at the origin
    const Vec4 t = view_matrix(c) * Vec4{0, 0, 0, 1};
    EXPECT_NEAR(t.x, 0, 1e-15);
    EXPECT_NEAR(t.y, 0, 1e-15);
    EXPECT_NEAR(t.z, -1, 1e-15);
    // Looking down world -x with y up, world -z is to the right.
    const Vec4 side = view_matrix(looking({5, 0, 0}, {0, 0, 0}, 45, 1, 2)) * Vec4{5, 0, -1, 1};
    EXPECT_NEAR(side.x, 1, 1e-15);
    EXPECT_NEAR(side.y, 0, 1e-15);
    EXPECT_NEAR(side.z, 0, 1e-15);

    const Mat4 p = projection_matrix(90, 2, 1, 3);
    const Vec4 near_corner = p * Vec4{2, 1, -1, 1};
    EXPECT_NEAR(near_corner.x / near_corner.w, 1, 1e-15);
    EXPECT_NEAR(near_corner.y / near_corner.w, 1, 1e-15);
    EXPECT_NEAR(near_corner.z / near_corner.w, -1, 1e-15);
    EXPECT_NEAR(near_corner.w, 1, 1e-15);
    const Vec4 far_centre = p * Vec4{0, 0, -3, 1};
    EXPECT_NEAR(far_centre.z / far_centre.w, 1, 1e-15);
    EXPECT_NEAR(far_centre.w, 3, 1e-15);

    const Vec4 lo = viewport_matrix({100, 50}) * Vec4{-1, -1, 0.25, 1};
    const Vec4 hi = viewport_matrix({100, 50}) * Vec4{1, 1, -0.5, 1};
    EXPECT_EQ(lo.x, 0);
    EXPECT_EQ(lo.y, 0);
    EXPECT_EQ(lo.z, 0.25);
    EXPECT_EQ(hi.x, 100);
    EXPECT_EQ(hi.y, 50);
    EXPECT_EQ(hi.z, -0.5);
}

// Camera at the origin looking down -z, 90 degrees, near 1, far 3, on 100 x 100: x_s = 50 + 50 x / depth,
// and z_ndc = 2 - 3 / depth (OpenGL's depth with n = 1, f = 3).
Camera origin_camera() { return looking({0, 0, 0}, {0, 0, -1}, 90, 1, 3); }

TEST(Project, HandComputedTriangle) {
    Mesh m;
    m.positions = {{0, 0, -1}, {1, 1, -2}, {-3, 0, -3}};
    m.faces = {{0, 1, 2}};
    const Scene s = project(m, origin_camera(), {100, 100}, 4);
    EXPECT_EQ(s.viewport, (Viewport{100, 100}));
    EXPECT_EQ(s.samples, 4);
    ASSERT_EQ(s.triangles.size(), 1u);
    expect_vertex_near(s.triangles[0].v[0], 50, 50, -1);  // on the near plane: kept as it is
    expect_vertex_near(s.triangles[0].v[1], 75, 75, 0.5);
    expect_vertex_near(s.triangles[0].v[2], 0, 50, 1);
}

TEST(Project, ClipsAtTheNearPlaneIntoTwoTriangles) {
    Mesh m;
    // A (depth 0.5) is in front of the near plane; A-B and C-A cross it at a third of the way from A.
    m.positions = {{0, 0, -0.5}, {2, 0, -2}, {0, 2, -2}};
    m.faces = {{0, 1, 2}};
    const Projection p = project_with_sources(m, origin_camera(), {100, 100}, 1);
    ASSERT_EQ(p.scene.triangles.size(), 2u);
    EXPECT_EQ(p.source_face, (std::vector<std::size_t>{0, 0}));
    const Triangle& t0 = p.scene.triangles[0];
    const Triangle& t1 = p.scene.triangles[1];
    expect_vertex_near(t0.v[0], 50 + 100.0 / 3, 50, -1);  // (2/3, 0, -1)
    expect_vertex_near(t0.v[1], 100, 50, 0.5);
    expect_vertex_near(t0.v[2], 50, 100, 0.5);
    EXPECT_EQ(t1.v[0], t0.v[0]);
    EXPECT_EQ(t1.v[1], t0.v[2]);
    expect_vertex_near(t1.v[2], 50, 50 + 100.0 / 3, -1);  // (0, 2/3, -1)
    EXPECT_EQ(t0.v[0].z, -1.0);  // exactly on the plane
    EXPECT_EQ(t1.v[2].z, -1.0);
    // Front facing stays counter-clockwise; the quad is 1250 minus the clipped corner 5000/9.
    EXPECT_GT(signed_area(t0), 0);
    EXPECT_GT(signed_area(t1), 0);
    EXPECT_NEAR(total_signed_area(p.scene), 1250 - 5000.0 / 9, 1e-9);
    EXPECT_EQ(p.faces_cut, 1u);
    EXPECT_EQ(p.faces_hidden, 0u);
}

TEST(Project, DropsWhatIsBehindTheNearPlane) {
    Mesh m;
    m.positions = {{0, 0, -0.5}, {1, 0, -0.9}, {0, 1, 4}, {0, 0, -2}, {1, 0, -2}, {0, 1, -2}};
    m.faces = {{0, 1, 2}, {3, 4, 5}};
    const Projection p = project_with_sources(m, origin_camera(), {10, 10}, 1);
    EXPECT_EQ(p.scene.triangles.size(), 1u);
    EXPECT_EQ(p.source_face, (std::vector<std::size_t>{1}));
    EXPECT_EQ(p.faces_cut, 0u);
    EXPECT_EQ(p.faces_hidden, 1u);
}

// Near and far framed for the camera in use, along its view direction (here -z from the origin).
TEST(FrameDepth, BracketsTheMeshInFrontOfTheEye) {
    Mesh m;
    m.positions = {{0, 0, -2}, {1, 0, -10}, {0, 3, -4}};
    m.faces = {{0, 1, 2}};
    Camera c = origin_camera();
    const Camera framed = frame_depth(m, c);
    EXPECT_DOUBLE_EQ(framed.near_plane, 0.99 * 2);
    EXPECT_DOUBLE_EQ(framed.far_plane, 1.01 * 10);
    const Projection p = project_with_sources(m, framed, {10, 10}, 1);
    EXPECT_EQ(p.faces_cut + p.faces_hidden, 0u);
    EXPECT_EQ(p.scene.triangles.size(), 1u);
}

// A floor under the eye that reaches behind it: the near plane comes as close as far / 2^20, so that all
// of the floor in front of the eye but that sliver is drawn. One wholly behind keeps the camera's planes.
TEST(FrameDepth, ComesCloseWhereTheMeshReachesBehindTheEye) {
    Mesh floor;
    floor.positions = {{-5, -1, 5}, {5, -1, 5}, {5, -1, -5}, {-5, -1, -5}};
    floor.faces = {{0, 1, 2}, {0, 2, 3}};
    const Camera framed = frame_depth(floor, origin_camera());
    EXPECT_DOUBLE_EQ(framed.far_plane, 1.01 * 5);
    EXPECT_DOUBLE_EQ(framed.near_plane, 1.01 * 5 * 0x1p-20);
    const Projection p = project_with_sources(floor, framed, {10, 10}, 1);
    EXPECT_EQ(p.faces_cut, 2u);
    EXPECT_FALSE(p.scene.triangles.empty());

    Mesh behind = floor;
    for (Vec3& v : behind.positions) v.z = 1 + std::abs(v.z);
    const Camera unchanged = frame_depth(behind, origin_camera());
    EXPECT_EQ(unchanged.near_plane, origin_camera().near_plane);
    EXPECT_EQ(unchanged.far_plane, origin_camera().far_plane);
}

TEST(Project, FarPlaneDoesNotClip) {
    Mesh m;
    m.positions = {{0, 0, -6}, {1, 0, -6}, {0, 1, -6}};
    m.faces = {{0, 1, 2}};
    const Scene s = project(m, origin_camera(), {100, 100}, 1);
    ASSERT_EQ(s.triangles.size(), 1u);
    EXPECT_NEAR(s.triangles[0].v[0].z, 1.5, 1e-12);  // 2 - 3 / 6: beyond far, still ordered by depth
}

TEST(Project, RejectsBadInput) {
    const Mesh m = cube();
    Camera c = looking({0, 0, 5}, {0, 0, 0}, 45, 1, 10);
    EXPECT_THROW(project(m, c, {0, 10}, 1), std::invalid_argument);
    EXPECT_THROW(project(m, c, {10, 10}, 3), std::invalid_argument);
    for (auto bad : {looking({0, 0, 0}, {0, 0, 0}, 45, 1, 10), looking({0, 5, 0}, {0, 0, 0}, 45, 1, 10),
                     looking({0, 0, 5}, {0, 0, 0}, 180, 1, 10), looking({0, 0, 5}, {0, 0, 0}, 45, 0, 10),
                     looking({0, 0, 5}, {0, 0, 0}, 45, 2, 2), looking({0, 0, NAN}, {0, 0, 0}, 45, 1, 10)})
        EXPECT_THROW(project(m, bad, {10, 10}, 1), std::invalid_argument);
    Mesh broken = m;
    broken.faces.push_back({0, 1, 8});
    EXPECT_THROW(project(broken, c, {10, 10}, 1), std::invalid_argument);
}

TEST(Frame, EveryVertexStrictlyInsideTheViewport) {
    Mesh m = cube();
    for (Vec3& p : m.positions) p = Vec3{10 + 7 * p.x, -5 + p.y, 3 + 2 * p.z};  // off centre, stretched
    for (Viewport vp : {Viewport{100, 100}, Viewport{300, 50}, Viewport{40, 200}}) {
        const Scene s = project(m, frame(m, vp), vp, 1);
        ASSERT_EQ(s.triangles.size(), m.faces.size());  // nothing clipped
        for (const Triangle& t : s.triangles)
            for (const Vertex& v : t.v) {
                EXPECT_GT(v.x, 0);
                EXPECT_LT(v.x, vp.width);
                EXPECT_GT(v.y, 0);
                EXPECT_LT(v.y, vp.height);
                EXPECT_GT(v.z, -1);
                EXPECT_LT(v.z, 1);
            }
    }
}

TEST(ClosedMesh, UnclippedFrontAndBackAreasCancel) {
    const Mesh m = cube();
    const Scene s = project(m, looking({0.3, 0.2, 5}, {0, 0, 0}, 45, 0.5, 20), {100, 100}, 1);
    double front = 0;
    for (const Triangle& t : s.triangles) front += std::max(0.0, signed_area(t));
    EXPECT_GT(front, 100);
    EXPECT_NEAR(total_signed_area(s), 0, 1e-9 * front);
}

// Eye at (0, 0, 3), near plane at depth 2.5, i.e. world z = 0.5: the front face is gone, and what is left
// is seen from inside, back facing. Its projected boundary is the cut square, x, y in [-1, 1] at depth 2.5:
// with 90 degrees on 100 x 100 it spans 50 +- 50 / 2.5, so [30, 70]^2, area 1600.
TEST(ClosedMesh, AxisAlignedCutLeavesTheCapArea) {
    const Scene s = project(cube(), looking({0, 0, 3}, {0, 0, 0}, 90, 2.5, 10), {100, 100}, 1);
    EXPECT_NEAR(total_signed_area(s), -1600, 1e-9);
    for (const Triangle& t : s.triangles) {
        EXPECT_LE(signed_area(t), 1e-12);
        for (const Vertex& v : t.v) EXPECT_GE(v.z, -1.0);
    }
}

// Monotone chain: the area of the convex hull of points.
double convex_hull_area(std::vector<std::pair<double, double>> pts) {
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return 0;
    const auto turn = [](auto o, auto a, auto b) {
        return (a.first - o.first) * (b.second - o.second) - (a.second - o.second) * (b.first - o.first);
    };
    std::vector<std::pair<double, double>> hull(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
        hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
        hull[k++] = pts[i];
    }
    double area = 0;
    for (std::size_t i = 0; i + 1 < k; ++i) area += hull[i].first * hull[i + 1].second - hull[i + 1].first * hull[i].second;
    return area / 2;
}

// An oblique near plane through the cube: the clipped surface must be watertight except along the cut,
// keep every face's winding, and its signed area must be minus that of the cap (the cut polygon, convex,
// whose vertices are the clipped ones).
TEST(ClosedMesh, ObliqueCutStaysWatertightAndKeepsWinding) {
    const Mesh m = cube();
    const Camera camera = looking({2.2, 1.7, 2.9}, {0.1, -0.2, 0}, 60, 3.6, 20);
    const Projection p = project_with_sources(m, camera, {64, 48}, 1);
    const Scene& s = p.scene;
    ASSERT_GT(s.triangles.size(), 0u);

    std::vector<std::pair<double, double>> cut;
    std::map<std::tuple<double, double, double, double, double, double>, int> edges;  // directed edge count
    const auto on_cut = [](const Vertex& v) { return v.z == -1.0; };
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
        const Triangle& t = s.triangles[i];
        for (int k = 0; k < 3; ++k) {
            const Vertex &a = t.v[k], &b = t.v[(k + 1) % 3];
            EXPECT_GE(a.z, -1.0);
            if (on_cut(a)) cut.emplace_back(a.x, a.y);
            if (!(on_cut(a) && on_cut(b))) ++edges[{a.x, a.y, a.z, b.x, b.y, b.z}];
        }
        // Winding: facing in 3D (the face's normal towards the eye) is the sign of the screen area.
        const auto& f = m.faces[p.source_face[i]];
        const Vec3 normal = cross(m.positions[f[1]] - m.positions[f[0]], m.positions[f[2]] - m.positions[f[0]]);
        const double facing = dot(normal, camera.eye - m.positions[f[0]]);
        EXPECT_GT(facing * signed_area(t), 0) << "triangle " << i << " of face " << p.source_face[i];
    }
    EXPECT_GE(cut.size(), 3u);
    for (const auto& [e, count] : edges) {
        const auto& [ax, ay, az, bx, by, bz] = e;
        const auto reverse = edges.find({bx, by, bz, ax, ay, az});
        ASSERT_NE(reverse, edges.end()) << "edge without its bit-identical twin";
        EXPECT_EQ(reverse->second, count);
    }
    const double cap = convex_hull_area(cut);
    EXPECT_GT(cap, 10);
    EXPECT_NEAR(total_signed_area(s), -cap, 1e-9 * cap);
}

}  // namespace
}  // namespace rast
