// libFuzzer harness: both rasterizers fed fuzzed coordinates. Bytes decode to a scene of 1-4 triangles
// in a viewport of up to 16 or, straddling a tile border, 57..72 pixels a side (scene_bytes.h), with coordinates from +-0 and subnormals to
// +-DBL_MAX. Oracles, besides no crash, no UB, no hang and no exception other than those named:
//   - a non-finite coordinate: every engine throws std::invalid_argument naming the first bad triangle;
//   - fixed4 / fixed8 / fixed16: the id buffer equals the reference's on the snapped scene;
//   - float32 / float64: per triangle, a sample the fast path classifies differently from the reference
//     lies within edge_error_bound_at, there, of one of the triangle's edges (exact edge function, in
//     rationals); and on every sample where no triangle is so disputed, the id equals the reference's;
//   - every fast mode: an id names a triangle whose fast coverage holds the sample, and -1 only where no
//     triangle's fast coverage does (the z-buffer loses no fragment and invents none).
#include "scene_bytes.h"

#include <rast/engine.h>
#include <rast/exact_geometry.h>
#include <rast/properties.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using rast::Engine;
using rast::Framebuffer;
using rast::Scene;
using rast::Triangle;
using rast::properties::Rational;

[[noreturn]] void finding(const std::string& what) {
    std::cerr << "fuzz_rasterizers: " << what << '\n';
    std::abort();
}

std::optional<std::size_t> first_non_finite(const Scene& scene) {
    for (std::size_t id = 0; id < scene.triangles.size(); ++id)
        for (const rast::Vertex& v : scene.triangles[id].v)
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return id;
    return std::nullopt;
}

template <class Render>
void expect_rejected(const std::string& engine, std::size_t bad_id, Render render) {
    try {
        render();
    } catch (const std::invalid_argument& e) {
        if (std::string(e.what()).find("triangle " + std::to_string(bad_id)) == std::string::npos)
            finding(engine + ": the error does not name triangle " + std::to_string(bad_id) + ": " +
                    e.what());
        return;
    }
    finding(engine + ": a non-finite coordinate was rendered");
}

// The sample at framebuffer index k (Framebuffer::index inverted).
struct SamplePosition {
    double x, y;
};
SamplePosition sample_position(const Scene& scene, std::size_t k) {
    const auto n = static_cast<std::size_t>(scene.samples);
    const auto width = static_cast<std::size_t>(scene.viewport.width);
    const rast::SamplePoint offset = rast::sample_pattern(scene.samples)[k % n];
    return {static_cast<double>(k / n % width) + offset.x, static_cast<double>(k / n / width) + offset.y};
}

// Whether sample p is within the engine's bound there of one of t's edges: |(b - a) x (p - a)| <= bound,
// exactly.
bool near_an_edge(const Engine& engine, const Triangle& t, SamplePosition p) {
    const std::array<double, 3> bound = engine.edge_error_bound_at(t, p.x, p.y);
    for (int k = 0; k < 3; ++k) {
        if (std::isinf(bound[k])) return true;
        if (abs(rast::properties::edge_function(t.v[k], t.v[(k + 1) % 3], p.x, p.y)) <= Rational(bound[k]))
            return true;
    }
    return false;
}

// Each triangle's covered samples (ascending framebuffer indices), in one engine.
using Coverages = std::vector<std::vector<std::size_t>>;

Coverages coverages(const Scene& scene, const Engine& engine) {
    Coverages out;
    for (const Triangle& t : scene.triangles) out.push_back(engine.covered_samples(t, scene.viewport, scene.samples));
    return out;
}

