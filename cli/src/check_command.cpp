// rast check: how many triangles cover each sample, with no z-buffer. A closed mesh must cover every sample
// as often by front-facing as by back-facing triangles (so an even number of times): a ray that enters a
// closed surface leaves it. In a .tri scene, two triangles that share an edge must not both cover a sample.
// Either failure is a crack or an overlap along shared edges, printed, kept as a corpus case, and the exit
// status.
#include "commands.h"
#include "engine_choice.h"
#include "option_checks.h"
#include "output_paths.h"
#include "scene_input.h"
#include <rast/shell_word.h>

#include <rast/exact_geometry.h>
#include <rast/properties.h>
#include <rast/mesh.h>
#include <rast/number_text.h>
#include <rast/tri_format.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rast::cli {
namespace {

namespace fs = std::filesystem;

struct CheckOptions {
    EngineChoice engine;
    SceneInput input;
    std::string corpus_out = "corpus/found";
    bool corpus_out_given = false;  // --corpus-out on the command line
    std::size_t show = 20;
};

struct Violation {
    std::size_t sample;  // Framebuffer::index
    std::string what;
};

std::string describe_sample(Viewport vp, int samples, std::size_t index) {
    const int s = static_cast<int>(index % samples);
    const std::size_t pixel = index / samples;
    const int i = static_cast<int>(pixel % vp.width), j = static_cast<int>(pixel / vp.width);
    const SamplePoint p = sample_pattern(samples)[s];
    return "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") sample " + std::to_string(s) + " at (" +
           shortest(i + p.x) + ", " + shortest(j + p.y) + ")";
}

// For every sample, the triangles that cover it, ascending, as compressed rows: one offset per sample and
// one flat array of triangle ids, 4 bytes each. A vector per sample took 24 bytes a sample, twice render's
// buffers; this takes 4, beside 4 per covering and, while it is built, one triangle's list of samples.
class Coverage {
public:
    // Each triangle is rasterized twice, to count and then to fill, so no per-triangle lists are held.
    Coverage(const Scene& scene, const Engine& engine)
        : offsets_(static_cast<std::size_t>(scene.viewport.width) * scene.viewport.height * scene.samples + 1) {
        const auto& triangles = scene.triangles;
        // edge_numbers names each triangle's edges by 3 * triangle + edge in 32 bits.
        if (triangles.size() > std::numeric_limits<std::uint32_t>::max() / 3)
            throw std::length_error("rast check: " + std::to_string(triangles.size()) +
                                    " triangles exceed 32-bit edge numbers");
        for (const Triangle& t : triangles)
            for (std::size_t index : engine.covered_samples(t, scene.viewport, scene.samples)) ++offsets_[index + 1];
        // offsets_[index + 1] becomes where the sample's ids start, and the fill below moves it to where
        // they end, which is where the next sample's start.
        std::uint64_t total = 0;
        for (std::size_t k = 1; k < offsets_.size(); ++k)
            total += std::exchange(offsets_[k], static_cast<std::uint32_t>(total));
        if (total > std::numeric_limits<std::uint32_t>::max())
            throw std::length_error("rast check: " + std::to_string(total) + " coverings exceed 32-bit indices");
        ids_.resize(total);
        for (std::size_t k = 0; k < triangles.size(); ++k)
            for (std::size_t index : engine.covered_samples(triangles[k], scene.viewport, scene.samples))
                ids_[offsets_[index + 1]++] = static_cast<std::uint32_t>(k);
    }

    std::size_t samples() const { return offsets_.size() - 1; }
    std::span<const std::uint32_t> at(std::size_t sample) const {
        return {ids_.data() + offsets_[sample], ids_.data() + offsets_[sample + 1]};
    }

private:
    std::vector<std::uint32_t> offsets_, ids_;
};

// Each triangle's three edges as numbers, equal exactly where the endpoints are (as doubles, either
// direction): the edges sorted once, so that equal ones are adjacent.
std::vector<std::array<std::uint32_t, 3>> edge_numbers(const std::vector<Triangle>& triangles) {
    using Point = std::pair<double, double>;
    std::vector<std::pair<std::pair<Point, Point>, std::uint32_t>> edges;  // (edge, 3 * triangle + e)
    edges.reserve(3 * triangles.size());
    for (std::size_t k = 0; k < triangles.size(); ++k)
        for (int e = 0; e < 3; ++e) {
            const Vertex &a = triangles[k].v[e], &b = triangles[k].v[(e + 1) % 3];
            edges.push_back({std::minmax(Point{a.x, a.y}, Point{b.x, b.y}), static_cast<std::uint32_t>(3 * k + e)});
        }
    std::ranges::sort(edges);
    std::vector<std::array<std::uint32_t, 3>> numbers(triangles.size());
    std::uint32_t number = 0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        if (k > 0 && edges[k].first != edges[k - 1].first) ++number;
        numbers[edges[k].second / 3][edges[k].second % 3] = number;
    }
    return numbers;
}

