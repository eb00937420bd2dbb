// Triangle setup: everything the traversal needs, computed once per triangle. Templated on the injected
// fault so that the library (Fault::none) carries no trace of the faulty variants.
#pragma once

#include "bounded.h"
#include "exact.h"
#include "kernels.h"
#include "planes.h"
#include "snap.h"
#include "spans.h"

#include <rast/fast.h>
#include <rast/fast_faults.h>
#include <rast/filters/weights.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace rast::fast::detail {

// Screen tiles are kTile x kTile pixels; a tile row is one kernel row.
inline constexpr int kTile = kRowLanes;

// The 64-bit path's range in fixed units: with every vertex and sample within 2^29 of the origin, an
// edge function |A (X - ax) + B (Y - ay)| stays below 2^61 and its bias, steps and sums fit an int64.
inline constexpr double kFixedRange = 0x1p29;

// What one call rasterizes against: the viewport, the precision and the sample positions.
struct Context {
    Viewport vp;
    Precision precision;
    int bits;                                 // subpixel bits, 0 for the float modes
    std::vector<SamplePoint> offsets;         // per sample, inside the pixel
    std::vector<std::int64_t> sx, sy;         // the offsets in fixed units
    double ox_min, ox_max, oy_min, oy_max;    // their extent
    std::int64_t sx_min, sx_max, sy_min, sy_max;  // and in fixed units
    double unit;                              // the grid's spacing in pixels, 2^-bits
    double coordinate_limit;                  // kFixedRange in pixels
    bool fixed_fits;                          // the viewport itself is inside kFixedRange
    DepthSmallKernel depth_small;             // depth_small_kernel(), found once for the call
    DepthSmallRunKernel depth_small_run;      // and depth_small_run_kernel()
};

template <Fault F>
Context make_context(Viewport vp, int samples, Precision precision) {
    Context c{vp, precision, subpixel_bits(precision), {}, {}, {}, 1, 0, 1, 0, 0, 0, 0, 0, 0, 0, false,
              depth_small_kernel(), depth_small_run_kernel()};
    for (SamplePoint o : sample_pattern(samples)) {
        if constexpr (F == Fault::integer_sample_positions) o = {o.x - 0.5, o.y - 0.5};
        c.offsets.push_back(o);
        // Offsets are multiples of 1/16 and bits >= 4: exact integers in fixed units.
        c.sx.push_back(static_cast<std::int64_t>(std::ldexp(o.x, c.bits)));
        c.sy.push_back(static_cast<std::int64_t>(std::ldexp(o.y, c.bits)));
        c.ox_min = std::min(c.ox_min, o.x);
        c.ox_max = std::max(c.ox_max, o.x);
        c.oy_min = std::min(c.oy_min, o.y);
        c.oy_max = std::max(c.oy_max, o.y);
    }
    c.sx_min = *std::min_element(c.sx.begin(), c.sx.end());
    c.sx_max = *std::max_element(c.sx.begin(), c.sx.end());
    c.sy_min = *std::min_element(c.sy.begin(), c.sy.end());
    c.sy_max = *std::max_element(c.sy.begin(), c.sy.end());
    c.unit = std::ldexp(1.0, -c.bits);
    c.coordinate_limit = std::ldexp(kFixedRange, -c.bits);
    c.fixed_fits = vp.width + 1 <= c.coordinate_limit && vp.height + 1 <= c.coordinate_limit;
    return c;
}

enum class Path : std::uint8_t { fixed, wide, floating };

struct FixedEdge {
    std::int64_t a, b, c;  // E(X, Y) = a X + b Y + c in fixed units, tie bias included: covered iff >= 0
};

// The rectangle, in fixed units, of the samples of pixels [i0, i1] x [j0, j1] at every sample index.
struct FixedRect {
    std::int64_t x_lo, x_hi, y_lo, y_hi;
};
inline FixedRect samples_rect(const Context& c, int i0, int i1, int j0, int j1) {
    return {(std::int64_t{i0} << c.bits) + c.sx_min, (std::int64_t{i1} << c.bits) + c.sx_max,
            (std::int64_t{j0} << c.bits) + c.sy_min, (std::int64_t{j1} << c.bits) + c.sy_max};
}

