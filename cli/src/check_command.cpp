// rast check: how many triangles cover each sample, with no z-buffer. A closed mesh must cover every sample
// as often by front-facing as by back-facing triangles (so an even number of times): a ray that enters a
// closed surface leaves it. In a .tri scene, two triangles that share an edge must not both cover a sample.
// Either failure is a crack or an overlap along shared edges, printed, kept as a corpus case, and the exit
// status.
#include "commands.h"
#include "engine_choice.h"
#include "scene_input.h"

#include <rast/exact_geometry.h>
#include <rast/mesh.h>
#include <rast/tri_format.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <utility>

namespace rast::cli {
namespace {

namespace fs = std::filesystem;

struct CheckOptions {
    EngineChoice engine;
    SceneInput input;
    std::string corpus_out = "corpus/found";
    std::size_t show = 20;
};

struct Violation {
    std::size_t sample;                    // Framebuffer::index
    std::vector<std::size_t> triangles;    // those covering it, ascending
    std::string what;
};

std::string shortest(double value) {
    char text[32];
    return {text, std::to_chars(text, text + sizeof text, value).ptr};
}

std::string describe_sample(Viewport vp, int samples, std::size_t index) {
    const int s = static_cast<int>(index % samples);
    const std::size_t pixel = index / samples;
    const int i = static_cast<int>(pixel % vp.width), j = static_cast<int>(pixel / vp.width);
    const SamplePoint p = sample_pattern(samples)[s];
    return "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") sample " + std::to_string(s) + " at (" +
           shortest(i + p.x) + ", " + shortest(j + p.y) + ")";
}

std::vector<std::size_t> covered(const Triangle& t, const Scene& scene, const EngineChoice& engine) {
    if (engine.is_reference()) return reference::covered_samples(t, scene.viewport, scene.samples);
    return fast::covered_samples(t, scene.viewport, scene.samples, engine.fast_options().precision);
}

// For every sample, the triangles that cover it, in id order.
std::vector<std::vector<std::size_t>> coverers(const Scene& scene, const EngineChoice& engine) {
    std::vector<std::vector<std::size_t>> by_sample(static_cast<std::size_t>(scene.viewport.width) *
                                                    scene.viewport.height * scene.samples);
    for (std::size_t k = 0; k < scene.triangles.size(); ++k)
        for (std::size_t index : covered(scene.triangles[k], scene, engine)) by_sample[index].push_back(k);
    return by_sample;
}

using Point = std::pair<double, double>;

std::set<std::pair<Point, Point>> edges_of(const Triangle& t) {
    std::set<std::pair<Point, Point>> edges;
    for (int e = 0; e < 3; ++e) {
        Point a{t.v[e].x, t.v[e].y}, b{t.v[(e + 1) % 3].x, t.v[(e + 1) % 3].y};
        edges.insert(std::minmax(a, b));
    }
    return edges;
}

bool share_an_edge(const Triangle& a, const Triangle& b) {
    const auto ea = edges_of(a), eb = edges_of(b);
    return std::any_of(ea.begin(), ea.end(), [&](const auto& e) { return eb.count(e) > 0; });
}

// A .tri scene: samples covered by two triangles that share an edge (bit-identical endpoints).
std::vector<Violation> overlaps_along_shared_edges(const Scene& scene, const EngineChoice& engine) {
    std::vector<Violation> found;
    const auto by_sample = coverers(scene, engine);
    for (std::size_t index = 0; index < by_sample.size(); ++index) {
        const auto& ids = by_sample[index];
        for (std::size_t a = 0; a < ids.size(); ++a)
            for (std::size_t b = a + 1; b < ids.size(); ++b)
                if (share_an_edge(scene.triangles[ids[a]], scene.triangles[ids[b]])) {
                    found.push_back({index, ids,
                                     "covered " + std::to_string(ids.size()) + " times, by triangles " +
                                         std::to_string(ids[a]) + " and " + std::to_string(ids[b]) +
                                         ", which share an edge"});
                    a = b = ids.size();
                }
    }
    return found;
}

// A closed mesh: facing is the sign of each projected triangle's screen-space area (projection keeps the
// faces' winding); every sample must be covered as often by front- as by back-facing triangles.
std::vector<Violation> unbalanced_facing(const Scene& scene, const EngineChoice& engine) {
    std::vector<Violation> found;
    const auto by_sample = coverers(scene, engine);
    for (std::size_t index = 0; index < by_sample.size(); ++index) {
        int front = 0, back = 0;
        for (std::size_t k : by_sample[index]) (properties::orientation(scene.triangles[k]) > 0 ? front : back) += 1;
        if (front != back)
            found.push_back({index, by_sample[index],
                             "covered " + std::to_string(front + back) + " times: " + std::to_string(front) +
                                 " front-facing, " + std::to_string(back) + " back-facing"});
    }
    return found;
}

// The near plane maps to z = -1 exactly, and a clipped vertex is made on it: a mesh cut there is open on
// screen, and its coverage no longer balances.
bool cut_by_near_plane(const Scene& scene) {
    for (const Triangle& t : scene.triangles)
        for (const Vertex& v : t.v)
            if (v.z <= -1) return true;
    return false;
}

std::string command_line(const CheckOptions& o) {
    std::string text = "rast check " + o.input.path + " --engine " + o.engine.engine;
    if (!o.engine.is_reference()) text += " --precision " + o.engine.precision;
    return text;
}

// The violation as a corpus case: the triangles that cover the first violating sample. For a scene
// they are a folded or cracked tiling, which watertight rejects; for a mesh, front and back faces
// overlap by nature, so the case names the per-triangle properties that catch a wrong coverage.
fs::path keep_case(const CheckOptions& o, const Scene& scene, const Violation& first, bool mesh) {
    Scene kept{scene.viewport, scene.samples, {}};
    for (std::size_t k : first.triangles) kept.triangles.push_back(scene.triangles[k]);
    const std::string engine = o.engine.is_reference() ? "reference" : o.engine.precision;
    const std::string where = describe_sample(scene.viewport, scene.samples, first.sample);
    const TriHeader header{
        {"properties", mesh ? "tie_rule float_within_bound" : "watertight"},
        {"why", "rast check [" + engine + "]: " + where + " " + first.what},
        {"found-by", "rast check"},
        {"reproduce", command_line(o)}};
    const fs::path file =
        fs::path(o.corpus_out) / ("check-" + fs::path(o.input.path).stem().string() + "-" + engine + ".tri");
    fs::create_directories(file.parent_path());
    write_tri_file(file, kept, header);
    return file;
}

bool run_check(const CheckOptions& o) {
    const bool mesh = o.input.is_mesh();
    const Scene scene = o.input.load();
    std::cout << "scene:  " << o.input.path << ": " << scene.triangles.size() << " triangles, "
              << scene.viewport.width << "x" << scene.viewport.height << ", " << scene.samples
              << " sample(s) per pixel\nengine: " << o.engine.describe() << '\n';

    std::vector<Violation> violations;
    if (mesh) {
        if (!read_mesh(o.input.path).closed) {
            std::cout << "rule:   none: the mesh has boundary edges, so coverage need not balance\n";
            return true;
        }
        if (cut_by_near_plane(scene)) {
            std::cout << "rule:   none: the near plane cuts the mesh open; move the camera (--eye, --near)\n";
            return true;
        }
        std::cout << "rule:   closed mesh: every sample covered as often by front- as by back-facing triangles\n";
        violations = unbalanced_facing(scene, o.engine);
    } else {
        std::cout << "rule:   no sample covered by two triangles that share an edge\n";
        violations = overlaps_along_shared_edges(scene, o.engine);
    }
    for (std::size_t k = 0; k < violations.size() && k < o.show; ++k)
        std::cout << "  " << describe_sample(scene.viewport, scene.samples, violations[k].sample) << ": "
                  << violations[k].what << '\n';
    if (violations.size() > o.show) std::cout << "  ... and " << violations.size() - o.show << " more\n";
    std::cout << violations.size() << " violating samples\n";
    if (violations.empty()) return true;
    std::cout << "wrote " << keep_case(o, scene, violations.front(), mesh).string() << '\n';
    return false;
}

}  // namespace

void add_check_command(CLI::App& app, int& status) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* cmd = app.add_subcommand(
        "check",
        "Count, for every sample, the triangles that cover it (no z-buffer). A closed mesh (OBJ, OFF, PLY,\n"
        "STL; OpenMesh tells) must be covered as often by front- as by back-facing triangles everywhere; a .tri\n"
        "scene must not cover a sample twice by triangles sharing an edge. Violations are printed, written as a\n"
        "corpus case, and make the exit status 1.");
    add_scene_options(*cmd, o->input)->required();
    add_engine_options(*cmd, o->engine);
    cmd->add_option("--corpus-out", o->corpus_out, "Folder for the corpus case a violation is written to")
        ->capture_default_str();
    cmd->add_option("--show", o->show, "How many violating samples to print")->capture_default_str();
    cmd->callback([o, &status] {
        if (!run_check(*o)) status = 1;
    });
}

}  // namespace rast::cli
