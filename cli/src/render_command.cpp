// rast render: rasterize a scene with one engine and write what the user asks for.
#include "buffer_files.h"
#include "commands.h"
#include "default_scene.h"
#include "engine_choice.h"
#include "output_paths.h"
#include "png_image.h"
#include "progress_meter.h"
#include "scene_input.h"

#include <rast/atomic_file.h>
#include <rast/reference.h>
#include <rast/visible_area.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rast::cli {
namespace {

constexpr int kErrorSampleCounts[] = {1, 4, 8, 16};

struct RenderOptions {
    SceneInput input;
    bool use_default = false;
    EngineChoice engine;
    std::optional<std::string> image_out;
    int magnify = 1;
    std::string coverage = "samples";
    std::optional<std::string> ids_out, depth_out, coverage_out, visible_out;
};

std::string percent(std::uint64_t part, std::uint64_t whole) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g%%", whole == 0 ? 0.0 : 100.0 * double(part) / double(whole));
    return text;
}

// The exact area coverage as a grey picture (an area above 1, where triangles overlap, shows white).
Image area_image(Viewport vp, const std::vector<reference::Rational>& area) {
    Image image(vp.width, vp.height);
    for (int j = 0; j < vp.height; ++j) {
        for (int i = 0; i < vp.width; ++i) {
            const double a = std::min(1.0, area[std::size_t(j) * vp.width + i].convert_to<double>());
            std::uint8_t* out = image.at(i, vp.height - 1 - j);
            std::fill(out, out + 3, static_cast<std::uint8_t>(a * 255 + 0.5));
        }
    }
    return image;
}

// The depth buffer as a grey ramp over its finite depths: the nearest white, the farthest a fifth of it,
// empty samples black; a pixel the average of its samples. One finite depth alone is white.
Image depth_image(const Framebuffer& fb) {
    double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
    for (const double z : fb.depth)
        if (std::isfinite(z)) nearest = std::min(nearest, z), farthest = std::max(farthest, z);
    const double span = farthest - nearest;
    Image image(fb.viewport.width, fb.viewport.height);
    for (int j = 0; j < fb.viewport.height; ++j)
        for (int i = 0; i < fb.viewport.width; ++i) {
            double sum = 0;
            for (int s = 0; s < fb.samples; ++s) {
                const double z = fb.depth[fb.index(i, j, s)];
                if (std::isfinite(z)) sum += 1 - 0.8 * (span > 0 ? (z - nearest) / span : 0);
            }
            std::uint8_t* out = image.at(i, fb.viewport.height - 1 - j);
            std::fill(out, out + 3, static_cast<std::uint8_t>(sum / fb.samples * 255 + 0.5));
        }
    return image;
}

