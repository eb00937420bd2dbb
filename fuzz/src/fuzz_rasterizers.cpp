// libFuzzer harness: both rasterizers fed fuzzed coordinates. Bytes decode to a scene of 1-4 triangles
// in a viewport of up to 16 or, straddling a tile border, 57..72 pixels a side (scene_bytes.h), with coordinates from +-0 and subnormals to
// +-DBL_MAX. Oracles, besides no crash, no UB, no hang and no exception other than those named:
//   - a non-finite coordinate: every engine throws std::invalid_argument naming the first bad triangle;
//   - fixed4 / fixed8 / fixed16: the id buffer equals the reference's on the snapped scene (fast::snap);
//   - float32 / float64: per triangle, a sample the fast path classifies differently from the reference
//     lies within edge_error_bound of one of the triangle's edges (exact edge function, in rationals);
//     and on every sample where no triangle is so disputed, the id equals the reference's;
//   - every fast mode: an id names a triangle whose fast coverage holds the sample, and -1 only where no
//     triangle's fast coverage does (the z-buffer loses no fragment and invents none).
#include "scene_bytes.h"

#include <rast/fast.h>
#include <rast/reference.h>

#include <algorithm>
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

using rast::Framebuffer;
using rast::Scene;
using rast::Triangle;
using rast::fast::Precision;
using rast::reference::Rational;

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

// Whether sample p is within `bound` of one of t's edges: |(b - a) x (p - a)| <= bound, exactly.
bool near_an_edge(const Triangle& t, SamplePosition p, double bound) {
    if (std::isinf(bound)) return true;
    const Rational limit(bound);
    for (int k = 0; k < 3; ++k) {
        const rast::Vertex &a = t.v[k], &b = t.v[(k + 1) % 3];
        const Rational e = (Rational(b.x) - Rational(a.x)) * (Rational(p.y) - Rational(a.y)) -
                           (Rational(b.y) - Rational(a.y)) * (Rational(p.x) - Rational(a.x));
        if (abs(e) <= limit) return true;
    }
    return false;
}

// Each triangle's covered samples (ascending framebuffer indices), in one engine.
using Coverages = std::vector<std::vector<std::size_t>>;

Coverages fast_coverages(const Scene& scene, Precision p) {
    Coverages out;
    for (const Triangle& t : scene.triangles)
        out.push_back(rast::fast::covered_samples(t, scene.viewport, scene.samples, p));
    return out;
}

// Every id names a triangle whose fast coverage holds the sample, and -1 only where none does. Per sample
// a bit set of the (at most kMaxTriangles) covering triangles: a vector per sample made the allocator,
// under ASan, most of the harness's time.
void check_z_buffer_consistency(const Scene& scene, Precision p, const Coverages& coverage, const Framebuffer& fb) {
    static_assert(rast::fuzz::kMaxTriangles <= 8);
    const std::size_t samples = static_cast<std::size_t>(scene.viewport.width) *
                                static_cast<std::size_t>(scene.viewport.height) *
                                static_cast<std::size_t>(scene.samples);
    if (fb.ids.size() != samples) finding(std::string(name(p)) + ": framebuffer of the wrong size");
    std::vector<std::uint8_t> owners(samples, 0);
    for (std::size_t id = 0; id < coverage.size(); ++id)
        for (std::size_t k : coverage[id]) {
            if (k >= samples) finding(std::string(name(p)) + ": covered_samples names a sample beyond the viewport");
            owners[k] |= static_cast<std::uint8_t>(1u << id);
        }
    for (std::size_t k = 0; k < samples; ++k) {
        const std::int32_t id = fb.ids[k];
        const bool named = id >= 0 && static_cast<std::size_t>(id) < coverage.size();
        const bool consistent = id == Framebuffer::kNoTriangle ? owners[k] == 0 : named && (owners[k] >> id & 1) != 0;
        if (!consistent)
            finding(std::string(name(p)) + ": sample " + std::to_string(k) + " holds id " +
                    std::to_string(fb.ids[k]) + ", which its coverage does not explain");
    }
}

void check_fixed(const Scene& scene, Precision p) {
    Scene snapped = scene;
    for (Triangle& t : snapped.triangles) t = rast::fast::snap(t, p);
    const Framebuffer expected = rast::reference::render(snapped);
    const Framebuffer got = rast::fast::render(scene, {p, 1});
    check_z_buffer_consistency(scene, p, fast_coverages(scene, p), got);
    for (std::size_t k = 0; k < expected.ids.size(); ++k)
        if (got.ids[k] != expected.ids[k])
            finding(std::string(name(p)) + ": sample " + std::to_string(k) + " is " + std::to_string(got.ids[k]) +
                    ", the reference on the snapped scene says " + std::to_string(expected.ids[k]));
}

// exact: the reference's coverage of each triangle, shared by both float modes.
void check_float(const Scene& scene, const Framebuffer& reference, const Coverages& exact, Precision p) {
    const Coverages fast = fast_coverages(scene, p);
    std::vector<bool> disputed(reference.ids.size(), false);
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) {
        const Triangle& t = scene.triangles[id];
        const double bound = rast::fast::edge_error_bound(t, p, scene.viewport);
        std::vector<std::size_t> differ;
        std::set_symmetric_difference(exact[id].begin(), exact[id].end(), fast[id].begin(), fast[id].end(),
                                      std::back_inserter(differ));
        for (std::size_t k : differ) {
            if (!near_an_edge(t, sample_position(scene, k), bound))
                finding(std::string(name(p)) + ": sample " + std::to_string(k) +
                        " is classified against the reference farther than edge_error_bound from every edge");
            disputed.at(k) = true;
        }
    }
    const Framebuffer got = rast::fast::render(scene, {p, 1});
    check_z_buffer_consistency(scene, p, fast, got);
    for (std::size_t k = 0; k < reference.ids.size(); ++k)
        if (!disputed[k] && got.ids[k] != reference.ids[k])
            finding(std::string(name(p)) + ": undisputed sample " + std::to_string(k) + " is " +
                    std::to_string(got.ids[k]) + ", the reference says " + std::to_string(reference.ids[k]));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const Scene scene = rast::fuzz::decode_scene(std::span(data, size));
    if (const auto bad = first_non_finite(scene)) {
        expect_rejected("reference", *bad, [&] { rast::reference::render(scene); });
        for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16, Precision::float32,
                            Precision::float64})
            expect_rejected(std::string(name(p)), *bad, [&] { rast::fast::render(scene, {p, 1}); });
        return 0;
    }
    const Framebuffer reference = rast::reference::render(scene);
    for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16}) check_fixed(scene, p);
    Coverages exact;
    for (const Triangle& t : scene.triangles)
        exact.push_back(rast::reference::covered_samples(t, scene.viewport, scene.samples));
    for (Precision p : {Precision::float32, Precision::float64}) check_float(scene, reference, exact, p);
    return 0;
}
