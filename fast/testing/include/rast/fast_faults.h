// rast — the fast rasterizer with one deliberate, realistic bug injected, so that the property tests can
// show that each property detects the bug it is meant to. Internal: not installed, not for users.
// The library itself is the Fault::none instantiation of the same templates and pays nothing for this.
#pragma once

#include <rast/fast.h>

#include <cstddef>
#include <vector>

namespace rast::fast {

enum class Fault {
    none,
    wrong_tie_bias,            // bottom instead of top edges own their samples
    integer_sample_positions,  // samples at (i, j) + pattern - 1/2, i.e. the centre at (i, j)
    depth_less_equal,          // a depth test the filter cannot settle is a plain <= on the double depths
    no_id_tiebreak,            // equal exact depths: the last drawn triangle wins instead of the lower id
    bbox_one_short,            // the bounding box misses its last column and row of pixels
    float_row_accumulation,    // float modes: the edge function stepped along a row by repeated addition
    halved_depth_bound,        // every depth plane's error bound halved (docs/filters.md)
    halved_float_margin,       // float modes: the whole-tile test's margin halved (docs/filters.md)
};

Framebuffer render_with_fault(const Scene& scene, const Options& options, Fault fault);

std::vector<std::size_t> covered_samples_with_fault(const Triangle& t, Viewport vp, int samples,
                                                    Precision precision, Fault fault);

}  // namespace rast::fast
