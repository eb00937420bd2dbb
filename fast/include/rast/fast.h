// rast — the fast rasterizer, as a library.
//
// Same conventions as the exact reference (shared/DESIGN.md): y up, pixel centres at (i + 1/2, j + 1/2),
// the top-left tie rule, the (z, id) depth order. Where it departs from the reference is the precision
// mode, chosen per call:
//   fixed4 / fixed8 / fixed16: vertices snapped to a 1/2^N pixel grid (round to nearest, ties to even),
//     then exact integer edge functions: bit-identical to the reference on already snapped vertices.
//   float32 / float64: edge functions in floating point, within edge_error_bound() of the exact edge.
#pragma once

#include <rast/scene.h>

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace rast::fast {

enum class Precision { fixed4, fixed8, fixed16, float32, float64 };

struct Options {
    Precision precision = Precision::fixed8;
    int threads = 1;  // 0: all hardware threads. The result is identical for every count.
};

std::string_view name(Precision p);
std::optional<Precision> parse_precision(std::string_view s);

// Rasterizes the scene with the z-buffer's (z, id) order.
Framebuffer render(const Scene& scene, const Options& options = {});

// The framebuffer indices (Framebuffer::index) of every sample that `t` covers, ascending; no depth test.
std::vector<std::size_t> covered_samples(const Triangle& t, Viewport vp, int samples,
                                         Precision precision = Precision::fixed8);

}  // namespace rast::fast
