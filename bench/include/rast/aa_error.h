// rast — how far each sample pattern is from the ideal antialiasing: the exact area of a triangle inside
// each pixel square (the box filter), against the fraction of the pixel's samples the triangle covers;
// and, with depth, the exact visible area against the resolved samples of the z-buffer.
#pragma once

#include <rast/scene.h>
#include <rast/visible_area.h>

#include <cstddef>
#include <span>
#include <vector>

namespace rast::bench {

// Per-pixel coverage error |covered samples / n - exact area| of a scene's triangles, each taken on its
// own: summing over overlapping triangles would need clamping, which hides error. Pixels counted are
// those a triangle touches (positive area inside the square, or at least one covered sample).
struct PatternError {
    int samples = 0;
    std::size_t pixels = 0;  // (triangle, pixel) pairs
    double mean = 0;
    double worst = 0;
};

// One PatternError per sample count in `sample_counts` (each 1, 4, 8 or 16, else std::invalid_argument),
// all from one pass: the area comes from rast::reference::pixel_area, the samples from
// reference::covers, both exact; each pixel's error is exact, rounded once to double. Pixels outside
// the viewport do not count.
std::vector<PatternError> pattern_errors(const Scene& scene, std::span<const int> sample_counts);

// The resolved image against the exact visible area (rast/visible_area.h) of a z-buffered scene: per
// pixel, reference::resolve_error between the reference's samples and the visible areas, the largest
// error the resolved colour can have for colours in [0, 1]. Pixels counted: those where something is
// seen or some sample covered. One entry per sample count, each rendered by the reference.
struct VisibleError {
    int samples = 0;
    std::size_t pixels = 0;
    double mean = 0;
    double worst = 0;
};
std::vector<VisibleError> visible_errors(const Scene& scene, const reference::VisibleArea& visible,
                                         std::span<const int> sample_counts);

// The error of one triangle at one pixel: (covered samples of pixel (i, j)) / n - pixel_area, signed.
double pixel_coverage_error(const Triangle& t, int i, int j, int samples);

// The halfplane discrepancy of a sample pattern: the largest |area(H ∩ square) - (samples in H) / n| over
// every half-plane H, the measure Direct3D used to choose its standard patterns.
//
// Method. For a fixed normal direction the area grows continuously with the offset of the line while the
// sample fraction is a step function, so the extremes lie at lines through a sample, approached from
// either side (the sample excluded or included). The sample fraction changes with the direction only
// where the line runs through two samples, so those directions are evaluated exactly (normals with
// exact components, so collinear samples tie exactly), and `directions` evenly spaced directions
// cover the rest of the half-turn. Rotating a line about a sample changes the area inside the unit
// square by at most 1 per radian, so the result is below the true discrepancy by at most `resolution`
// (half the spacing, in radians).
struct Discrepancy {
    double value = 0;
    double normal_x = 0, normal_y = 0;  // the worst half-plane: normal . p <= offset
    double offset = 0;
    double resolution = 0;
};
Discrepancy halfplane_discrepancy(std::span<const SamplePoint> pattern, int directions = 1 << 16);

// The area of {p in [0, 1]^2 : n . p <= c}; exposed for the tests.
double square_area_below(double nx, double ny, double c);

}  // namespace rast::bench
