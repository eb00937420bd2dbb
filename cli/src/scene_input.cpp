#include "scene_input.h"
#include "wording.h"

#include <rast/mesh.h>
#include <rast/number_text.h>
#include <rast/scene_limits.h>
#include <rast/tri_format.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace rast::cli {
namespace {

const std::string kMeshViewGroup = "Meshes (OBJ, OFF, PLY, STL)";

bool is_mesh_path(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}

// "x,y,z" into three finite doubles, for CLI11.
CLI::Option* add_vector_option(CLI::App& command, const std::string& name, std::optional<Vec3>& target,
                               const std::string& help) {
    return command
        .add_option_function<std::vector<double>>(
            name, [&target](const std::vector<double>& v) { target = Vec3{v[0], v[1], v[2]}; }, help)
        ->delimiter(',')
        ->expected(3)
        ->type_name("X,Y,Z")
        ->check(CLI::Number);
}

// A finite distance of at least the least normal double, read as CLI11 reads it (strtold, then rounded to
// double). CLI::PositiveNumber's message spells out the largest double, 309 digits; a subnormal near plane
// left the camera's depth range empty, so that nothing was drawn.
std::string positive_distance(const std::string& text) {
    char* end = nullptr;
    const double value = static_cast<double>(std::strtold(text.c_str(), &end));
    const bool read = end != text.c_str() && *end == '\0';
    return read && value > 0 && std::isnormal(value)
               ? ""
               : "a distance must be finite and at least 2^-1022, the least normal double; got " + text;
}

void add_mesh_view_options(CLI::App& command, MeshView& view) {
    const std::vector<CLI::Option*> options{
        command.add_option("--width", view.width, "Viewport width in pixels, for a mesh")
            ->check(CLI::Range(1, 32768))
            ->capture_default_str(),
        command.add_option("--height", view.height, "Viewport height in pixels, for a mesh")
            ->check(CLI::Range(1, 32768))
            ->capture_default_str(),
        add_vector_option(command, "--eye", view.eye, "Camera position (default: framed to fit the mesh)"),
        add_vector_option(command, "--target", view.target, "Point the camera looks at (default: the mesh's centre)"),
        add_vector_option(command, "--up", view.up, "Camera up direction (default: 0,1,0)"),
        command.add_option("--fov", view.fov_y_degrees, "Vertical field of view in degrees (default: 45)")
            ->check(CLI::Range(1e-3, 179.0)),
        command.add_option("--near", view.near_plane, "Near plane distance (default: framed)")
            ->check(positive_distance),
        command.add_option("--far", view.far_plane, "Far plane distance (default: framed)")
            ->check(positive_distance)};
    // A .tri scene is in screen space already: it would ignore them. Parsing has read every argument before
    // any option is checked, so SCENE's value is there to look at.
    const auto for_meshes_only = [&command](const std::string&) -> std::string {
        const CLI::Option* scene = command.get_option("SCENE");
        if (scene->count() == 0 || is_mesh_path(scene->results().back())) return {};
        return "applies to meshes only (OBJ, OFF, PLY, STL), and " + scene->results().back() + " is a .tri scene";
    };
    for (CLI::Option* option : options) option->group(kMeshViewGroup)->check(for_meshes_only);
}

}  // namespace

CLI::Option* add_scene_options(CLI::App& command, SceneInput& input) {
    CLI::Option* scene =
        command
            .add_option("SCENE", input.path,
                        "A .tri scene or a mesh file (OBJ, OFF, PLY, STL); - reads a .tri scene from standard input")
            ->check([](const std::string& path) {
                return path == kStandardInput ? std::string{} : CLI::ExistingFile(path);
            });
    command.add_option("--samples", input.samples, "Samples per pixel (1, 4, 8 or 16); overrides the scene's")
        ->check(CLI::IsMember({1, 4, 8, 16}));
    add_mesh_view_options(command, input.view);
    return scene;
}

std::vector<CLI::Option*> mesh_view_options(CLI::App& command) {
    return command.get_options([](const CLI::Option* option) { return option->get_group() == kMeshViewGroup; });
}

bool SceneInput::is_mesh() const { return is_mesh_path(path); }

std::string SceneInput::options() const {
    // Numbers as the shortest text that reads back as the same double; "=" keeps a leading minus from
    // reading as an option.
    std::string text;
    if (samples) text += " --samples " + std::to_string(*samples);
    if (!is_mesh()) return text;
    text += " --width=" + std::to_string(view.width) + " --height=" + std::to_string(view.height);
    const std::pair<const char*, const std::optional<Vec3>*> vectors[] = {
        {"--eye", &view.eye}, {"--target", &view.target}, {"--up", &view.up}};
    for (const auto& [name, value] : vectors)
        if (*value)
            text += std::string(" ") + name + "=" + shortest((*value)->x) + "," + shortest((*value)->y) + "," +
                    shortest((*value)->z);
    const std::pair<const char*, const std::optional<double>*> scalars[] = {
        {"--fov", &view.fov_y_degrees}, {"--near", &view.near_plane}, {"--far", &view.far_plane}};
    for (const auto& [name, value] : scalars)
        if (*value) text += std::string(" ") + name + "=" + shortest(**value);
    return text;
}

Scene SceneInput::with_samples(Scene scene) const {
    if (!samples) return scene;
    // The scene was checked with its own count; a larger one can take it past the size limit.
    try {
        check_scene_size(scene.viewport, *samples);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--samples " + std::to_string(*samples) + ": " + e.what());
    }
    scene.samples = *samples;
    return scene;
}

Scene SceneInput::load() const {
    if (path == kStandardInput) return with_samples(read_tri_document(std::cin, "<stdin>").scene);
    if (!is_mesh()) return with_samples(read_tri_file(path));
    const Mesh mesh = read_mesh(path);
    const Viewport vp{view.width, view.height};
    Camera camera = frame(mesh, vp);
    if (view.eye) camera.eye = *view.eye;
    if (view.target) camera.target = *view.target;
    if (view.up) camera.up = *view.up;
    if (view.fov_y_degrees) camera.fov_y_degrees = *view.fov_y_degrees;
    // The default planes bracket the mesh as seen from the default eye; from anywhere else, frame them
    // again for the camera in use.
    if (view.eye || view.target || view.up) camera = frame_depth(mesh, camera);
    if (view.near_plane) camera.near_plane = *view.near_plane;
    if (view.far_plane) camera.far_plane = *view.far_plane;
    const Projection projection = project_with_sources(mesh, camera, vp, 1);
    if (projection.faces_cut > 0 || projection.faces_hidden > 0)
        std::cerr << "rast: note: the near plane, " << shortest(camera.near_plane) << " from the eye, cuts "
                  << projection.faces_cut << " of the mesh's " << mesh.faces.size() << " faces and hides "
                  << projection.faces_hidden << " behind it (move the camera, or set --near)\n";
    return with_samples(projection.scene);
}

std::string summary(const Scene& scene) {
    std::string text = counted(scene.triangles.size(), "triangle", "triangles") + ", ";
    if (!scene.lines.empty()) text += counted(scene.lines.size(), "line", "lines") + ", ";
    return text + std::to_string(scene.viewport.width) + "x" + std::to_string(scene.viewport.height) + ", " +
           std::to_string(scene.samples) + " sample(s) per pixel";
}

}  // namespace rast::cli