// A .tri scene: samples covered by two triangles that share an edge, each named by its first such pair
// (lowest ids first). At each sample the covering triangles' edges are sorted, so that a shared one
// shows as a run: the cost grows as the coverings times their logarithm, however deep the overlap and
// however many triangles share one edge.
std::vector<Violation> overlaps_along_shared_edges(const Scene& scene, const Coverage& coverage) {
    std::vector<Violation> found;
    const auto numbers = edge_numbers(scene.triangles);
    const std::vector<std::int32_t> id_of = triangle_ids(scene);  // as --ids-out names them, lines counted
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // (edge number, triangle) at one sample
    for (std::size_t index = 0; index < coverage.samples(); ++index) {
        const auto ids = coverage.at(index);
        edges.clear();
        for (std::uint32_t t : ids)
            for (std::uint32_t number : numbers[t]) edges.push_back({number, t});
        std::ranges::sort(edges);
        // Within a run of one edge the triangles ascend: its least pair is its first two distinct ones.
        std::optional<std::pair<std::uint32_t, std::uint32_t>> least;
        for (std::size_t start = 0, end = 0; start < edges.size(); start = end) {
            while (end < edges.size() && edges[end].first == edges[start].first) ++end;
            for (std::size_t k = start + 1; k < end; ++k)
                if (edges[k].second != edges[start].second) {
                    least = std::min(least.value_or(std::pair{edges[start].second, edges[k].second}),
                                     std::pair{edges[start].second, edges[k].second});
                    break;
                }
        }
        if (least)
            found.push_back({index, "covered " + std::to_string(ids.size()) + " times, by triangles " +
                                        std::to_string(id_of[least->first]) + " and " +
                                        std::to_string(id_of[least->second]) +
                                        ", which share an edge"});
    }
    return found;
}

