// rast diff: the reference and the fast path side by side, with the samples where they disagree marked.
// A difference is information about a precision mode, not an error: the exit status is 0.
#include "commands.h"
#include "engine_choice.h"
#include "output_paths.h"
#include "png_image.h"
#include "progress_meter.h"
#include "scene_input.h"

#include <rast/atomic_file.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace rast::cli {
namespace {

struct DiffOptions {
    SceneInput input;
    EngineChoice engine{.engine = "fast"};
    std::optional<std::string> image_out;
    std::optional<int> magnify;  // none: small viewports magnified up to kDefaultSide
};

// Small viewports are magnified (nearest neighbour) as many times as keeps the longer side within this
// many picture pixels, at most kMaxMagnify, so that single pixels are visible.
constexpr int kDefaultSide = 512;
constexpr std::array<std::uint8_t, 3> kDisagree{255, 0, 255};

// Where the two agree, the reference dimmed to a quarter; where any sample differs, the loud colour,
// as strong as the share of samples that differ (but never fainter than half).
Image disagreement(const Framebuffer& a, const Framebuffer& b, const Image& reference) {
    Image out = reference;
    for (int j = 0; j < a.viewport.height; ++j)
        for (int i = 0; i < a.viewport.width; ++i) {
            int differing = 0;
            for (int s = 0; s < a.samples; ++s) differing += a.id(i, j, s) != b.id(i, j, s);
            std::uint8_t* px = out.at(i, a.viewport.height - 1 - j);
            const double share = differing == 0 ? 0 : 0.5 + 0.5 * double(differing) / a.samples;
            for (int k = 0; k < 3; ++k)
                px[k] = static_cast<std::uint8_t>(share * kDisagree[k] + (1 - share) * px[k] / 4);
        }
    return out;
}


void run_diff(const DiffOptions& o) {
    check_output_paths({o.input.path}, {{"-o", o.image_out}});
    const Scene scene = o.input.load();
    const Viewport vp = scene.viewport;
    const int scale = o.magnify.value_or(std::clamp(kDefaultSide / std::max(vp.width, vp.height), 1, kMaxMagnify));
    if (o.image_out) {
        // Three panels side by side, with two separators, checked before the work.
        try {
            check_picture_size((std::int64_t{vp.width} * 3 + 2) * scale, std::int64_t{vp.height} * scale);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--magnify " + std::to_string(scale) + ": " + e.what());
        }
    }
    const Engine engine = o.engine.make();
    note_unbounded_triangles(scene, engine);
    const auto meter = stderr_meter("reference render", "triangles");
    const Framebuffer exact = reference_engine(nullptr, meter->progress()).render(scene);
    const Framebuffer fast = engine.render(scene);

    std::size_t samples = 0, pixels = 0;
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            int differing = 0;
            for (int s = 0; s < scene.samples; ++s) differing += exact.id(i, j, s) != fast.id(i, j, s);
            samples += differing;
            pixels += differing > 0;
        }
    std::cout << "scene:  " << o.input.path << ": " << summary(scene) << "\n"
              << "compare: reference (exact) vs " << engine.description << '\n'
              << "differing samples: " << samples << " of " << exact.ids.size() << '\n'
              << "differing pixels: " << pixels << " of " << std::size_t(vp.width) * vp.height << '\n';
    if (!o.image_out) return;
    const Image reference = resolve_ids(exact, scene.lines);
    const Image panels =
        side_by_side({reference, resolve_ids(fast, scene.lines), disagreement(exact, fast, reference)}, scale);
    write_file_atomic(*o.image_out, encode_png(panels));
    std::cout << "wrote " << *o.image_out << " (reference | " << engine.description
              << " | disagreeing pixels in magenta), magnified " << scale << "x\n";
}

}  // namespace

void add_diff_command(CLI::App& app) {
    auto o = std::make_shared<DiffOptions>();
    CLI::App* cmd = app.add_subcommand(
        "diff",
        "Render a scene with the exact reference and with another engine (the fast path, or a plugin), count\n"
        "the samples and pixels where their id buffers disagree, and optionally draw both side by side with a third panel marking the\n"
        "disagreeing pixels in magenta (small viewports magnified). A difference is information about a\n"
        "precision mode, not an error: the exit status is 0 whatever the count.");
    add_scene_options(*cmd, o->input)->required();
    add_engine_options(*cmd, o->engine);
    // One side is always the reference.
    cmd->get_option("--engine")
        ->description("The rasterizer compared with the reference: the fast path, or plugin:PATH, a shared library "
                      "with the plugin ABI (rast/plugin.h)")
        ->type_name("fast|plugin:PATH")
        ->check([](const std::string& s) {
            return s == "reference" ? "diff compares the reference with another engine" : "";
        });
    CLI::Option* image =
        cmd->add_option("-o,--output", o->image_out, "Write the side-by-side picture as PNG")->check(png_name);
    cmd->add_option("--magnify", o->magnify,
                    "Magnify the picture N times, nearest neighbour (default: small viewports up to 512 pixels a "
                    "side, at most 64 times); a pixel's magenta is stronger the more of its samples differ")
        ->check(CLI::Range(1, kMaxMagnify))
        ->needs(image);
    cmd->callback([o] { run_diff(*o); });
}

}  // namespace rast::cli