// An integer edge's least and greatest values over a rectangle: it is linear, so they are at the corners
// its coefficients' signs pick.
inline std::int64_t least_over(const FixedEdge& f, const FixedRect& r) {
    return f.a * (f.a >= 0 ? r.x_lo : r.x_hi) + f.b * (f.b >= 0 ? r.y_lo : r.y_hi) + f.c;
}
inline std::int64_t greatest_over(const FixedEdge& f, const FixedRect& r) {
    return f.a * (f.a >= 0 ? r.x_hi : r.x_lo) + f.b * (f.b >= 0 ? r.y_hi : r.y_lo) + f.c;
}

// Pixels [i0, i1] x [j0, j1] of the viewport: one tile, or a part of one.
struct TileRect {
    int i0, i1, j0, j1;
};

// A wide edge's steps per pixel are below kWideStep (exact.h). A block's samples, and what the kernels
// compute past them (row_masks' rows below the block, the column kernel's vector past its last column, the
// covered subtiles' steps), lie within 4 kTile pixel steps of its first sample, over which the edge's value
// in pixel steps (WideEdge) changes by less than 2^58: where that value at the first sample is beyond
// +-kWideClamp, taking +-kWideClamp there instead keeps its sign at every one of them, and every value and
// step stays within the fixed path's 2^61.
inline constexpr std::int64_t kWideClamp = std::int64_t{1} << 60;
static_assert(4 * kTile * kWideStep <= kWideClamp / 4);
inline std::int64_t clamped(Int128 value) {
    return static_cast<std::int64_t>(std::clamp<Int128>(value, -kWideClamp, kWideClamp));
}

// A wide edge's least and greatest values in pixel steps over the samples of a rectangle of pixels,
// exactly.
inline Int128 least_over(const WideEdge& f, const TileRect& r) {
    return Int128{f.a} * (f.a >= 0 ? r.i0 : r.i1) + Int128{f.b} * (f.b >= 0 ? r.j0 : r.j1) + f.least;
}
inline Int128 greatest_over(const WideEdge& f, const TileRect& r) {
    return Int128{f.a} * (f.a >= 0 ? r.i1 : r.i0) + Int128{f.b} * (f.b >= 0 ? r.j1 : r.j0) + f.greatest;
}

// Edge k of corners v, from v[k] to v[k + 1], in doubles: E(p) = d1 (py - ay) - d3 (px - ax), d1 and d3
// the corners' differences rounded (each has the exact one's sign), as the float modes' whole-tile test
// takes it.
struct DoubleEdge {
    double ax, ay, d1, d3;
};
inline DoubleEdge double_edge(const Corners& v, int k) {
    const Vertex& a = v[static_cast<std::size_t>(k)];
    const Vertex& b = v[static_cast<std::size_t>((k + 1) % 3)];
    return {a.x, a.y, b.x - a.x, b.y - a.y};
}

struct FloatEdge {
    double ax, ay, d1, d3;  // a, b - a in the mode's type (exactly representable in it)
    bool inclusive;         // owns the samples exactly on it
};

// z(p) = z0 + (a (px - x0) + b (py - y0)) in double; err bounds its distance from the exact plane over
// the bounding box, times kSlack (which also covers the rounding of the depth test, depth_block in
// kernels.h).
struct Plane {
    double x0, y0, z0, a, b, err;
};

// A triangle that covers some sample of the viewport, as every path sees it first: vertices snapped
// (fixed modes) and counter-clockwise, its pixel bounding box inside the viewport (inclusive) and the
// path that computes its coverage.
struct Placed {
    Corners v;
    int i_lo, i_hi, j_lo, j_hi;
    Path path;
};

