// rast — the results of one `rast bench` run and the three ways they are written: a table for the
// terminal, JSON, and an SVG plot of speed against error.
#pragma once

#include <rast/aa_error.h>
#include <rast/scene.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rast::bench {

struct Machine {
    std::string cpu;      // model name from /proc/cpuinfo
    unsigned cores = 0;   // online processors
    double load_before = 0, load_after = 0;  // 1-minute load average at the start and the end
    std::string date;     // UTC, ISO 8601
};

struct SceneInfo {
    std::string name;
    std::string description;  // how it was made: generator spec or mesh file and camera
    std::size_t triangles = 0;
    Viewport viewport;
    int samples = 1;
    // Samples covered before the depth test, counted by the reference; none where it did not render.
    std::optional<std::uint64_t> fragments;
};

// Engines: "reference", the fast path's precision modes by name, "llvmpipe".
struct SpeedRow {
    std::string scene, engine;
    int threads = 1;
    double median = 0, min = 0, max = 0;  // seconds per render
    std::size_t runs = 0;
    double triangles_per_second = 0, samples_per_second = 0;  // from the median
};

struct ErrorRow {
    std::string scene, engine;
    std::uint64_t samples = 0;  // samples in the framebuffer
    // From each triangle's covered samples; llvmpipe gives only its framebuffer, so none there.
    std::optional<std::uint64_t> misclassified, triangles_affected;
    std::uint64_t ids_differing = 0;
    // Depths bit for bit, and the largest |z - z_reference| where both hold the same triangle; none for a
    // plugin, which returns ids alone.
    std::optional<std::uint64_t> depths_differing;
    std::optional<double> worst_depth_error;
    std::optional<std::uint64_t> watertight_violations;  // scenes with shared edges only
};

struct AaRow {
    std::string scene;
    PatternError error;
};

struct VisibleAaRow {
    std::string scene;
    VisibleError error;
};

// What the exact visible area cost on one scene.
struct VisibleCostRow {
    std::string scene;
    Viewport viewport;
    std::size_t triangles = 0;
    reference::VisibleStats stats;
    unsigned threads = 0;
    double seconds = 0;  // wall time of one reference::visible_area
};

// Lines: one engine on one set of segments, timed over the whole set, and its pixels against the
// reference's for the same (unsnapped) segments.
struct LineRow {
    std::string scene, engine;
    std::size_t segments = 0;
    double median = 0, min = 0, max = 0;  // seconds per pass over every segment
    std::size_t runs = 0;
    std::uint64_t pixels = 0;             // lit by the reference
    std::uint64_t differing = 0;          // lit by one of the two only
    std::uint64_t segments_affected = 0;  // segments with a differing pixel
};

struct Report {
    Machine machine;
    std::string command;
    bool quick = false;
    std::vector<SceneInfo> scenes;     // the speed and error scenes
    std::vector<SpeedRow> speed;
    std::vector<ErrorRow> errors;
    std::vector<SceneInfo> hard_families;
    std::vector<ErrorRow> hard_cases;  // scene = family
    std::vector<SceneInfo> aa_scenes;
    std::vector<AaRow> aa;
    std::vector<std::pair<int, Discrepancy>> discrepancy;  // per sample count
    std::vector<VisibleAaRow> visible_aa;                  // z-buffered: against the exact visible area
    std::vector<VisibleCostRow> visible_cost;
    std::vector<LineRow> lines;
    std::vector<std::string> notes;    // what was skipped, and why
};

std::string format_table(const Report& report);  // Markdown tables, also what stdout shows
std::string format_json(const Report& report);
// Log-log: x the median triangles per second on one thread, y the fraction of samples whose id differs
// from the reference; one labelled point per engine and scene, exact ones on a separate "0" row.
std::string format_svg(const Report& report);
// Log-log: x samples per pixel, y the mean per-pixel error; per scene, against the exact visible area
// (solid) and, where measured, the depth-ignoring per-triangle area error (dashed).
std::string format_aa_svg(const Report& report);

}  // namespace rast::bench
