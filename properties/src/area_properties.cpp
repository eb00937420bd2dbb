// area_tiling: the exact box-filtered coverage of a tiled region, and what it implies for the samples.
#include <rast/reference.h>

#include <algorithm>
#include <cmath>

#include "checks.h"
#include <rast/exact_geometry.h>
#include "samples.h"

namespace rast::properties {

namespace {

// Beyond this many pixels a triangle's area is not summed pixel by pixel (exact clipping is slow).
constexpr double kMaxSummedPixels = 4096;

// The pixels a triangle's bounding box meets, unclipped; none when the box is too large to sum.
std::optional<PixelRange> summable_pixels(const Triangle& t) {
    const auto [x0, x1] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [y0, y1] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    const double fx0 = std::floor(x0), fy0 = std::floor(y0), cx1 = std::ceil(x1), cy1 = std::ceil(y1);
    if ((cx1 - fx0) * (cy1 - fy0) > kMaxSummedPixels) return std::nullopt;
    return PixelRange{static_cast<int>(fx0), static_cast<int>(std::max(fx0, cx1 - 1)), static_cast<int>(fy0),
                      static_cast<int>(std::max(fy0, cy1 - 1))};
}

bool strictly_inside_pixel(const SamplePoint& p) { return p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1; }

}  // namespace

// For a tiled region (triangles meeting only along edges and vertices): the exact areas a triangle
// leaves in the pixels sum to its area, and the triangles' areas in a pixel sum to the pixel's covered
// area; no pixel is covered more than once over; a pixel covered entirely has every sample inside it
// covered, and a pixel not covered at all has none of them covered.
Outcome area_tiling(const Scene& scene, const Engine& engine) {
    const Scene geometry = rasterized_geometry(engine, scene);
    if (auto folded = folded_by_snapping(scene, geometry, engine)) return *folded;
    const Viewport vp = scene.viewport;
    const auto pixel_index = [&](int i, int j) {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) + static_cast<std::size_t>(i);
    };
    // The per-pixel sums are complete only if every triangle could be summed.
    std::vector<Rational> summed(static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height));
    bool all_summed = true;
    for (std::size_t k = 0; k < geometry.triangles.size(); ++k) {
        const Triangle& t = geometry.triangles[k];
        const auto pixels = summable_pixels(t);
        all_summed = all_summed && pixels;
        if (!pixels) continue;
        Rational sum = 0;
        for (int j = pixels->j0; j <= pixels->j1; ++j)
            for (int i = pixels->i0; i <= pixels->i1; ++i) {
                const Rational a = reference::pixel_area(t, i, j);
                sum += a;
                if (i >= 0 && i < vp.width && j >= 0 && j < vp.height) summed[pixel_index(i, j)] += a;
            }
        if (2 * sum != twice_area(t))
            return Outcome::fail("triangle " + describe(t, k) + ": its pixel areas sum to " + sum.str() +
                                 ", its area is " + Rational(twice_area(t) / 2).str());
    }

    const auto pattern = sample_pattern(scene.samples);
    const auto area = reference::coverage_area(geometry);
    const Framebuffer image = engine.render(scene);
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            const Rational& a = area[pixel_index(i, j)];
            const std::string pixel = "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ")";
            if (all_summed && a != summed[pixel_index(i, j)])
                return Outcome::fail(pixel + ": covered area " + a.str() + ", yet the triangles' areas in it sum to " +
                                     summed[pixel_index(i, j)].str());
            if (a > 1) return Outcome::fail(pixel + ": covered area " + a.str() + " exceeds 1: the triangles overlap");
            if (a != 0 && a != 1) continue;
            for (int s = 0; s < scene.samples; ++s) {
                if (!strictly_inside_pixel(pattern[s])) continue;
                const bool covered = image.id(i, j, s) != Framebuffer::kNoTriangle;
                if (covered != (a == 1))
                    return Outcome::fail(describe(Sample{i, j, s, i + pattern[s].x, j + pattern[s].y,
                                                         image.index(i, j, s)}) +
                                         ": the pixel's covered area is " + a.str() + ", yet " + engine.name +
                                         (covered ? " covers" : " does not cover") + " the sample");
            }
        }
    return Outcome::pass();
}

}  // namespace rast::properties