// Everything the traversal needs, computed once per triangle. What the common fixed path reads comes
// first, in as few cache lines as it fits.
struct Setup {
    Placed p;
    std::array<FixedEdge, 3> fixed{};
    Plane plane{};
    // Whether hierarchical z tests the subtiles of its tiles (tile_buffer.h): a big triangle that covers a
    // good part of its bounding box (a sliver's nearest corner in a subtile it passes says little).
    bool subtiles = false;
    bool classify_tiles = true;  // false: every tile is partial (a small triangle gains nothing from the test)
    std::array<FloatEdge, 3> flt{};
    // Float modes: a tile whose samples all have an exact edge function beyond +-margin on the same
    // side for each edge is classified without evaluating them; +infinity when not computed.
    double float_margin = std::numeric_limits<double>::infinity();
    // Wide path: which edges own the samples exactly on them (wide_spans' inclusive); its near edges
    // where wide_edges finds them, which classify tiles and from which a partial tile's rows are walked
    // in 64 bits (wide_edges_at, coverage.h); otherwise, with classify_tiles, what its spans lie within
    // per row of screen tiles. The spans themselves are found where a tile needs them (spans_of) rather
    // than kept from binning to the end of the render: at 8 bytes per row and sample each, thousands of
    // triangles reaching far beyond a large screen held gigabytes.
    std::array<bool, 3> owns{};
    std::optional<std::array<WideEdge, 3>> near;
    std::vector<SpanBand> bands;
};

// The wide path's spans of t over the pixel rows [j0, j1] of its bounding box, laid out as wide_spans
// lays them; spans holds (j1 - j0 + 1) * c.offsets.size() entries.
inline void spans_of(const Setup& t, const Context& c, int j0, int j1, std::span<Span> spans) {
    wide_spans(t.p.v, c.bits, t.owns, c.offsets, t.p.i_lo, t.p.i_hi, j0, j1, spans);
}

// The tie rule of docs/design.md for edge a -> b of a counter-clockwise triangle: left (dy < 0) and
// top (dy = 0, dx < 0) edges own their samples. Without branches: edge directions are random, so they
// would mispredict.
template <Fault F, class T>
bool owns_ties(T ax, T ay, T bx, T by) {
    if constexpr (F == Fault::wrong_tie_bias) return (by < ay) | ((by == ay) & (bx > ax));
    return (by < ay) | ((by == ay) & (bx < ax));
}

// Which edges of a counter-clockwise triangle own the samples exactly on them, edge k being v[k] -> v[k+1]
// (the fixed path's integer bias says it itself).
template <Fault F>
std::array<bool, 3> owning_edges(const Corners& v) {
    std::array<bool, 3> owns;
    for (int k = 0; k < 3; ++k) owns[k] = owns_ties<F>(v[k].x, v[k].y, v[(k + 1) % 3].x, v[(k + 1) % 3].y);
    return owns;
}

// The integer edge functions of a counter-clockwise triangle with corners (x[k], y[k]) in fixed units:
// E >= 0 on an owning edge, E > 0 (E - 1 >= 0 for integers) on the others. Scaling by 2^bits is exact
// and monotone, so the integers own the same edges as the coordinates they scale.
template <Fault F, class Int>
std::array<FixedEdge, 3> fixed_edges(const Int* x, const Int* y) {
    std::array<FixedEdge, 3> edges;
    for (int k = 0; k < 3; ++k) {
        const std::int64_t ax = x[k], ay = y[k], bx = x[(k + 1) % 3], by = y[(k + 1) % 3];
        const std::int64_t a = ay - by, b = bx - ax;
        edges[k] = {a, b, -(a * ax + b * ay) - (owns_ties<F>(ax, ay, bx, by) ? 0 : 1)};
    }
    return edges;
}

// [first, last] within [0, size): whether any pixel is left.
template <Fault F>
bool clip_range(int size, int& first, int& last) {
    if constexpr (F == Fault::bbox_one_short) last -= 1;
    first = std::max(first, 0);
    last = std::min(last, size - 1);
    return first <= last;
}

// Pixels whose samples can lie in [lo, hi] along one axis, given the sample offsets' extent there.
// Rounding is monotone and the bounds are integers, so ceil/floor of the rounded difference are exact.
// Clamped to [-1, size] first, where truncation to int is exact and ceil/floor are one correction.
template <Fault F>
bool pixel_range(double lo, double hi, double o_min, double o_max, int size, int& first, int& last) {
    const double from = std::clamp(lo - o_max, -1.0, double(size));
    const double to = std::clamp(hi - o_min, -1.0, double(size));
    first = static_cast<int>(from);
    first += first < from;
    last = static_cast<int>(to);
    last -= last > to;
    return clip_range<F>(size, first, last);
}

