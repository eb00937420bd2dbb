#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

#include "rast/mesh.h"
#include "rast/scene_limits.h"

namespace rast {

namespace {

// A polygon corner during clipping: its clip-space position and signed distance to the near plane.
struct Corner {
    Vec4 clip;
    double near_distance;  // z + w: >= 0 on the visible side of the near plane (z_ndc >= -1)
};

struct Clipper {
    const Mesh& mesh;
    const std::vector<Corner>& corners;  // per mesh vertex

    // Where the edge (a, b) crosses the near plane. The endpoints are put in one order that depends only
    // on their positions, so both faces sharing the edge compute the same bits; the new vertex gets
    // z = -w, exactly on the plane (z_ndc = -1).
    Corner crossing(std::uint32_t a, std::uint32_t b) const {
        const Vec3 pa = mesh.positions[a], pb = mesh.positions[b];
        if (std::tie(pb.x, pb.y, pb.z, b) < std::tie(pa.x, pa.y, pa.z, a)) std::swap(a, b);
        const Corner& ca = corners[a];
        const Corner& cb = corners[b];
        const double t = ca.near_distance / (ca.near_distance - cb.near_distance);
        const double w = ca.clip.w + t * (cb.clip.w - ca.clip.w);
        return {{ca.clip.x + t * (cb.clip.x - ca.clip.x), ca.clip.y + t * (cb.clip.y - ca.clip.y), -w, w}, 0};
    }

    // Sutherland-Hodgman against the near plane alone: keeps the corners' cyclic order, so the winding;
    // 0, 3 or 4 corners.
    std::vector<Corner> clip(const std::array<std::uint32_t, 3>& face) const {
        std::vector<Corner> polygon;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = face[k], b = face[(k + 1) % 3];
            const double da = corners[a].near_distance, db = corners[b].near_distance;
            if (da >= 0) polygon.push_back(corners[a]);
            // A corner exactly on the plane is kept as it is; only a strict crossing makes a new vertex.
            if ((da < 0 && db > 0) || (da > 0 && db < 0)) polygon.push_back(crossing(a, b));
        }
        return polygon;
    }
};

}  // namespace

Projection project_with_sources(const Mesh& mesh, const Camera& camera, Viewport viewport, int samples) {
    check_camera(camera);
    check_scene_size(viewport, samples);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (std::uint32_t v : mesh.faces[f])
            if (v >= mesh.positions.size())
                throw std::invalid_argument("project: face " + std::to_string(f) + " refers to vertex " +
                                            std::to_string(v) + " of " + std::to_string(mesh.positions.size()));
    const double aspect = camera.aspect > 0 ? camera.aspect : static_cast<double>(viewport.width) / viewport.height;
    const Mat4 to_clip =
        projection_matrix(camera.fov_y_degrees, aspect, camera.near_plane, camera.far_plane) * view_matrix(camera);
    const Mat4 to_screen = viewport_matrix(viewport);

    std::vector<Corner> corners;
    corners.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) {
        const Vec4 c = to_clip * Vec4{p.x, p.y, p.z, 1};
        corners.push_back({c, c.z + c.w});
    }
    const auto screen = [&](const Corner& c, std::size_t face) {
        const Vec4 s = to_screen * Vec4{c.clip.x / c.clip.w, c.clip.y / c.clip.w, c.clip.z / c.clip.w, 1};
        if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z))
            throw std::invalid_argument("project: face " + std::to_string(face) +
                                        " projects to a non-finite screen coordinate");
        return Vertex{s.x, s.y, s.z};
    };

    Projection out;
    out.scene.viewport = viewport;
    out.scene.samples = samples;
    const Clipper clipper{mesh, corners};
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const std::vector<Corner> polygon = clipper.clip(mesh.faces[f]);
        const auto& face = mesh.faces[f];
        const bool whole = corners[face[0]].near_distance >= 0 && corners[face[1]].near_distance >= 0 &&
                           corners[face[2]].near_distance >= 0;
        out.faces_hidden += polygon.size() < 3;
        out.faces_cut += !whole && polygon.size() >= 3;
        // A fan from the first corner keeps the polygon's orientation in every triangle.
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            out.scene.triangles.push_back(
                Triangle{{screen(polygon[0], f), screen(polygon[k], f), screen(polygon[k + 1], f)}});
            out.source_face.push_back(f);
        }
    }
    return out;
}

Scene project(const Mesh& mesh, const Camera& camera, Viewport viewport, int samples) {
    return project_with_sources(mesh, camera, viewport, samples).scene;
}

}  // namespace rast
