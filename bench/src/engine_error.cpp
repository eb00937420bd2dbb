#include "engine_error.h"

#include <rast/exact_geometry.h>
#include <rast/properties.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>

namespace rast::bench {
namespace {

// |a \ b| + |b \ a| for ascending lists.
std::uint64_t symmetric_difference(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
    std::uint64_t count = 0;
    std::size_t ia = 0, ib = 0;
    while (ia < a.size() && ib < b.size()) {
        if (a[ia] == b[ib]) {
            ++ia, ++ib;
        } else {
            ++count;
            a[ia] < b[ib] ? ++ia : ++ib;
        }
    }
    return count + (a.size() - ia) + (b.size() - ib);
}

void add_winding(std::vector<std::int32_t>& winding, const std::vector<std::size_t>& covered, int sign) {
    for (const std::size_t index : covered) winding[index] += sign;
}

}  // namespace

BufferDifference compare_buffers(const Framebuffer& reference, const Framebuffer& other) {
    BufferDifference d;
    for (std::size_t k = 0; k < reference.ids.size(); ++k) {
        d.ids += reference.ids[k] != other.ids[k] ? 1 : 0;
        d.depths += std::bit_cast<std::uint64_t>(reference.depth[k]) != std::bit_cast<std::uint64_t>(other.depth[k])
                        ? 1
                        : 0;
        if (reference.ids[k] == other.ids[k] && reference.ids[k] != Framebuffer::kNoTriangle) {
            d.worst_depth = std::max(d.worst_depth, std::abs(reference.depth[k] - other.depth[k]));
        }
    }
    return d;
}

std::vector<CoverageDifference> compare_coverage(const Scene& scene, std::span<const Engine> engines,
                                                 bool watertight) {
    using properties::orientation;
    const Engine reference = reference_engine();
    const Viewport vp = scene.viewport;
    const int n = scene.samples;
    const std::size_t total = static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height) *
                              static_cast<std::size_t>(n);
    std::vector<CoverageDifference> result(engines.size());
    std::vector<std::vector<std::int32_t>> winding, expected;
    if (watertight) {
        winding.assign(engines.size(), std::vector<std::int32_t>(total, 0));
        expected = winding;
    }
    for (const Triangle& t : scene.triangles) {
        const std::vector<std::size_t> exact = reference.covered_samples(t, vp, n);
        for (std::size_t m = 0; m < engines.size(); ++m) {
            const std::vector<std::size_t> got = engines[m].covered_samples(t, vp, n);
            const std::uint64_t differing = symmetric_difference(got, exact);
            result[m].samples += differing;
            result[m].triangles += differing > 0 ? 1 : 0;
            if (!watertight) continue;
            const Triangle geometry = properties::rasterized_geometry(engines[m], t);
            // A triangle that snapping flattens keeps its input's sign, so that anything the mode
            // still covers with it shows up.
            const int sign = orientation(geometry) != 0 ? orientation(geometry) : orientation(t);
            add_winding(winding[m], got, sign);
            add_winding(expected[m], geometry == t ? exact : reference.covered_samples(geometry, vp, n), sign);
        }
    }
    for (std::size_t m = 0; m < engines.size() && watertight; ++m) {
        std::uint64_t violations = 0;
        for (std::size_t k = 0; k < total; ++k) violations += winding[m][k] != expected[m][k] ? 1 : 0;
        result[m].watertight = violations;
    }
    return result;
}

}  // namespace rast::bench