// The same in fixed units: lo, hi and the offsets' extent are multiples of 2^-bits times 2^bits, and
// an arithmetic shift right is floor division by 2^bits.
template <Fault F>
bool pixel_range(std::int64_t lo, std::int64_t hi, std::int64_t o_min, std::int64_t o_max, int bits, int size,
                 int& first, int& last) {
    const std::int64_t from = -((o_max - lo) >> bits), to = (hi - o_min) >> bits;  // ceil and floor
    first = static_cast<int>(std::clamp<std::int64_t>(from, -1, size));
    last = static_cast<int>(std::clamp<std::int64_t>(to, -1, size));
    return clip_range<F>(size, first, last);
}

// The two sources of a plane's error (bounded.h's rounding charges, weighed by a Weights policy,
// rast/filters/weights.h): the roundings that make the gradient (a, b), carried to every sample by the
// distance from corner 0, and those of the evaluation at the sample.
enum class PlaneTerm { gradient, evaluation };

// The plane of gradient (a, b) through corner 0, with the bound of its evaluation
// z0 + (a (px - x0) + b (py - y0)) over the box, from the magnitudes: at the box's far corner every
// term is as large as it gets, and every one can be.
template <class W = filters::Sound>
Plane plane_over_box(const Placed& s, const Context& c, Bounded a, Bounded b) {
    const Corners& v = s.v;
    const double w = W::weight(PlaneTerm::evaluation), u = w * kUnitDouble;
    const double reach_x = std::max(std::abs(s.i_lo + c.ox_min - v[0].x), std::abs(s.i_hi + c.ox_max - v[0].x));
    const double reach_y = std::max(std::abs(s.j_lo + c.oy_min - v[0].y), std::abs(s.j_hi + c.oy_max - v[0].y));
    const Bounded tx = mul({std::abs(a.v), a.e}, {reach_x, u * reach_x}, w);
    const Bounded ty = mul({std::abs(b.v), b.e}, {reach_y, u * reach_y}, w);
    const Bounded z = add(exact(std::abs(v[0].z)), add(tx, ty, w), w);
    double err = z.e * kSlack;
    if (!std::isfinite(err)) err = std::numeric_limits<double>::infinity();
    return {v[0].x, v[0].y, v[0].z, a.v, b.v, err};
}

template <class W = filters::Sound>
Plane make_plane(const Placed& s, const Context& c) {
    const Corners& v = s.v;
    const double w = W::weight(PlaneTerm::gradient);
    const Bounded dx1 = sub(exact(v[1].x), exact(v[0].x), w), dy1 = sub(exact(v[1].y), exact(v[0].y), w);
    const Bounded dx2 = sub(exact(v[2].x), exact(v[0].x), w), dy2 = sub(exact(v[2].y), exact(v[0].y), w);
    const Bounded dz1 = sub(exact(v[1].z), exact(v[0].z), w), dz2 = sub(exact(v[2].z), exact(v[0].z), w);
    const Bounded det = sub(mul(dx1, dy2, w), mul(dx2, dy1, w), w);
    const Bounded a = div(sub(mul(dz1, dy2, w), mul(dz2, dy1, w), w), det, w);
    const Bounded b = div(sub(mul(dx1, dz2, w), mul(dx2, dz1, w), w), det, w);
    return plane_over_box<W>(s, c, a, b);
}

// Snapping, winding, bounding box and path: nothing when the triangle covers no sample of the viewport.
template <Fault F>
std::optional<Placed> place(const Triangle& t, const Context& c) {
    Placed s;
    s.v = snapped(t, c.precision).v;
    const int orient = orientation(s.v);
    if (orient == 0) return std::nullopt;  // zero area covers nothing
    if (orient < 0) std::swap(s.v[1], s.v[2]);
    const auto [xmin, xmax] = std::minmax({s.v[0].x, s.v[1].x, s.v[2].x});
    const auto [ymin, ymax] = std::minmax({s.v[0].y, s.v[1].y, s.v[2].y});
    if (!pixel_range<F>(xmin, xmax, c.ox_min, c.ox_max, c.vp.width, s.i_lo, s.i_hi) ||
        !pixel_range<F>(ymin, ymax, c.oy_min, c.oy_max, c.vp.height, s.j_lo, s.j_hi))
        return std::nullopt;
    const double limit = c.coordinate_limit;
    const bool fits = c.fixed_fits && std::all_of(s.v.begin(), s.v.end(), [limit](const Vertex& p) {
                          return std::abs(p.x) <= limit && std::abs(p.y) <= limit;
                      });
    s.path = !is_fixed(c.precision) ? Path::floating : fits ? Path::fixed : Path::wide;
    return s;
}

