// Sample patterns against the exact area coverage; see aa_error.h.
#include <rast/aa_error.h>

#include <rast/reference.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace rast::bench {
namespace {

using reference::Rational;

// The error of `t` at pixel (i, j) for one pattern, given the exact area there; `touched` is false where
// the triangle neither covers a sample nor has area in the square.
struct PixelError {
    Rational error;
    bool touched;
};

PixelError error_at(const Triangle& t, int i, int j, std::span<const SamplePoint> pattern, const Rational& area) {
    int covered = 0;
    for (const SamplePoint& s : pattern) covered += reference::covers(t, i + s.x, j + s.y) ? 1 : 0;
    return {Rational(covered, static_cast<int>(pattern.size())) - area, covered > 0 || area > 0};
}

// The pixel index range [lo, hi] that the interval [a, b] of screen coordinates touches, clipped to
// [0, size - 1]; empty (hi < lo) outside. A sample can sit on the pixel's lower border (x = 0 in the 16x
// pattern), so the pixel whose lower border is b counts.
std::pair<int, int> pixel_span(double a, double b, int size) {
    const double lo = std::clamp(std::floor(a), 0.0, static_cast<double>(size));
    const double hi = std::clamp(std::floor(b), -1.0, static_cast<double>(size - 1));
    return {static_cast<int>(lo), static_cast<int>(hi)};
}

// Sutherland–Hodgman of the unit square against n . p <= c, then the shoelace formula.
double clipped_square_area(double nx, double ny, double c) {
    constexpr std::array<std::array<double, 2>, 4> square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
    std::vector<std::array<double, 2>> kept;
    for (std::size_t k = 0; k < square.size(); ++k) {
        const auto& p = square[k];
        const auto& q = square[(k + 1) % square.size()];
        const double fp = nx * p[0] + ny * p[1] - c, fq = nx * q[0] + ny * q[1] - c;
        if (fp <= 0) kept.push_back(p);
        if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
            const double s = fp / (fp - fq);
            kept.push_back({p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])});
        }
    }
    double twice = 0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const auto& p = kept[k];
        const auto& q = kept[(k + 1) % kept.size()];
        twice += p[0] * q[1] - q[0] * p[1];
    }
    return twice / 2;
}

constexpr double kRounding = 0x1p-40;

// The worst half-plane with this normal: lines through each sample, that sample (and any other on the
// same line) excluded or included.
void worst_for_normal(std::span<const SamplePoint> pattern, double nx, double ny, Discrepancy& best) {
    const double n = static_cast<double>(pattern.size());
    for (const SamplePoint& s : pattern) {
        const double c = nx * s.x + ny * s.y;
        int below = 0, on = 0;
        for (const SamplePoint& o : pattern) {
            const double d = nx * o.x + ny * o.y;
            below += d < c ? 1 : 0;
            on += d == c ? 1 : 0;
        }
        const double area = clipped_square_area(nx, ny, c);
        const double worst = std::max(std::abs(area - below / n), std::abs(area - (below + on) / n));
        // The areas of the dense directions carry rounding (a few ulps, far below the resolution): only
        // a clearly larger value displaces one found earlier, so an exact value at a critical direction
        // or an axis stands as it was computed.
        if (worst > best.value + kRounding) {
            best.value = worst;
            best.normal_x = nx;
            best.normal_y = ny;
            best.offset = c;
        }
    }
}

}  // namespace

double square_area_below(double nx, double ny, double c) { return clipped_square_area(nx, ny, c); }

double pixel_coverage_error(const Triangle& t, int i, int j, int samples) {
    return error_at(t, i, j, sample_pattern(samples), reference::pixel_area(t, i, j)).error.convert_to<double>();
}

std::vector<PatternError> pattern_errors(const Scene& scene, std::span<const int> sample_counts) {
    std::vector<PatternError> result;
    std::vector<std::span<const SamplePoint>> patterns;
    for (const int n : sample_counts) {
        patterns.push_back(sample_pattern(n));
        result.push_back({n, 0, 0, 0});
    }
    std::vector<double> sums(sample_counts.size(), 0);
    for (const Triangle& t : scene.triangles) {
        const auto [xmin, xmax] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
        const auto [ymin, ymax] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
        const auto [i0, i1] = pixel_span(xmin, xmax, scene.viewport.width);
        const auto [j0, j1] = pixel_span(ymin, ymax, scene.viewport.height);
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const Rational area = reference::pixel_area(t, i, j);
                for (std::size_t p = 0; p < result.size(); ++p) {
                    const PixelError e = error_at(t, i, j, patterns[p], area);
                    if (!e.touched) continue;
                    const double error = abs(e.error).convert_to<double>();
                    ++result[p].pixels;
                    sums[p] += error;
                    result[p].worst = std::max(result[p].worst, error);
                }
            }
        }
    }
    for (std::size_t p = 0; p < result.size(); ++p) {
        result[p].mean = result[p].pixels == 0 ? 0 : sums[p] / static_cast<double>(result[p].pixels);
    }
    return result;
}

Discrepancy halfplane_discrepancy(std::span<const SamplePoint> pattern, int directions) {
    Discrepancy best;
    // Directions through two samples, with exact normals: every coordinate is a multiple of 1/16.
    for (const SamplePoint& a : pattern) {
        for (const SamplePoint& b : pattern) {
            if (a.x != b.x || a.y != b.y) worst_for_normal(pattern, a.y - b.y, b.x - a.x, best);
        }
    }
    // A half-turn suffices: the opposite normal gives the complement, whose error is the same.
    const double step = std::numbers::pi / directions;
    for (int k = 0; k < directions; ++k) {
        worst_for_normal(pattern, std::cos(k * step), std::sin(k * step), best);
    }
    best.resolution = step / 2;
    return best;
}

}  // namespace rast::bench
