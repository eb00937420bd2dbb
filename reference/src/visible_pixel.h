// The exact visible area inside one pixel square: which part of the square each triangle owns under the
// z-buffer's (z, id) order, cut exactly.
//
// The square is kept as a map of convex regions, each owned by one triangle or by nothing. Triangles are
// inserted one at a time: a region is cut by the new triangle's three edge lines (the parts outside keep
// their owner) and what lies inside by the line where the two depth planes meet (each side to the nearer
// plane; coplanar, to the lower id). Every cut is exact in rationals, and a cut that would leave a part of
// zero area leaves none. The result does not depend on the insertion order (a test shuffles it); inserting
// front to back saves cuts, since a region whose owner is nearer at all its corners is left whole.
#pragma once

#include "rational_polygon.h"

#include <rast/reference.h>
#include <rast/visible_area.h>

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace rast::reference::detail {

// The affine function a x + b y + c.
struct Affine {
    Rational a, b, c;
    Rational at(const RationalPoint& p) const { return a * p.x + b * p.y + c; }
};

// A triangle of non-zero area, ready to cut pixels: its edge functions, each >= 0 on the closed triangle,
// and its depth plane z = depth(x, y).
struct Cutter {
    std::size_t id;
    std::array<Affine, 3> edges;
    Affine depth;
};

// None for a triangle of zero area. Precondition: finite coordinates.
std::optional<Cutter> make_cutter(const Triangle& t, std::size_t id);

// The visible area of each cutter in pixel square (i, j), ids ascending, zero areas omitted. `cutters`
// is the insertion order; ids must be distinct.
std::vector<VisiblePiece> visible_in_square(int i, int j, std::span<const Cutter* const> cutters);

}  // namespace rast::reference::detail