void run_render(const RenderOptions& o) {
    if (o.engine.plugin() && (o.depth_out || (o.image_out && o.coverage == "depth")))
        throw std::invalid_argument(std::string(o.depth_out ? "--depth-out" : "--coverage depth") +
                                    ": a plugin returns ids only, no depths");
    std::vector<std::filesystem::path> inputs;
    if (!o.use_default) inputs.push_back(o.input.path);
    check_output_paths(inputs, {{"-o", o.image_out}, {"--ids-out", o.ids_out}, {"--depth-out", o.depth_out},
                                {"--coverage-out", o.coverage_out}, {"--visible-out", o.visible_out}});
    const Scene scene = o.use_default ? o.input.with_samples(default_scene()) : o.input.load();
    const std::string name = o.use_default ? "default scene" : o.input.path;
    // --coverage visible-error shows the ideal and the error at each sample count side by side.
    const int panels = o.coverage == "visible-error" ? 1 + static_cast<int>(std::size(kErrorSampleCounts)) : 1;
    if (o.image_out) {
        try {
            check_picture_size((std::int64_t{scene.viewport.width} * panels + panels - 1) * o.magnify,
                               std::int64_t{scene.viewport.height} * o.magnify);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--magnify " + std::to_string(o.magnify) + ": " + e.what());
        }
    }

    reference::Stats stats;
    const auto meter = stderr_meter("reference render", "triangles");
    const Engine engine = o.engine.make(&stats, meter->progress());
    if (panels > 1 && !scene.lines.empty())
        throw std::invalid_argument("--coverage visible-error measures samples against the exact visible area, "
                                    "in which lines (no area) have no part; the scene has " +
                                    std::to_string(scene.lines.size()) + " lines");
    if (panels > 1 && engine.contract) {
        for (const int n : kErrorSampleCounts)
            if (!engine.contract->renders(n))
                throw std::invalid_argument("--coverage visible-error renders 1, 4, 8 and 16 samples a pixel; " +
                                            engine.name + " does not render " + std::to_string(n));
    }
    note_unbounded_triangles(scene, engine);
    const auto start = std::chrono::steady_clock::now();
    const Framebuffer fb = engine.render(scene);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    std::size_t covered = 0;
    for (auto id : fb.ids) covered += id != Framebuffer::kNoTriangle;
    std::cout << "scene:   " << name << ": " << summary(scene) << "\n"
              << "engine:  " << engine.description << ", " << std::fixed << std::setprecision(2) << ms
              << " ms\n" << std::defaultfloat
              << "covered: " << covered << " of " << fb.ids.size() << " samples\n";
    if (engine.is_reference()) {
        // How often the floating-point filters could not decide and exact arithmetic ran.
        const auto line = [](std::uint64_t exact, std::uint64_t all, const char* what) {
            std::cout << "  " << exact << " of " << all << ' ' << what << " (" << percent(exact, all) << ")\n";
        };
        std::cout << "exact arithmetic needed for:\n";
        line(stats.orientation_exact, stats.orientation_tests, "orientation tests");
        line(stats.depth_exact, stats.depth_tests, "depth comparisons");
        line(stats.depth_nearest_exact, stats.samples_covered, "depths rounded to nearest");
    }

    const bool want_area = o.coverage == "area" || o.coverage_out;
    const auto area_meter = stderr_meter("exact area", "triangles");
    const auto area = want_area ? reference::coverage_area(scene, area_meter->progress())
                                : std::vector<reference::Rational>{};
    std::optional<reference::VisibleArea> visible;
    if (o.coverage.starts_with("visible") || o.visible_out) {
        const auto visible_meter = stderr_meter("exact visible area", "rows");
        const auto begin = std::chrono::steady_clock::now();
        visible = reference::visible_area(scene, visible_meter->progress());
        std::cout << "visible: the exact visible area in " << std::fixed << std::setprecision(2)
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() << " s\n"
                  << std::defaultfloat;
    }
    // Every file's bytes first, so that nothing is written unless all of them could be made.
    std::vector<std::pair<std::string, std::string>> files;
    if (o.image_out) {
        std::vector<Image> pictures;
        if (o.coverage == "area") pictures.push_back(area_image(scene.viewport, area));
        else if (o.coverage == "depth") pictures.push_back(depth_image(fb));
        else if (o.coverage == "samples") pictures.push_back(resolve_ids(fb, scene.lines));
        else pictures.push_back(visible_image(*visible));
        if (o.coverage == "visible-error") {
            for (const int n : kErrorSampleCounts) {
                Scene at_n = scene;
                at_n.samples = n;
                pictures.push_back(resolve_error_image(*visible, engine.render(at_n)));
            }
        }
        files.emplace_back(*o.image_out, encode_png(o.magnify == 1 && pictures.size() == 1
                                                        ? pictures.front()
                                                        : side_by_side(pictures, o.magnify)));
    }
    if (o.ids_out) files.emplace_back(*o.ids_out, format_ids(fb));
    if (o.depth_out) files.emplace_back(*o.depth_out, format_depth(fb));
    if (o.coverage_out) files.emplace_back(*o.coverage_out, format_area(scene.viewport, area));
    if (o.visible_out) files.emplace_back(*o.visible_out, format_visible(*visible));
    write_files_atomic(std::vector<FileContent>(files.begin(), files.end()));
    for (const auto& file : files) std::cout << "wrote " << file.first << '\n';
}

}  // namespace

void add_render_command(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Rasterize a scene (.tri, or a mesh: OBJ, OFF, PLY, STL) and write a picture and buffers");
    auto* scene = add_scene_options(*cmd, o->input);
    auto* def = cmd->add_flag("--default", o->use_default, "Render the built-in default scene instead");
    scene->excludes(def);
    // The built-in scene is in screen space already: a camera would be ignored.
    for (CLI::Option* view : mesh_view_options(*cmd)) def->excludes(view);
    add_engine_options(*cmd, o->engine);
    auto* image =
        cmd->add_option("-o,--output", o->image_out, "Write a PNG picture: each triangle id in its own colour, lines paler")
            ->check(png_name);
    // Both shape the picture only: without one they would be ignored.
    cmd->add_option("--magnify", o->magnify, "Magnify the picture N times, nearest neighbour, so pixels stay sharp")
        ->check(CLI::Range(1, kMaxMagnify))
        ->capture_default_str()
        ->needs(image);
    cmd->add_option("--coverage", o->coverage,
                    "What the picture shows: 'samples' (ids, samples averaged), 'area' (exact area coverage), "
                    "'depth' (a grey ramp, nearest white, over the finite depths), 'visible' (the ideal antialiased "
                    "picture: id colours weighted by exact visible area) or 'visible-error' (that ideal, then the "
                    "engine's error against it at 1, 4, 8 and 16 samples: grey = square root of the error)")
        ->check(CLI::IsMember({"samples", "area", "depth", "visible", "visible-error"}))
        ->capture_default_str()
        ->needs(image);
    cmd->add_option("--ids-out", o->ids_out,
                    "Write the id buffer: H lines of W ids of the triangle or line owning each pixel centre, or -1");
    cmd->add_option("--depth-out", o->depth_out,
                    "Write the depth buffer: H lines of W depths at pixel centres (inf where empty)");
    cmd->add_option("--coverage-out", o->coverage_out,
                    "Write the exact covered area of every pixel: H lines of W rationals p/q, depth ignored");
    cmd->add_option("--visible-out", o->visible_out,
                    "Write the exact visible area: H lines of W entries, id:area pairs joined by ',' (ids "
                    "ascending, areas p/q), '-' where nothing is seen");
    cmd->callback([o, scene, def] {
        if (scene->count() == 0 && def->count() == 0) throw CLI::RequiredError("SCENE or --default");
        run_render(*o);
    });
}

}  // namespace rast::cli
