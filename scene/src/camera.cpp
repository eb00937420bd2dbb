#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rast/mesh.h"
#include "rast/scene_limits.h"

namespace rast {

namespace {
bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
double radians(double degrees) { return degrees * std::numbers::pi / 180; }
}  // namespace

void check_camera(const Camera& c) {
    if (!finite(c.eye) || !finite(c.target) || !finite(c.up))
        throw std::invalid_argument("camera: eye, target and up must be finite");
    if (c.eye == c.target) throw std::invalid_argument("camera: eye and target are the same point");
    const Vec3 side = cross(c.target - c.eye, c.up);
    if (!(length(side) > 0) || !std::isfinite(length(side)))
        throw std::invalid_argument("camera: up is zero or parallel to the view direction");
    if (!(c.fov_y_degrees > 0 && c.fov_y_degrees < 180))
        throw std::invalid_argument("camera: fov_y must be in (0, 180) degrees, got " + std::to_string(c.fov_y_degrees));
    if (!(c.aspect >= 0) || !std::isfinite(c.aspect))
        throw std::invalid_argument("camera: aspect must be positive, or 0 to take it from the viewport");
    if (!(c.near_plane > 0) || !std::isfinite(c.near_plane))
        throw std::invalid_argument("camera: near plane must be positive, got " + std::to_string(c.near_plane));
    if (!(c.far_plane > c.near_plane) || !std::isfinite(c.far_plane))
        throw std::invalid_argument("camera: far plane must lie beyond the near plane");
}

Mat4 view_matrix(const Camera& c) {
    // g: gaze, t: up made orthogonal to g, g x t: right. R_view maps them to +x, +y, -z.
    const Vec3 g = normalized(c.target - c.eye);
    const Vec3 right = normalized(cross(g, c.up));
    const Vec3 t = cross(right, g);
    const Mat4 rotate{{{{right.x, right.y, right.z, 0}, {t.x, t.y, t.z, 0}, {-g.x, -g.y, -g.z, 0}, {0, 0, 0, 1}}}};
    const Mat4 translate{{{{1, 0, 0, -c.eye.x}, {0, 1, 0, -c.eye.y}, {0, 0, 1, -c.eye.z}, {0, 0, 0, 1}}}};
    return rotate * translate;
}

Mat4 projection_matrix(double fov_y_degrees, double aspect, double near_plane, double far_plane) {
    // The lecture's camera looks down -z, so the planes lie at z = n and z = f with 0 > n > f.
    const double n = -near_plane, f = -far_plane;
    const double top = near_plane * std::tan(radians(fov_y_degrees) / 2), right = aspect * top;
    const Mat4 persp_to_ortho{{{{n, 0, 0, 0}, {0, n, 0, 0}, {0, 0, n + f, -n * f}, {0, 0, 1, 0}}}};
    // The box [-right, right] x [-top, top] x [f, n] to [-1, 1]^3; it is centred in x and y.
    const Mat4 ortho{{{{1 / right, 0, 0, 0}, {0, 1 / top, 0, 0}, {0, 0, 2 / (n - f), -(n + f) / (n - f)}, {0, 0, 0, 1}}}};
    // The lecture's NDC keep the view's right-handed z: near -> +1. The z-buffer wants smaller z nearer, so
    // flip z. Then negate the whole matrix, which leaves the projective map unchanged but makes
    // w = -z_view > 0 in front of the camera, so clipping tests read the usual way.
    const Mat4 flip_z_and_w{{{{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, -1}}}};
    return flip_z_and_w * ortho * persp_to_ortho;
}

Mat4 viewport_matrix(Viewport vp) {
    const double hw = vp.width / 2.0, hh = vp.height / 2.0;
    return {{{{hw, 0, 0, hw}, {0, hh, 0, hh}, {0, 0, 1, 0}, {0, 0, 0, 1}}}};
}

Camera frame(const Mesh& mesh, Viewport viewport) {
    check_viewport(viewport);
    if (mesh.positions.empty()) throw std::invalid_argument("frame: the mesh has no vertices");
    Vec3 lo = mesh.positions.front(), hi = lo;
    for (const Vec3& p : mesh.positions) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const Vec3 centre = 0.5 * (lo + hi);
    double radius = 0;
    for (const Vec3& p : mesh.positions) radius = std::max(radius, length(p - centre));
    // A single point still needs a sphere with room for the near plane in front of it.
    radius = 1.1 * (radius > 0 ? radius : 1.0);

    Camera camera;
    const double aspect = static_cast<double>(viewport.width) / viewport.height;
    const double half_y = radians(camera.fov_y_degrees) / 2;
    const double half_x = std::atan(aspect * std::tan(half_y));
    // The sphere fits the cone of the narrower half-angle, which lies inside the view frustum.
    const double distance = radius / std::sin(std::min(half_x, half_y));
    camera.eye = centre + Vec3{0, 0, distance};
    camera.target = centre;
    camera.up = {0, 1, 0};
    camera.near_plane = distance - radius;
    camera.far_plane = distance + radius;
    return camera;
}

Camera frame_depth(const Mesh& mesh, Camera camera) {
    check_camera(camera);
    const Vec3 direction = normalized(camera.target - camera.eye);
    double nearest = std::numeric_limits<double>::infinity(), farthest = 0;
    bool behind = false;  // a vertex at or behind the eye's plane
    for (const Vec3& p : mesh.positions) {
        const double depth = dot(p - camera.eye, direction);
        if (depth > 0) nearest = std::min(nearest, depth);
        else behind = true;
        farthest = std::max(farthest, depth);
    }
    if (!(farthest > 0)) return camera;
    // Room either side, so that no vertex lies on a plane; depth is exact in the reference whatever the
    // ratio far / near, and the floor keeps the projection's numbers in range.
    camera.far_plane = 1.01 * farthest;
    const double floor = camera.far_plane * 0x1p-20;
    camera.near_plane = behind ? floor : std::max(0.99 * nearest, floor);
    return camera;
}

}  // namespace rast
