#include "engine_error.h"

#include <rast/reference.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>

namespace rast::bench {
namespace {

// The sign of twice the signed area, exactly.
int orientation(const Triangle& t) {
    using reference::Rational;
    const Vertex &a = t.v[0], &b = t.v[1], &c = t.v[2];
    const Rational cross = (Rational(b.x) - a.x) * (Rational(c.y) - a.y) - (Rational(b.y) - a.y) * (Rational(c.x) - a.x);
    return cross.sign();
}

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

std::vector<CoverageDifference> compare_coverage(const Scene& scene, std::span<const fast::Precision> modes,
                                                 bool watertight) {
    const Viewport vp = scene.viewport;
    const int n = scene.samples;
    const std::size_t total = static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height) *
                              static_cast<std::size_t>(n);
    std::vector<CoverageDifference> result(modes.size());
    std::vector<std::vector<std::int32_t>> winding, expected;
    if (watertight) {
        winding.assign(modes.size(), std::vector<std::int32_t>(total, 0));
        expected = winding;
    }
    for (const Triangle& t : scene.triangles) {
        const std::vector<std::size_t> exact = reference::covered_samples(t, vp, n);
        for (std::size_t m = 0; m < modes.size(); ++m) {
            const std::vector<std::size_t> got = fast::covered_samples(t, vp, n, modes[m]);
            const std::uint64_t differing = symmetric_difference(got, exact);
            result[m].samples += differing;
            result[m].triangles += differing > 0 ? 1 : 0;
            if (!watertight) continue;
            const Triangle geometry = fast::snap(t, modes[m]);
            // A triangle that snapping flattens keeps its input's sign, so that anything the mode
            // still covers with it shows up.
            const int sign = orientation(geometry) != 0 ? orientation(geometry) : orientation(t);
            add_winding(winding[m], got, sign);
            add_winding(expected[m], geometry == t ? exact : reference::covered_samples(geometry, vp, n), sign);
        }
    }
    for (std::size_t m = 0; m < modes.size() && watertight; ++m) {
        std::uint64_t violations = 0;
        for (std::size_t k = 0; k < total; ++k) violations += winding[m][k] != expected[m][k] ? 1 : 0;
        result[m].watertight = violations;
    }
    return result;
}

}  // namespace rast::bench
