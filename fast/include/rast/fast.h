// rast — the fast rasterizer, as a library.
//
// Same conventions as the exact reference (docs/design.md): y up, pixel centres at (i + 1/2, j + 1/2),
// the top-left tie rule, the (z, id) depth order. Where it departs from the reference is the precision
// mode, chosen per call:
//   fixed4 / fixed8 / fixed16: vertices snapped to a 1/2^N pixel grid (round to nearest, ties to even),
//     then exact integer edge functions: bit-identical to the reference on already snapped vertices.
//   float32 / float64: edge functions in floating point, within edge_error_bound() of the exact edge.
//     Where that bound is +infinity (an evaluation can overflow: the edge function's products of
//     coordinates, from about 2^63 pixels in float32 and 2^511 in float64), the coverage is whatever the
//     IEEE evaluation gives: such a triangle can lose samples, or all of them (a float32 triangle with
//     corners at +-2^64 covering the whole viewport draws nothing).
//
// Fixed-point range. A triangle whose snapped coordinates and the viewport's extent are all within
// 2^(29-N) pixels of the origin (fixed8: 2^21) takes the fast path: 64-bit integer edge functions,
// tiles of 64 x 64 pixels with trivial reject / accept, each sample row's covered run walked from the
// previous row's by exact integer steps (or, for a small triangle whose edge functions fit, found in
// 32-bit SIMD lanes; a block of a few samples is tested sample by sample), and the depth test in SIMD on
// that run alone. Any other triangle, up to
// coordinates of +-DBL_MAX, takes the wide path: where its coordinates lie within 2^(60-N) pixels and
// differ by less than 2^(50-N) (fixed8: 2^42), the same tiles and row walk in 64 bits, in steps of a
// pixel, from each tile's edge values found exactly in 128-bit integers; otherwise the row walk itself in
// 128-bit integers (coordinates within 2^(60-N) pixels) or big integers. Every way gives exactly the
// reference's coverage of the snapped triangle.
//
// Depth. z is the triangle's plane evaluated in double at the sample; the z-buffer decides the (z, id)
// order exactly: a comparison the double values and their error bounds cannot settle is made in exact
// rational arithmetic. The depth written is that double plane value, which differs from the reference's
// exact depth rounded to nearest by at most a few ulps of the depths and plane slopes involved (a
// running error bound kept per triangle; it grows without limit only for near-degenerate triangles).
// Where double arithmetic overflows, the depth written is the exact depth rounded. Overlapping
// triangles of equal depth tie at every shared sample: two of constant depth (a flat 2D scene) are
// ordered by those depths and ids at once, but coplanar sloped ones by an exact rational comparison at
// each such sample.
//
// Determinism. The framebuffer is identical for every thread count and every SIMD target (Highway
// dynamic dispatch: SSE4, AVX2, AVX-512 where present): coverage is exact or evaluated in the same IEEE
// operations everywhere, and each sample ends with its (z, id)-least triangle, decided exactly, and that
// triangle's own depth, computed the same way by every path that stores it, whatever order a tile
// composes its triangles in (triangles of a tile's area or more nearest first, then the others in id
// order).
//
// Lines (Scene::lines, rast/scene.h). After the triangles, each line's pixels (bresenham() on the fixed
// mode's grid, dda() in the float modes' type) are offered to the finished z-buffer on one thread; a lit
// pixel's samples take the line's depth at the pixel, ordered exactly against what is stored (a line's
// depth filter, then exact arithmetic), so lines and triangles share the (z, id) order.
//
// Input. Every function throws std::invalid_argument for a viewport that is not 1..2^24 pixels on each
// side or whose samples number more than 2^32 (a framebuffer of 48 GiB), a sample count other than 1, 4,
// 8, 16, a non-finite coordinate (naming the triangle and the vertex, or the line and the end) or sample
// position, lines' ids that triangle_ids() refuses, a Precision outside the enum, or a thread count
// outside 0..1024: the sizes before anything is allocated for them, the coordinates while the triangles
// are binned, and always before the target framebuffer is touched.
// name() alone answers "unknown" for such a Precision.
#pragma once

#include <rast/scene.h>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace rast::fast {

enum class Precision { fixed4, fixed8, fixed16, float32, float64 };

struct Options {
    Precision precision = Precision::fixed8;
    // 0..1024; 0: as many as max_threads(), as does a count above it. The result is identical for every count.
    int threads = 1;
};

// The most threads a render runs: the hardware threads this process may use, or the limit the application
// set with tbb::global_control. Asking for more would oversubscribe the cores, and TBB would ignore the
// request with a warning on stderr.
int max_threads();