// The least and the greatest of three integers, without branches: std::minmax over an initializer list
// is a loop, and a small triangle's lane takes four of these.
template <class Int>
std::pair<Int, Int> min_max(Int a, Int b, Int c) {
    return {std::min(std::min(a, b), c), std::max(std::max(a, b), c)};
}

// A triangle whose bounding box spans at most kSmallSide pixels each way (so at most 2 x 2 tiles) is
// binned as it was placed and set up in each tile it is rasterized in: its record is small and read
// once, where a shared setup would be written, then read back from memory.
inline constexpr int kSmallSide = 32;

inline bool is_small(int i_lo, int i_hi, int j_lo, int j_hi) {
    return i_hi - i_lo < kSmallSide && j_hi - j_lo < kSmallSide;
}

// A small triangle of the 64-bit fixed path as binned, the common case kept compact: snapped and
// counter-clockwise in fixed units, with its depths and pixel bounding box (the tile reads nothing else,
// so it never goes back to the input, which would cost a cache miss per triangle).
struct SmallFixed {
    double z[3];
    std::int32_t x[3], y[3];  // |.| <= 2^29
    std::int32_t i_lo, i_hi, j_lo, j_hi;
    std::int32_t id;
    bool narrow;  // narrow_edges, found once when placed (in the record's padding)
};

// Whether the edge functions of `t` fit in 32 bits at every sample of its bounding box (scale: grid
// units to the pixel). With w the larger extent of its corners in grid units, such a sample lies within
// w + scale of each corner along each axis (the sample offsets are within the pixel), and an edge's
// coefficients are coordinate differences, so |E| <= 2 w (w + scale) + 1 (the tie bias).
inline bool narrow_edges(const SmallFixed& t, std::int64_t scale) {
    const auto [xmin, xmax] = min_max(t.x[0], t.x[1], t.x[2]);
    const auto [ymin, ymax] = min_max(t.y[0], t.y[1], t.y[2]);
    const std::int64_t w = std::max(std::int64_t{xmax} - xmin, std::int64_t{ymax} - ymin);
    return 2 * w * (w + scale) + 1 < (std::int64_t{1} << 31);  // w, scale <= 2^30: no overflow
}

enum class Lane { culled, small_fixed, general };

// place() in integers, for a fixed-mode context whose viewport is in the 64-bit range: culled (zero area
// or no sample of the viewport), small_fixed with `out` filled, or general when place() must decide (a
// coordinate beyond the range, or a triangle that is not small).
template <Fault F>
Lane place_small_fixed(const Triangle& t, std::int32_t id, const Context& c, SmallFixed& out) {
    const double scale = static_cast<double>(std::int64_t{1} << c.bits);
    std::int64_t x[3], y[3];
    for (int k = 0; k < 3; ++k) {
        const Vertex& p = t.v[k];
        // Within the range, and so is the snapped value: the range's end is on the grid.
        if (!(std::abs(p.x) <= c.coordinate_limit && std::abs(p.y) <= c.coordinate_limit)) return Lane::general;
        x[k] = grid_units(p.x, scale);  // |p.x · scale| <= 2^29
        y[k] = grid_units(p.y, scale);
    }
    // Differences below 2^30, products below 2^60: exact in 64 bits.
    const std::int64_t cross = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (cross == 0) return Lane::culled;
    const auto [xmin, xmax] = min_max(x[0], x[1], x[2]);
    const auto [ymin, ymax] = min_max(y[0], y[1], y[2]);
    if (!pixel_range<F>(xmin, xmax, c.sx_min, c.sx_max, c.bits, c.vp.width, out.i_lo, out.i_hi) ||
        !pixel_range<F>(ymin, ymax, c.sy_min, c.sy_max, c.bits, c.vp.height, out.j_lo, out.j_hi))
        return Lane::culled;
    if (!is_small(out.i_lo, out.i_hi, out.j_lo, out.j_hi)) return Lane::general;
    // Counter-clockwise: a clockwise triangle's corners 1 and 2 trade places, picked by index rather than
    // swapped under a branch, which mispredicted every other triangle (windings are random).
    const int second = cross < 0 ? 2 : 1;
    const int order[3] = {0, second, 3 - second};
    for (int k = 0; k < 3; ++k) {
        out.x[k] = static_cast<std::int32_t>(x[order[k]]);
        out.y[k] = static_cast<std::int32_t>(y[order[k]]);
        out.z[k] = t.v[order[k]].z;
    }
    out.id = id;
    out.narrow = narrow_edges(out, std::int64_t{1} << c.bits);
    return Lane::small_fixed;
}

