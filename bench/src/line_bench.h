// rast bench's lines section: the exact diamond-exit rule, Bresenham and the DDA on the same segments.
#pragma once

#include <rast/bench_report.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace rast::bench {

// One row per engine (reference, Bresenham at 1/256 pixel, DDA in float32 and float64), each timed over
// `runs` passes of every segment, one thread.
std::vector<LineRow> measure_lines(const std::string& scene, const std::vector<Segment>& segments, Viewport vp,
                                   std::size_t runs, std::ostream& progress);

}  // namespace rast::bench