// "fixed4", "fixed8", "fixed16", "float32", "float64" ("unknown" for a value outside the enum);
// parse_precision is its inverse.
std::string_view name(Precision p);
std::optional<Precision> parse_precision(std::string_view s);

// Rasterizes the scene, triangles and lines, with the z-buffer's (z, id) order.
Framebuffer render(const Scene& scene, const Options& options = {});

// The same, into `target`: every sample of it is overwritten, and its storage is kept when its viewport
// and sample count already match the scene's (resized otherwise). For frame after frame, as a GL context
// keeps its framebuffer; render(scene, options) allocates and fills a new one each call. Invalid input
// throws before target is touched. Its working memory is allocated afresh each call: see Renderer.
void render(const Scene& scene, Framebuffer& target, const Options& options = {});

namespace detail {
struct Workspace;
}

// render(scene, target, options) for frame after frame: a Renderer keeps what a render allocates for
// the next one (the triangles' bins per screen tile, each thread's tile z-buffer, the threads' arena),
// as a GL context keeps its own. Fresh memory is faulted in page by page: where the heap gave the last
// render's back to the system (glibc trims the top of its heap), 10^5 small triangles (about 9 MB of
// bins) spent a sixth of their render's time faulting it in again. The memory is that of the largest
// scene rendered so far, freed with the Renderer. The result is the free function's, bit for bit. One
// call at a time per Renderer.
class Renderer {
public:
    Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;
    ~Renderer();

    void render(const Scene& scene, Framebuffer& target, const Options& options = {});

private:
    std::unique_ptr<detail::Workspace> workspace_;
};

// The framebuffer indices (Framebuffer::index) of every sample that `t` covers, ascending; no depth test.
std::vector<std::size_t> covered_samples(const Triangle& t, Viewport vp, int samples,
                                         Precision precision = Precision::fixed8);

// The triangle as a fixed-point mode sees it: x and y rounded to the nearest multiple of 2^-N
// (ties to even), z unchanged. The identity for the float modes.
Triangle snap(const Triangle& t, Precision precision);

// For the float modes: an upper bound on |E_computed(p) - E_exact(p)| over every sample p of the
// viewport, for each edge E(p) = (b - a) x (p - a) of `t` (a, b the input doubles, any vertex order),
// E_computed taken before the rounding of its last subtraction (which is monotone and keeps the sign, so
// it never changes a classification). A sample can be classified differently from the reference only if
// |E_exact(p)| <= this bound for some edge. Derived by standard error analysis of the evaluation
// (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x), each operation rounded to nearest in the mode's
// type (u = 2^-24 or 2^-53), including the rounding of every input to float for float32. +infinity where
// the evaluation can overflow; 0 for the fixed modes, which are exact on the snapped triangle.
double edge_error_bound(const Triangle& t, Precision precision, Viewport vp);

// The same analysis at one sample (x, y), edge by edge: element k bounds |E_computed - E_exact| there for
// the edge between v[k] and v[k + 1], evaluated from its start in counter-clockwise order as the
// rasterizer does, with that sample's |p - a| and |p| in place of the viewport's extremes. Far smaller
// than edge_error_bound() near an edge's start vertex. A sample can be classified differently from the
// reference only if |E_exact(x, y)| <= element k for some edge k.
std::array<double, 3> edge_error_bound_at(const Triangle& t, Precision precision, double x, double y);

// Lines: the pixels of the viewport a segment lights by the diamond-exit rule (docs/design.md), as pixel
// indices j * width + i, ascending. The midpoint (Bresenham) algorithm: x and y of both ends snapped to
// the 1/2^bits grid as the fixed modes snap (bits 1..16), then one candidate per column (x-major) or row
// (y-major) stepped in integers (128-bit, or big integers for ends beyond 2^(51 - bits) pixels), and the
// ends' diamonds decided exactly: the reference's pixels for the snapped segment, bit for bit. Throws
// std::invalid_argument for a viewport outside the limits above, bits outside 1..16 or an end that is not
// finite.
std::vector<std::size_t> bresenham(const Segment& s, Viewport vp, int bits = 8);

// The same rule by the digital differential analyzer in float32 or float64: the ends rounded to that
// type, the candidate across each column (or row) found by adding the slope once a step, the ends'
// diamonds decided in that type. Rounding can move a pixel off the reference's; rast bench counts how
// often. Any finite coordinate is accepted, but where the ends' difference overflows the type (past
// float range in float32, past about 2^1023 in float64) the slope is infinite or NaN and the DDA lights
// what that gives: it can move a whole line, or lose it.
// Throws std::invalid_argument for a viewport outside the limits above, a coordinate that is not finite,
// or a fixed-point precision (bresenham is that line).
std::vector<std::size_t> dda(const Segment& s, Viewport vp, Precision precision = Precision::float32);

}  // namespace rast::fast