// What place() makes of the triangle that `s` records.
inline Placed placed_of(const SmallFixed& s, const Context& c) {
    Placed p{{}, s.i_lo, s.i_hi, s.j_lo, s.j_hi, Path::fixed};
    for (int k = 0; k < 3; ++k) p.v[k] = {s.x[k] * c.unit, s.y[k] * c.unit, s.z[k]};
    return p;
}

// What the SIMD planes need of the context (planes.h).
inline PlaneGrid plane_grid(const Context& c) { return {c.unit, c.ox_min, c.ox_max, c.oy_min, c.oy_max}; }

// The depth planes of n placed triangles (1 to kPlaneBatch), placed(k) a reference to the k-th:
// make_plane's, set up together (make_planes).
template <class PlacedOf>
void placed_planes(std::size_t n, PlacedOf placed, const Context& c, Plane* planes) {
    CornerBatch batch;
    for (std::size_t k = 0; k < kPlaneBatch; ++k) {
        const Placed& s = placed(k < n ? k : 0);  // lanes past the run repeat its first
        for (int corner = 0; corner < 3; ++corner) {
            batch.x[corner][k] = s.v[corner].x;
            batch.y[corner][k] = s.v[corner].y;
            batch.z[corner][k] = s.v[corner].z;
        }
        batch.i_lo[k] = s.i_lo;
        batch.i_hi[k] = s.i_hi;
        batch.j_lo[k] = s.j_lo;
        batch.j_hi[k] = s.j_hi;
    }
    make_planes(batch, plane_grid(c));
    for (std::size_t k = 0; k < n; ++k) {
        const Vertex& v0 = placed(k).v[0];
        planes[k] = Plane{v0.x, v0.y, v0.z, batch.a[k], batch.b[k], batch.err[k]};
    }
}

// The depth planes of a run of 1 to kPlaneBatch small triangles, and which of them are narrow
// (narrow_edges; bit k for run[k]): the narrow ones' set up together (narrow_planes), the others',
// make_plane's, together too (placed_planes). Where any is narrow, `batch` holds the run's corners and
// boxes (lanes past the run repeat its first triangle).
inline std::uint32_t small_planes(std::span<const SmallFixed> run, const Context& c, Plane* planes,
                                  PlaneBatch& batch) {
    std::uint32_t narrow = 0;
    for (std::size_t k = 0; k < run.size(); ++k)
        narrow |= std::uint32_t{run[k].narrow} << k;
    if (narrow != 0) {
        for (std::size_t k = 0; k < kPlaneBatch; ++k) {
            const SmallFixed& t = run[k < run.size() ? k : 0];
            for (int corner = 0; corner < 3; ++corner) {
                batch.x[corner][k] = t.x[corner];
                batch.y[corner][k] = t.y[corner];
                batch.z[corner][k] = t.z[corner];
            }
            batch.i_lo[k] = t.i_lo;
            batch.i_hi[k] = t.i_hi;
            batch.j_lo[k] = t.j_lo;
            batch.j_hi[k] = t.j_hi;
        }
        narrow_planes(batch, plane_grid(c));
    }
    const std::uint32_t all = (std::uint32_t{1} << run.size()) - 1;
    if (narrow != all) {  // the others' planes, make_plane's, in lanes too (fixed16's are seldom narrow)
        Placed placed[kPlaneBatch];
        for (std::size_t k = 0; k < run.size(); ++k) placed[k] = placed_of(run[k], c);
        placed_planes(run.size(), [&](std::size_t k) -> const Placed& { return placed[k]; }, c, planes);
    }
    for (std::size_t k = 0; k < run.size(); ++k) {
        const SmallFixed& t = run[k];
        if (narrow >> k & 1)
            planes[k] = Plane{t.x[0] * c.unit, t.y[0] * c.unit, t.z[0], batch.a[k], batch.b[k], batch.err[k]};
    }
    return narrow;
}

