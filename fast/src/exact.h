// The decisions double arithmetic cannot settle, made exactly (Boost.Multiprecision, private to
// exact.cpp): triangle orientation on arbitrary doubles, the depth order at a sample, and the edges and
// covered spans of a triangle beyond the 64-bit fixed-point range (the wide path).
#pragma once

#include "spans.h"

#include <rast/scene.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace rast::fast::detail {

using Corners = std::array<Vertex, 3>;
__extension__ using Int128 = __int128;  // GCC and Clang on x86-64

// Sign (-1, 0, 1) of (v1 - v0) x (v2 - v0): 1 for counter-clockwise.
int orientation(const Corners& v);

// The exact depth planes of the triangles a z-buffer had to order exactly, each built once, at its
// triangle's first such comparison, then evaluated per sample. Not synchronized: one per thread.
class ExactPlanes {
public:
    ExactPlanes();
    ExactPlanes(ExactPlanes&&) noexcept;
    ExactPlanes& operator=(ExactPlanes&&) noexcept;
    ~ExactPlanes();

    // Sign of depth_t(x, y) - depth_u(x, y) for the non-degenerate triangles t and u (any corner order),
    // named by their ids.
    int compare(std::int64_t t_id, const Corners& t, std::int64_t u_id, const Corners& u, double x, double y);

    // The exact depth of the plane of triangle t at (x, y), rounded to a double.
    double depth(std::int64_t id, const Corners& t, double x, double y);

private:
    struct Cache;
    std::unique_ptr<Cache> cache_;  // created at the first exact comparison
};

// A depth the lines' z-buffer test may have to settle exactly: the plane of `triangle` (non-degenerate,
// any corner order) at (x, y), or the depth of `segment` at its point nearest (x, y), z interpolated
// along it (docs/design.md). Exactly one of the two is set.
struct DepthAt {
    const Corners* triangle = nullptr;
    const Segment* segment = nullptr;
    double x = 0, y = 0;
};

// Sign (-1, 0, 1) of a's depth minus b's.
int compare(const DepthAt& a, const DepthAt& b);

// a's depth rounded to the nearest double.
double nearest(const DepthAt& a);

// For a counter-clockwise triangle whose coordinates are multiples of 2^-bits: for each pixel row j in
// [j_lo, j_hi] and each sample s, spans[(j - j_lo) * offsets.size() + s] := the pixels i in [i_lo, i_hi]
// whose sample (i + offset.x, j + offset.y) the triangle covers. inclusive[k] says whether edge
// v[k] -> v[k+1] owns the samples exactly on it. spans holds (j_hi - j_lo + 1) * offsets.size() entries.
void wide_spans(const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                std::span<const SamplePoint> offsets, int i_lo, int i_hi, int j_lo, int j_hi,
                std::span<Span> spans);

// The wide path's integer edges for a triangle near enough that a tile's rows are walked in 64 bits, in
// steps of a pixel. E(X, Y) = a X + b Y + c in fixed units (the tie rule in c: covered iff E >= 0); at
// the sample of pixel (i, j) with offset (sx, sy) in fixed units, E = 2^bits (a i + b j) + C with
// C = a sx + b sy + c, and a i + b j is an integer, so the sample is covered exactly where
// a i + b j + floor(C / 2^bits) >= 0 (offset_term). least and greatest: that term's extremes over the
// sample offsets.
struct WideEdge {
    std::int64_t a, b;
    Int128 c, least, greatest;
};
inline constexpr std::int64_t kWideStep = std::int64_t{1} << 50;  // |a| and |b| are below it

inline Int128 offset_term(const WideEdge& f, int bits, std::int64_t sx, std::int64_t sy) {
    return (Int128{f.a} * sx + Int128{f.b} * sy + f.c) >> bits;  // an arithmetic shift: floor
}

// The edges of a counter-clockwise triangle whose corners are multiples of 2^-bits, for the sample offsets
// (sx[k], sy[k]) in fixed units, where its coordinates lie within 2^(60 - bits) pixels and a and b are
// below kWideStep (its coordinates differ by less than 2^(50 - bits) pixels); otherwise none, and the
// triangle keeps its spans.
std::optional<std::array<WideEdge, 3>> wide_edges(const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                                                  std::span<const std::int64_t> sx, std::span<const std::int64_t> sy);

// For the same triangle and rows, the bands of `rows` pixel rows (band k holds the rows
// [k rows, (k + 1) rows) of [j_lo, j_hi], k from j_lo / rows on) that its spans lie within, found
// without its spans.
std::vector<SpanBand> wide_bands(const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                                 std::span<const SamplePoint> offsets, int i_lo, int i_hi, int j_lo, int j_hi,
                                 int rows);

}  // namespace rast::fast::detail