// A closed mesh: facing is the sign of each projected triangle's screen-space area (projection keeps the
// faces' winding); every sample must be covered as often by front- as by back-facing triangles.
// Facing is that of the geometry the engine rasterizes: snapping can turn a sliver over, and one that
// snapping flattens covers nothing and counts for neither side. Says how many snapping changed.
std::vector<Violation> unbalanced_facing(const Scene& scene, const Engine& engine, const Coverage& coverage) {
    std::vector<int> facing(scene.triangles.size());
    std::size_t turned = 0, flattened = 0;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const int given = properties::orientation(scene.triangles[k]);
        facing[k] = properties::orientation(properties::rasterized_geometry(engine, scene.triangles[k]));
        turned += given != 0 && facing[k] == -given;
        flattened += given != 0 && facing[k] == 0;
    }
    if (engine.snap_bits())
        std::cout << "facing: of the snapped triangles; snapping to the " << engine.name << " grid turned " << turned
                  << " over and flattened " << flattened << '\n';
    std::vector<Violation> found;
    for (std::size_t index = 0; index < coverage.samples(); ++index) {
        const auto ids = coverage.at(index);
        const auto front = std::ranges::count_if(ids, [&](std::uint32_t k) { return facing[k] > 0; });
        const auto back = std::ranges::count_if(ids, [&](std::uint32_t k) { return facing[k] < 0; });
        if (front != back)
            found.push_back({index, "covered " + std::to_string(ids.size()) + " times: " + std::to_string(front) +
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

std::string check_command_line(const CheckOptions& o) {
    std::string text = "rast check " + shell_word(o.input.path) + o.input.options() + " --engine " + o.engine.engine;
    if (o.engine.engine == "fast") text += " --precision " + o.engine.precision;
    return text;
}

// Where a violation is kept: one file per input and engine, replaced by the next run's.
fs::path case_file(const CheckOptions& o, const Engine& engine) {
    const std::string name = "check-" + fs::path(o.input.path).stem().string() + "-" + engine.name + ".tri";
    return fs::path(o.corpus_out) / name;
}

// The violation as a corpus case: the triangles that cover the first violating sample, as the engine
// drew them or as the tie rule would on the geometry it rasterizes (so that a triangle the engine
// wrongly left out is there too). For a scene they are a folded or cracked tiling, which watertight
// rejects; for a mesh, front and back faces overlap by nature, so the case names the per-triangle
// properties that catch a wrong coverage.
fs::path keep_case(const CheckOptions& o, const Engine& engine, const Scene& scene, const Coverage& coverage,
                   const Violation& first, bool mesh) {
    const auto drawn = coverage.at(first.sample);
    const std::size_t pixel = first.sample / static_cast<std::size_t>(scene.samples);
    const SamplePoint p = sample_pattern(scene.samples)[first.sample % static_cast<std::size_t>(scene.samples)];
    const double x = static_cast<double>(pixel % static_cast<std::size_t>(scene.viewport.width)) + p.x;
    const double y = static_cast<double>(pixel / static_cast<std::size_t>(scene.viewport.width)) + p.y;
    const bool one_geometry = !engine.contract || engine.contract->deterministic();
    Scene kept{scene.viewport, scene.samples, {}};
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const Triangle& t = scene.triangles[k];
        const bool by_engine = std::find(drawn.begin(), drawn.end(), k) != drawn.end();
        const bool by_rule = one_geometry && properties::rule_covers(properties::rasterized_geometry(engine, t), x, y);
        if (by_engine || by_rule) kept.triangles.push_back(t);
    }
    const std::string where = describe_sample(scene.viewport, scene.samples, first.sample);
    const TriHeader header{
        {"properties", mesh ? "tie_rule float_within_bound" : "watertight"},
        {"why", "rast check [" + engine.name + "]: " + where + " " + first.what},
        {"found-by", "rast check"},
        {"reproduce", check_command_line(o)}};
    const fs::path file = case_file(o, engine);
    fs::create_directories(file.parent_path());
    write_tri_file(file, kept, header);
    return file;
}

bool run_check(const CheckOptions& o) {
    // A folder the user named is checked before the work. The default is not: most checks find nothing
    // to write, and they run in a folder the user may not write in as well.
    const Engine engine = o.engine.make();
    if (o.corpus_out_given) check_output_paths({o.input.path}, {{"--corpus-out", case_file(o, engine).string(), true}});
    const bool mesh = o.input.is_mesh();
    const Scene scene = o.input.load();
    std::cout << "scene:  " << o.input.path << ": " << summary(scene) << "\nengine: " << engine.description << '\n';
    if (!scene.lines.empty()) std::cout << "lines:  not part of the check: they cover no area\n";

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
    } else {
        std::cout << "rule:   no sample covered by two triangles that share an edge (endpoints bit-identical; a crack\n"
                     "        between edges that only nearly coincide is not seen)\n";
    }
    const Coverage coverage(scene, engine);
    const std::vector<Violation> violations =
        mesh ? unbalanced_facing(scene, engine, coverage) : overlaps_along_shared_edges(scene, coverage);
    for (std::size_t k = 0; k < violations.size() && k < o.show; ++k)
        std::cout << "  " << describe_sample(scene.viewport, scene.samples, violations[k].sample) << ": "
                  << violations[k].what << '\n';
    if (violations.size() > o.show) std::cout << "  ... and " << violations.size() - o.show << " more\n";
    std::cout << violations.size() << " violating samples\n";
    if (violations.empty()) return true;
    const fs::path kept = keep_case(o, engine, scene, coverage, violations.front(), mesh);
    std::cout << "wrote " << kept.string() << '\n';
    return false;
}

}  // namespace

void add_check_command(CLI::App& app, int& status) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* cmd = app.add_subcommand(
        "check",
        "Count, for every sample, the triangles that cover it (no z-buffer). A closed mesh (OBJ, OFF, PLY,\n"
        "STL; OpenMesh tells) must be covered as often by front- as by back-facing triangles everywhere (facing\n"
        "as the engine rasterizes them: snapped, in the fixed modes); a .tri scene must not cover a sample twice\n"
        "by triangles sharing an edge, an edge being shared only where its endpoints are bit-identical (so a\n"
        "crack or T-junction between edges that nearly coincide is not seen). Violations are printed, written\n"
        "as a corpus case, and make the exit status 1.");
    add_scene_options(*cmd, o->input)->required();
    add_engine_options(*cmd, o->engine);
    // Coverage is counted triangle by triangle, on one thread: the option would be ignored.
    cmd->remove_option(cmd->get_option("--threads"));
    // The folder is made only when a violation is found (an empty folder would put it in the working folder).
    CLI::Option* corpus_out =
        cmd->add_option("--corpus-out", o->corpus_out, "Folder for the corpus case a violation is written to")
        ->check(nonempty_folder)
        ->capture_default_str();
    cmd->add_option("--show", o->show, "How many violating samples to print")
        ->transform(decimal_number("a count", std::numeric_limits<std::size_t>::max()))
        ->capture_default_str();
    cmd->callback([o, corpus_out, &status] {
        o->corpus_out_given = corpus_out->count() > 0;
        if (!run_check(*o)) status = 1;
    });
}

}  // namespace rast::cli
