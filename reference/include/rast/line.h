// rast — lines, exactly: the diamond-exit rule of Direct3D 11 and OpenGL (docs/design.md).
//
// Pixel (i, j) has the diamond |x - (i + 1/2)| + |y - (j + 1/2)| < 1/2, with part of its boundary: the two
// lower edges and the bottom corner (y up, so "lower" is as the written image shows it), and for a
// y-major segment (|dy| > |dx|) the right corner too. A segment lights the pixel when, travelling from its
// start to its end, it leaves that diamond: it meets the diamond and its end is not in it. Every
// decision is an exact orientation predicate (CGAL) on the input doubles.
#pragma once

#include <rast/reference.h>
#include <rast/scene.h>

#include <cstddef>
#include <vector>

namespace rast::reference {

// Whether `s` lights pixel (i, j). A segment of zero length lights nothing.
bool lights(const Segment& s, int i, int j);

// The pixels of the viewport that `s` lights, as pixel indices j * width + i, ascending.
std::vector<std::size_t> lit_pixels(const Segment& s, Viewport vp);

// The exact depth of `s` at pixel (i, j): z interpolated along the segment at its point nearest the
// pixel centre (i + 1/2, j + 1/2), an end where the centre lies beyond it. In a framebuffer every sample
// of a pixel a line lights takes that one depth. The start's z for a segment of zero length.
Rational line_depth(const Segment& s, int i, int j);

}  // namespace rast::reference
