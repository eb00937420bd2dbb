// The error of any engine, and of any framebuffer, against the exact reference.
#pragma once

#include <rast/engine.h>
#include <rast/scene.h>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rast::bench {

struct BufferDifference {
    std::uint64_t ids = 0;     // samples whose triangle id differs
    std::uint64_t depths = 0;  // samples whose depth differs bit for bit
    double worst_depth = 0;    // the largest |depth difference| where both hold the same triangle
};

// `reference` is the reference's framebuffer: its depths are the exact depths rounded to nearest.
BufferDifference compare_buffers(const Framebuffer& reference, const Framebuffer& other);

struct CoverageDifference {
    std::uint64_t samples = 0;    // over all triangles, samples covered by the mode or the reference, not both
    std::uint64_t triangles = 0;  // triangles with at least one such sample
    // Samples whose winding count (counter-clockwise triangles covering the sample minus clockwise ones)
    // differs from the exact count of the geometry the mode rasterizes: the input, or for the fixed
    // modes its snapped triangles. On a consistently oriented mesh every crack and every double cover
    // along a shared edge changes that count; on a mesh with an open boundary, so does a misclassified
    // sample on the boundary.
    std::optional<std::uint64_t> watertight;
};

// Per triangle, each engine's covered_samples against the reference's, for each engine in order; the
// watertightness count only when `watertight` is set (it needs the reference on every snapped triangle).
std::vector<CoverageDifference> compare_coverage(const Scene& scene, std::span<const Engine> engines,
                                                 bool watertight);

}  // namespace rast::bench
