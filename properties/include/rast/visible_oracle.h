// rast properties — the judge of the exact visible area (rast/visible_area.h), written independently of
// the reference's cutting: Cavalieri's principle on vertical slabs; and what bounds supersampling's error
// against it: the cells of a pixel that the boundaries of its visible regions meet.
#pragma once

#include <rast/exact_geometry.h>
#include <rast/scene.h>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace rast::properties {

struct SlabPixel {
    std::vector<std::pair<std::size_t, Rational>> visible;  // (id, area), ids ascending, no zero areas
    Rational covered;                                       // the area of the union of the triangles
};

// Pixel square (i, j) of `scene`. Every line that can bound a visible region (the triangles' edges, the
// pixel's top and bottom, the line where two triangles' planes meet) is drawn, and the square is cut at
// the x of every crossing of two of them inside it (its top and bottom included). Between two such x no two lines cross, so along a
// vertical line the triangles' sections and their depth order keep their combinatorics: each triangle's
// visible length is linear in x there, and its value at the slab's middle times the slab's width is
// that slab's exact area. Depth planes come from the vertices' cross product, not from edge functions.
SlabPixel visible_by_slabs(const Scene& scene, int i, int j);

// The number of cells of `pixel` (a grid of `columns` x `rows` closed rectangles tiling pixel square
// (i, j)) that meet a boundary where the visible owner can change: an edge of a triangle, or the segment
// of two triangles' overlap along which their depths are equal.
int cells_met_by_boundaries(const Scene& scene, int i, int j, int columns, int rows);

// The grid of cells, columns x rows, that gives each sample of the pattern a closed cell of its own (a
// test finds the matching): 1x1, 2x2, 4x2 and 2x8 for 1, 4, 8 and 16 samples.
//
// Why it bounds the error: say each sample s has its cell C_s of area 1/N. A cell that no boundary meets
// lies inside one owner's region with its sample, so it adds the same to that owner's sample fraction
// and its area; any other cell moves at most 1/N of each. So the total variation distance between the
// sample fractions and the visible areas (over the owners and "nothing"), which is the largest error
// the resolved colour can have for colours in [0, 1], is at most (cells met) / N. The boundaries counted
// are those of the triangles whose box meets the open pixel square. A triangle that only touches the
// square from outside can own none of its samples: the samples on the square's border (16x only) lie on
// its left and top sides, where such a triangle has a right or bottom edge, which the tie rule leaves.
std::pair<int, int> sample_cells(int samples);

// The triangle that holds all of the closed pixel square (i, j) and is in front of every other triangle
// near it, if there is one: it owns the whole pixel. In front: its depth is at most the other's at all
// four corners (the difference is affine, so then everywhere), and where the two are equal at all four,
// its id is the lower.
std::optional<std::size_t> front_cover(const Scene& scene, int i, int j);

}  // namespace rast::properties
