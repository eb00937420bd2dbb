// rast — where a scene comes from: a .tri file as it is, or a mesh placed by a camera.
#pragma once

#include <rast/scene.h>
#include <rast/vec.h>

#include <CLI/App.hpp>

#include <optional>
#include <string>

namespace rast::cli {

// What the user may say about a mesh's camera and viewport; unset values take the automatic framing.
struct MeshView {
    int width = 512;
    int height = 512;
    std::optional<Vec3> eye, target, up;
    std::optional<double> fov_y_degrees, near_plane, far_plane;
};

// Registers --width/--height and the camera options on a subcommand.
void add_mesh_view_options(CLI::App& command, MeshView& view);

// True for the mesh file extensions (OBJ, OFF, PLY, STL), case-insensitively.
bool is_mesh_path(const std::string& path);

// Reads a .tri scene, or a mesh projected into the viewport by the (framed or given) camera.
Scene load_scene(const std::string& path, const MeshView& view);

}  // namespace rast::cli
