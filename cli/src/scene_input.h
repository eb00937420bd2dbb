// rast — where a scene comes from: a .tri file as it is, or a mesh placed by a camera.
#pragma once

#include <rast/scene.h>
#include <rast/vec.h>

#include <CLI/App.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rast::cli {

// What the user may say about a mesh's camera and viewport; unset values take the automatic framing.
struct MeshView {
    int width = 512;
    int height = 512;
    std::optional<Vec3> eye, target, up;
    std::optional<double> fov_y_degrees, near_plane, far_plane;
};

// The SCENE that names standard input: a .tri scene read from it.
inline constexpr const char* kStandardInput = "-";

// A scene as the user names it on the command line.
struct SceneInput {
    std::string path;             // a .tri scene, a mesh file, or kStandardInput
    MeshView view;                // for a mesh
    std::optional<int> samples;   // overrides the scene's samples per pixel

    // Reads a .tri scene, or a mesh projected into the viewport by the (framed or given) camera, and
    // applies the samples override.
    Scene load() const;
    // The samples override applied to a scene from elsewhere; throws std::invalid_argument when the scene
    // would then be above the size limit (scene_limits.h).
    Scene with_samples(Scene scene) const;
    bool is_mesh() const;
    // The options after SCENE that make this scene again: --samples if given, and for a mesh its viewport and
    // the camera options given (e.g. " --samples 4 --width=512 --height=512 --eye=0,0,5"; empty if none).
    std::string options() const;
};

// "3 triangles, 2 lines, 64x48, 4 sample(s) per pixel" (the lines only where there are some).
std::string summary(const Scene& scene);

// Registers SCENE, --samples, --width/--height and the camera options on a subcommand; returns SCENE.
// --width/--height and the camera options are refused with a .tri SCENE, which would ignore them.
CLI::Option* add_scene_options(CLI::App& command, SceneInput& input);

// The options --width/--height and the camera options that add_scene_options registered on `command`.
std::vector<CLI::Option*> mesh_view_options(CLI::App& command);

}  // namespace rast::cli
