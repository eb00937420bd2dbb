// The lines section of rast bench; see line_bench.h.
#include "line_bench.h"

#include "timing.h"

#include <rast/fast.h>
#include <rast/line.h>

#include <algorithm>
#include <functional>
#include <iterator>

namespace rast::bench {

namespace {

using Lit = std::function<std::vector<std::size_t>(const Segment&)>;

struct Contender {
    std::string name;
    Lit lit;
};

}  // namespace

std::vector<LineRow> measure_lines(const std::string& scene, const std::vector<Segment>& segments, Viewport vp,
                                   std::size_t runs, std::ostream& progress) {
    const std::vector<Contender> contenders{
        {"reference", [vp](const Segment& s) { return reference::lit_pixels(s, vp); }},
        {"bresenham 1/256", [vp](const Segment& s) { return fast::bresenham(s, vp, 8); }},
        {"dda float32", [vp](const Segment& s) { return fast::dda(s, vp, fast::Precision::float32); }},
        {"dda float64", [vp](const Segment& s) { return fast::dda(s, vp, fast::Precision::float64); }}};
    std::vector<std::vector<std::size_t>> exact;
    exact.reserve(segments.size());
    std::uint64_t pixels = 0;
    for (const Segment& s : segments) {
        exact.push_back(reference::lit_pixels(s, vp));
        pixels += exact.back().size();
    }
    std::vector<LineRow> rows;
    for (const Contender& c : contenders) {
        progress << "[lines] " << scene << ": " << c.name << '\n';
        LineRow row{scene, c.name, segments.size(), 0, 0, 0, 0, pixels, 0, 0};
        std::vector<double> seconds;
        // Each call returns a vector from another translation unit: nothing here can be optimized away.
        for (std::size_t r = 0; r < runs; ++r)
            seconds.push_back(seconds_of([&] {
                for (const Segment& s : segments) c.lit(s);
            }));
        const Spread t = spread(seconds);
        row.median = t.median;
        row.min = t.min;
        row.max = t.max;
        row.runs = t.runs;
        for (std::size_t k = 0; k < segments.size(); ++k) {
            const std::vector<std::size_t> mine = c.lit(segments[k]);
            std::vector<std::size_t> differ;
            std::set_symmetric_difference(mine.begin(), mine.end(), exact[k].begin(), exact[k].end(),
                                          std::back_inserter(differ));
            row.differing += differ.size();
            row.segments_affected += differ.empty() ? 0 : 1;
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace rast::bench
