// The antialiasing report as an SVG plot: the mean per-pixel error against samples per pixel, both on
// log scales, one colour per scene; solid against the exact visible area, dashed for the depth-ignoring
// error of each triangle's own area.
#include <rast/bench_report.h>

#include "svg.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace rast::bench {
namespace {

using namespace svg;

constexpr double kLeft = 90, kRight = 560, kTop = 40, kBottom = 420, kWidth = 800, kHeight = 480;
constexpr int kSampleCounts[] = {1, 4, 8, 16};

struct Series {
    std::string scene;
    bool visible;  // else depth-ignoring
    std::vector<std::pair<int, double>> points;  // (samples, mean error)
};

}  // namespace

std::string format_aa_svg(const Report& report) {
    std::vector<std::string> scenes;
    const auto scene_index = [&](const std::string& name) {
        const auto it = std::find(scenes.begin(), scenes.end(), name);
        if (it != scenes.end()) return static_cast<std::size_t>(it - scenes.begin());
        scenes.push_back(name);
        return scenes.size() - 1;
    };
    std::vector<Series> series;
    const auto add = [&](const std::string& scene, bool visible, int samples, double mean) {
        scene_index(scene);
        auto it = std::find_if(series.begin(), series.end(),
                               [&](const Series& s) { return s.scene == scene && s.visible == visible; });
        if (it == series.end()) it = series.insert(series.end(), Series{scene, visible, {}});
        it->points.emplace_back(samples, mean);
    };
    for (const VisibleAaRow& r : report.visible_aa) add(r.scene, true, r.error.samples, r.error.mean);
    for (const AaRow& r : report.aa) add(r.scene, false, r.error.samples, r.error.mean);

    double y_lo = std::numeric_limits<double>::infinity(), y_hi = -y_lo;
    for (const Series& s : series)
        for (const auto& [n, mean] : s.points)
            if (mean > 0) {
                y_lo = std::min(y_lo, std::floor(std::log10(mean)));
                y_hi = std::max(y_hi, std::ceil(std::log10(mean)));
            }
    if (!(y_lo < y_hi)) y_lo = -3, y_hi = 0;
    const auto lx = [](int samples) { return kLeft + std::log2(samples) / 4 * (kRight - kLeft); };
    const auto ly = [&](double l) { return kBottom - (l - y_lo) / (y_hi - y_lo) * (kBottom - kTop); };

    std::string out = open(kWidth, kHeight);
    for (const int n : kSampleCounts)
        out += line(lx(n), kTop, lx(n), kBottom, "#ddd") + text(lx(n), kBottom + 18, std::to_string(n),
                                                                 "text-anchor=\"middle\"");
    for (double e = y_lo; e <= y_hi; ++e)
        out += line(kLeft, ly(e), kRight, ly(e), "#ddd") + text(kLeft - 6, ly(e) + 4, power_of_ten(e),
                                                                 "text-anchor=\"end\"");
    out += text((kLeft + kRight) / 2, kHeight - 20, "samples per pixel (log)", "text-anchor=\"middle\"");
    out += text(16, (kTop + kBottom) / 2, "mean per-pixel error (log)",
                "text-anchor=\"middle\" transform=\"rotate(-90 16 " + num((kTop + kBottom) / 2) + ")\"");
    for (const Series& s : series) {
        const std::string colour = kColours[scene_index(s.scene) % kColours.size()];
        const std::string dash = s.visible ? "" : "stroke-dasharray=\"5 4\"";
        for (std::size_t k = 0; k < s.points.size(); ++k) {
            const auto& [n, mean] = s.points[k];
            if (mean <= 0) continue;
            const double x = lx(n), y = ly(std::log10(mean));
            out += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"3\" fill=\"" + colour + "\"/>\n";
            if (k > 0 && s.points[k - 1].second > 0)
                out += line(lx(s.points[k - 1].first), ly(std::log10(s.points[k - 1].second)), x, y, colour,
                            "stroke-width=\"1.5\" " + dash);
        }
    }
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const double y = kTop + 18.0 * static_cast<double>(k);
        const std::string colour = kColours[k % kColours.size()];
        out += line(kRight + 20, y, kRight + 44, y, colour, "stroke-width=\"2\"") + text(kRight + 50, y + 4, scenes[k]);
    }
    const double legend = kTop + 18.0 * static_cast<double>(scenes.size()) + 12;
    out += line(kRight + 20, legend, kRight + 44, legend, "black") +
           text(kRight + 50, legend + 4, "against the exact visible area");
    out += line(kRight + 20, legend + 18, kRight + 44, legend + 18, "black", "stroke-dasharray=\"5 4\"") +
           text(kRight + 50, legend + 22, "each triangle's own area, depth ignored");
    return out + "</svg>\n";
}

}  // namespace rast::bench