// The float modes' tile margin: the mode's edge error bound plus that of the double evaluation the tile
// classification makes, rounded up.
inline double float_margin(const Corners& v, const Context& c) {
    const Triangle t{v};
    return (edge_error_bound(t, c.precision, c.vp) + edge_error_bound(t, Precision::float64, c.vp)) *
           (1 + 0x1p-40);
}

// Twice the signed area of the triangle with corners v (positive counter-clockwise), in doubles: for
// heuristics, whose rounding does not matter.
inline double twice_area(const Corners& v) {
    return (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
}

// Whether the triangle with corners v covers at least an eighth of its bounding box (a fat one covers
// half at most).
inline bool fills_box(const Corners& v) {
    const auto [x_lo, x_hi] = std::minmax({v[0].x, v[1].x, v[2].x});
    const auto [y_lo, y_hi] = std::minmax({v[0].y, v[1].y, v[2].y});
    return 4 * std::abs(twice_area(v)) >= (x_hi - x_lo) * (y_hi - y_lo);
}

// classify_tiles: also compute what whole-tile trivial accept / reject needs (worth it for a triangle
// that spans tiles; a small one is classified by its edge functions alone). `plane`: make_plane's, found
// beforehand (the small lane's, by placed_planes) or by the overload below.
template <Fault F>
Setup setup_triangle(const Placed& placed, const Context& c, bool classify_tiles, const Plane& plane) {
    Setup s;
    s.plane = plane;
    s.p = placed;
    s.classify_tiles = classify_tiles;
    const Corners& v = placed.v;
    s.subtiles = classify_tiles && fills_box(v);

    switch (placed.path) {
        case Path::floating: {
            const bool single = c.precision == Precision::float32;
            const std::array<bool, 3> inclusive = owning_edges<F>(v);
            const auto in_type = [single](double x) { return single ? double(float(x)) : x; };
            for (int k = 0; k < 3; ++k) {
                const Vertex& p = v[k];
                const Vertex& q = v[(k + 1) % 3];
                const double ax = in_type(p.x), ay = in_type(p.y), bx = in_type(q.x), by = in_type(q.y);
                // The differences rounded once in the mode's type: float - float is correctly rounded in float.
                s.flt[k] = {ax, ay, single ? double(float(bx) - float(ax)) : bx - ax,
                            single ? double(float(by) - float(ay)) : by - ay, inclusive[k]};
            }
            if (classify_tiles) s.float_margin = float_margin(v, c) * (F == Fault::halved_float_margin ? 0.5 : 1);
            break;
        }
        case Path::fixed: {
            const double scale = static_cast<double>(std::int64_t{1} << c.bits);
            std::int64_t x[3], y[3];
            for (int k = 0; k < 3; ++k) {
                x[k] = static_cast<std::int64_t>(v[k].x * scale);
                y[k] = static_cast<std::int64_t>(v[k].y * scale);
            }
            s.fixed = fixed_edges<F>(x, y);
            break;
        }
        case Path::wide:
            s.owns = owning_edges<F>(v);
            s.near = wide_edges(v, c.bits, s.owns, c.sx, c.sy);
            if (classify_tiles && !s.near)
                s.bands = wide_bands(v, c.bits, s.owns, c.offsets, s.p.i_lo, s.p.i_hi, s.p.j_lo, s.p.j_hi, kTile);
            break;
    }
    return s;
}

template <Fault F>
Setup setup_triangle(const Placed& placed, const Context& c, bool classify_tiles) {
    return setup_triangle<F>(placed, c, classify_tiles, make_plane(placed, c));
}

// What the tiles need of the whole scene: the input triangles, for the exact depth order.
struct SceneView {
    std::span<const Triangle> triangles;
    const Context& c;
};

}  // namespace rast::fast::detail
