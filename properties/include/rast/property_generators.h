// rast — RapidCheck generators of scenes that reach the hard cases of rasterization: vertices on pixel
// centres and subpixel grids or a few ulps off them, arbitrary doubles, needles, slivers, zero and
// near-zero area, huge coordinates and subnormals; triangulated regions with exactly shared vertices
// (closed fans around a sample, strips, grids, triangulations of point sets and polygons, the front of a
// closed mesh under a random camera); overlapping and interpenetrating triangles with equal and unequal
// depths. Every scene is valid input: finite coordinates, a viewport of 1..24 pixels a side (long_rows:
// up to 256). The generators below draw the same distribution whatever RapidCheck's size (they resize
// to its nominal size): a counterexample is made small by shrinking.
#pragma once

#include <rast/scene.h>

#include <rapidcheck.h>

#include <ostream>
#include <string_view>
#include <vector>

namespace rast {

// How RapidCheck shows a scene in a failure (found by argument-dependent lookup): as .tri text, every
// coordinate a hex-float, so that it can be pasted into a file and replayed.
void showValue(const Scene& scene, std::ostream& os);

}  // namespace rast

namespace rast::gen {

// A coordinate in [lo, hi]: on the pixel grid, on pixel centres, on a 2^-bits subpixel grid
// (bits 1..16), a few ulps off such a point, or an arbitrary double.
rc::Gen<double> coordinate(double lo, double hi);

// A depth: often from a few shared values (to make ties), otherwise arbitrary in [-1, 2].
rc::Gen<double> depth();

rc::Gen<Viewport> viewport();
rc::Gen<int> sample_count();  // 1, 4, 8 or 16

// One triangle near the viewport, of a kind drawn at random: ordinary, needle, sliver, exactly
// degenerate, reaching out to huge coordinates (up to 2^60), or touching subnormals.
rc::Gen<Triangle> triangle(Viewport vp);

// A few triangles of any kind (triangle()), with any sample count.
rc::Gen<Scene> loose_triangles();

// Wide, short viewports (64..256 pixels by 1..4) crossed by triangles with a vertex up to 2^25 pixels
// away (half of them on an edge nudged a few ulps off a line of pixel centres): long rows of samples
// whose edge functions are large, where float rounding accumulates.
rc::Gen<Scene> long_rows();

// Triangles with exactly shared vertices tiling a region, every one in a random vertex order and the
// list in a random order: a closed fan around a sample, a strip, a perturbed grid, a triangulation of a
// point set or a polygon (CGAL), or the front faces of a closed mesh under a random camera.
rc::Gen<Scene> triangulated_region();
// The same, with every vertex on the 2^-bits grid (so that a fixed mode's snapping leaves it alone).
rc::Gen<Scene> triangulated_region_on_grid(int bits);

// Overlapping and interpenetrating triangles: coplanar at equal depths, duplicated, or on crossing
// planes; often sharing vertices, always with depth ties somewhere likely.
rc::Gen<Scene> overlapping_triangles();

// Runs of pixel-sized triangles packed into a few pixels, as the fast path composes them a run of stamps
// at a time (fast/src/compose.h): twins of earlier ones (tied everywhere) among depths from 1e-300 to
// 1.7e308, whose planes' error bounds lie hundreds of orders apart or overflow.
rc::Gen<Scene> stamped_runs();

// Layers: large triangles over the whole viewport on crossing planes (dyadic, so ties are exact), with a
// few small triangles among them, on the same planes or their own.
rc::Gen<Scene> layered_triangles();

// Lines among triangles on a few dyadic planes, ids interleaved in a random file order: ends anywhere, one
// out at up to 2^60, on pixel centres (rows, columns, diagonals, knight's moves) or along a row in a plane (a plane level in
// y ties with such a line at every lit centre).
rc::Gen<Scene> lines_among_triangles();

// A window of at most 4 x 4 pixels anywhere in a scene of `scenes`, the triangles moved by whole pixels:
// the judge of the visible area cuts each pixel at every crossing of its lines, so its scenes stay small.
rc::Gen<Scene> small_window(rc::Gen<Scene> scenes);

// One of all of the above.
rc::Gen<Scene> any_scene();

// The scenes that reach the hard cases of one property (rast/properties.h names them); throws
// std::invalid_argument for a name that is not a property.
rc::Gen<Scene> scenes_for(std::string_view property);

// Parts the generators above are built from, for the triangulation sources in their own files.
namespace detail {
// The triangles of a region, shuffled and each in a random vertex order.
rc::Gen<std::vector<Triangle>> shuffled(std::vector<Triangle> triangles);
// Points for a triangulation in [lo, hi]^2: on a 2^-bits grid with bits >= 0, else arbitrary doubles.
rc::Gen<std::vector<Vertex>> point_set(double lo, double hi, int bits);
// Triangulations by CGAL: Delaunay, the insertion-order triangulation (long, thin triangles), and the
// constrained triangulation of a random simple polygon.
rc::Gen<std::vector<Triangle>> delaunay(Viewport vp, int bits);
rc::Gen<std::vector<Triangle>> insertion_order_triangulation(Viewport vp, int bits);
rc::Gen<std::vector<Triangle>> polygon_triangulation(Viewport vp, int bits);
// The front faces of a closed convex mesh read through rast::scene, seen from a random camera outside it.
rc::Gen<std::vector<Triangle>> mesh_front(Viewport vp);
}  // namespace detail

}  // namespace rast::gen
