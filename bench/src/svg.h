// The few SVG pieces the bench's plots are drawn with, written directly.
#pragma once

#include <array>
#include <cstdio>
#include <string>

namespace rast::bench::svg {

inline constexpr std::array<const char*, 8> kColours{"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                      "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

inline std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

inline std::string power_of_ten(double exponent) { return "1e" + std::to_string(static_cast<int>(exponent)); }

inline std::string text(double x, double y, const std::string& body, const std::string& extra = "") {
    return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\"" + (extra.empty() ? "" : " " + extra) + ">" + body +
           "</text>\n";
}

inline std::string line(double x0, double y0, double x1, double y1, const std::string& colour,
                        const std::string& extra = "") {
    return "<line x1=\"" + num(x0) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(x1) + "\" y2=\"" + num(y1) +
           "\" stroke=\"" + colour + "\"" + (extra.empty() ? "" : " " + extra) + "/>\n";
}

// The opening of a picture of width x height on a white ground.
inline std::string open(double width, double height) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + "\" height=\"" + num(height) +
           "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

}  // namespace rast::bench::svg
