// The report as an SVG scatter plot of speed against error, written directly: one labelled point per
// engine and scene, x = median triangles/s on one thread, y = fraction of samples whose id differs from
// the reference, both on log scales. Error 0 has no logarithm, so exact points sit on their own row.
#include <rast/bench_report.h>

#include "svg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace rast::bench {
namespace {

using namespace svg;

// The exact points get a band below the log axis, one row per scene so that their labels do not collide.
constexpr double kLeft = 90, kRight = 760, kTop = 40, kBottom = 520, kZeroBand = 550, kZeroRowStep = 9,
                 kHeight = 680, kWidth = 1000;

struct Point {
    std::size_t scene;
    std::string engine;
    double speed, error;
};

}  // namespace

std::string format_svg(const Report& report) {
    std::vector<Point> points;
    for (std::size_t k = 0; k < report.scenes.size(); ++k) {
        const SceneInfo& scene = report.scenes[k];
        for (const SpeedRow& s : report.speed) {
            if (s.scene != scene.name || s.threads != 1) continue;
            double error = 0;  // the reference is the measure of error
            for (const ErrorRow& e : report.errors) {
                if (e.scene == s.scene && e.engine == s.engine)
                    error = static_cast<double>(e.ids_differing) / static_cast<double>(e.samples);
            }
            points.push_back({k, s.engine, s.triangles_per_second, error});
        }
    }
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
    for (const Point& p : points) {
        x_lo = std::min(x_lo, std::floor(std::log10(p.speed)));
        x_hi = std::max(x_hi, std::ceil(std::log10(p.speed)));
        if (p.error > 0) {
            y_lo = std::min(y_lo, std::floor(std::log10(p.error)));
            y_hi = std::max(y_hi, std::ceil(std::log10(p.error)));
        }
    }
    if (points.empty()) x_lo = 0, x_hi = 1;
    if (x_hi == x_lo) x_hi += 1;
    if (!(y_lo < y_hi)) y_lo = -6, y_hi = 0;
    // Screen positions of a decimal logarithm.
    const auto lx = [&](double l) { return kLeft + (l - x_lo) / (x_hi - x_lo) * (kRight - kLeft); };
    const auto ly = [&](double l) { return kBottom - (l - y_lo) / (y_hi - y_lo) * (kBottom - kTop); };

    std::string svg = open(kWidth, kHeight);
    for (double e = x_lo; e <= x_hi; ++e) {
        svg += line(lx(e), kTop, lx(e), kBottom, "#ddd") +
               text(lx(e), kHeight - 32, power_of_ten(e), "text-anchor=\"middle\"");
    }
    for (double e = y_lo; e <= y_hi; ++e) {
        svg += line(kLeft, ly(e), kRight, ly(e), "#ddd") +
               text(kLeft - 6, ly(e) + 4, power_of_ten(e), "text-anchor=\"end\"");
    }
    const double zero_band_end = kZeroBand + kZeroRowStep * static_cast<double>(report.scenes.size());
    svg += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(kZeroBand - 6) + "\" width=\"" + num(kRight - kLeft) +
           "\" height=\"" + num(zero_band_end - kZeroBand + 6) + "\" fill=\"#f4f4f4\"/>\n" +
           text(kLeft - 6, (kZeroBand + zero_band_end) / 2, "0 (exact)", "text-anchor=\"end\"");
    svg += text((kLeft + kRight) / 2, kHeight - 10, "median triangles per second, one thread (log)", "text-anchor=\"middle\"");
    svg += text(16, (kTop + kBottom) / 2, "fraction of samples whose id differs from the reference (log)",
                "text-anchor=\"middle\" transform=\"rotate(-90 16 " + num((kTop + kBottom) / 2) + ")\"");
    for (const Point& p : points) {
        const char* colour = kColours[p.scene % kColours.size()];
        const double x = lx(std::log10(p.speed));
        const double y = p.error == 0 ? kZeroBand + kZeroRowStep * static_cast<double>(p.scene) : ly(std::log10(p.error));
        svg += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"3.5\" fill=\"" + colour + "\"/>\n";
        svg += text(x + 5, y + 3, p.engine, "font-size=\"9\" fill=\"" + std::string(colour) + "\"");
    }
    for (std::size_t k = 0; k < report.scenes.size(); ++k) {
        const double y = kTop + 18.0 * static_cast<double>(k);
        const char* colour = kColours[k % kColours.size()];
        svg += "<circle cx=\"" + num(kRight + 30) + "\" cy=\"" + num(y) + "\" r=\"4\" fill=\"" + colour + "\"/>\n";
        svg += text(kRight + 40, y + 4, report.scenes[k].name);
    }
    return svg + "</svg>\n";
}

}  // namespace rast::bench