// Every id names a triangle whose fast coverage holds the sample, and -1 only where none does. Per sample
// a bit set of the (at most kMaxTriangles) covering triangles: a vector per sample made the allocator,
// under ASan, most of the harness's time.
void check_z_buffer_consistency(const Scene& scene, const Engine& engine, const Coverages& coverage,
                                const Framebuffer& fb) {
    static_assert(rast::fuzz::kMaxTriangles <= 8);
    const std::size_t samples = static_cast<std::size_t>(scene.viewport.width) *
                                static_cast<std::size_t>(scene.viewport.height) *
                                static_cast<std::size_t>(scene.samples);
    if (fb.ids.size() != samples) finding(engine.name + ": framebuffer of the wrong size");
    std::vector<std::uint8_t> owners(samples, 0);
    for (std::size_t id = 0; id < coverage.size(); ++id)
        for (std::size_t k : coverage[id]) {
            if (k >= samples) finding(engine.name + ": covered_samples names a sample beyond the viewport");
            owners[k] |= static_cast<std::uint8_t>(1u << id);
        }
    for (std::size_t k = 0; k < samples; ++k) {
        const std::int32_t id = fb.ids[k];
        const bool named = id >= 0 && static_cast<std::size_t>(id) < coverage.size();
        const bool consistent = id == Framebuffer::kNoTriangle ? owners[k] == 0 : named && (owners[k] >> id & 1) != 0;
        if (!consistent)
            finding(engine.name + ": sample " + std::to_string(k) + " holds id " +
                    std::to_string(fb.ids[k]) + ", which its coverage does not explain");
    }
}

void check_fixed(const Scene& scene, const Engine& reference, const Engine& engine) {
    const Framebuffer expected = reference.render(rast::properties::rasterized_geometry(engine, scene));
    const Framebuffer got = engine.render(scene);
    check_z_buffer_consistency(scene, engine, coverages(scene, engine), got);
    for (std::size_t k = 0; k < expected.ids.size(); ++k)
        if (got.ids[k] != expected.ids[k])
            finding(engine.name + ": sample " + std::to_string(k) + " is " + std::to_string(got.ids[k]) +
                    ", the reference on the snapped scene says " + std::to_string(expected.ids[k]));
}

// exact: the reference's coverage of each triangle, shared by both float modes.
void check_float(const Scene& scene, const Framebuffer& reference, const Coverages& exact, const Engine& engine) {
    const Coverages fast = coverages(scene, engine);
    std::vector<bool> disputed(reference.ids.size(), false);
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) {
        const Triangle& t = scene.triangles[id];
        std::vector<std::size_t> differ;
        std::set_symmetric_difference(exact[id].begin(), exact[id].end(), fast[id].begin(), fast[id].end(),
                                      std::back_inserter(differ));
        for (std::size_t k : differ) {
            if (!near_an_edge(engine, t, sample_position(scene, k)))
                finding(engine.name + ": sample " + std::to_string(k) +
                        " is classified against the reference farther than edge_error_bound_at from every edge");
            disputed.at(k) = true;
        }
    }
    const Framebuffer got = engine.render(scene);
    check_z_buffer_consistency(scene, engine, fast, got);
    for (std::size_t k = 0; k < reference.ids.size(); ++k)
        if (!disputed[k] && got.ids[k] != reference.ids[k])
            finding(engine.name + ": undisputed sample " + std::to_string(k) + " is " + std::to_string(got.ids[k]) +
                    ", the reference says " + std::to_string(reference.ids[k]));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::vector<Engine> engines = rast::all_engines();  // the reference first
    const Engine& reference = engines.front();
    const Scene scene = rast::fuzz::decode_scene(std::span(data, size));
    if (const auto bad = first_non_finite(scene)) {
        for (const Engine& engine : engines) expect_rejected(engine.name, *bad, [&] { engine.render(scene); });
        return 0;
    }
    const Framebuffer exact_ids = reference.render(scene);
    Coverages exact;
    for (const Engine& engine : engines) {
        if (engine.is_reference()) continue;
        if (engine.exact()) {
            check_fixed(scene, reference, engine);
            continue;
        }
        if (exact.empty()) exact = coverages(scene, reference);
        check_float(scene, exact_ids, exact, engine);
    }
    return 0;
}
