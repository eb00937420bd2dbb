// rast — meshes from files, a camera, and the lecture's transforms that turn a mesh into a .tri Scene:
// view, perspective projection, near-plane clipping in clip space, then the viewport transform of
// docs/design.md. Model = identity: mesh coordinates are world coordinates.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "rast/parse_error.h"
#include "rast/scene.h"
#include "rast/vec.h"

namespace rast {

struct Mesh {
    std::vector<Vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> faces;  // indices into positions; polygons are triangulated
    bool closed = false;                              // no boundary edge: every edge has a face on each side
};

// Reads OBJ, OFF (ASCII), PLY or STL (ASCII or binary), chosen by the extension (any case). OpenMesh reads
// coordinates as float32, so they are exactly floats widened to double; give exact doubles as .tri.
// Throws ParseError: unreadable file, unknown extension, no faces, a non-finite coordinate, and, in the
// text formats, a malformed number, a face index out of range or repeated within a face, with the line;
// for PLY, ASCII or binary, a header OpenMesh would misread (with the line) and, in binary data, a face
// index out of range or repeated, or data that ends early or goes on; for OBJ, OFF and PLY also any face
// OpenMesh did not keep. STL has no vertex indices: OpenMesh
// merges corners at equal positions and drops a triangle with two equal corners (it has zero area and
// covers nothing). OpenMesh's own log output is silenced; when it fails, what it said is in the error.
Mesh read_mesh(const std::filesystem::path& path);

struct Camera {
    Vec3 eye{0, 0, 1};
    Vec3 target{0, 0, 0};
    Vec3 up{0, 1, 0};
    double fov_y_degrees = 45;
    double aspect = 0;  // width / height; 0 takes it from the viewport
    double near_plane = 0.1;
    double far_plane = 100;
};

// Throws std::invalid_argument saying what is wrong: a non-finite value, eye == target, up parallel to the
// view direction, fov_y outside (0, 180), a negative aspect, near_plane <= 0 or far_plane <= near_plane.
void check_camera(const Camera& camera);

// A camera that shows the whole mesh: its bounding sphere (centre of the bounding box, enlarged by 10% so
// that no vertex lands on the border) fits both fields of view, looking from +z down to the centre with
// y up; near and far bracket the sphere.
Camera frame(const Mesh& mesh, Viewport viewport);

// `camera` with near and far framed for where it stands and looks: far beyond the mesh's farthest vertex
// along the view direction, near where the mesh begins in front of the eye (a little before its nearest
// vertex there, and no nearer than far / 2^20, where a vertex lies at or behind the eye). A mesh wholly
// behind the eye keeps the camera's planes: nothing of it can be seen.
Camera frame_depth(const Mesh& mesh, Camera camera);

// The lecture's matrices. view_matrix: M_view = R_view * T_view, the camera at the origin looking down -z
// with y up. projection_matrix: M_ortho * M_persp->ortho with the lecture's n = -near, f = -far, followed by
// a flip of z so that, as the z-buffer wants, smaller z is nearer (near -> -1, far -> +1) and w = -z_view
// is positive in front of the camera. viewport_matrix: x_s = W/2 (x + 1), y_s = H/2 (y + 1), z unchanged.
Mat4 view_matrix(const Camera& camera);
Mat4 projection_matrix(double fov_y_degrees, double aspect, double near_plane, double far_plane);
Mat4 viewport_matrix(Viewport viewport);

struct Projection {
    Scene scene;
    std::vector<std::size_t> source_face;  // per scene triangle, the mesh face it came from
    std::size_t faces_cut = 0;             // faces the near plane cut, each drawn in part
    std::size_t faces_hidden = 0;          // faces wholly behind the near plane, not drawn
};

// The mesh as seen by the camera. Faces crossing the near plane are clipped there in clip space into one
// or two triangles keeping the face's winding, so front or back facing stays the sign of the screen-space
// area; faces wholly behind the near plane are dropped. A vertex made on an edge
// is computed from the edge's endpoints in one canonical order, so the two faces sharing the edge get the
// bit-identical vertex and a clipped closed mesh stays watertight. The far plane does not clip: depth
// stays monotonic beyond it (z > 1), so the z-buffer still orders correctly. Triangle ids are in output
// order, faces in mesh order. Throws std::invalid_argument for a bad camera, viewport or sample count
// (rast/scene_limits.h), or a projected coordinate that overflows.
Projection project_with_sources(const Mesh& mesh, const Camera& camera, Viewport viewport, int samples);
Scene project(const Mesh& mesh, const Camera& camera, Viewport viewport, int samples);

}  // namespace rast
