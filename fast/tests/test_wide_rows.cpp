// The wide path's near edges (wide_edges): a block's rows walked in 64 bits from the edges' exact values
// at its first sample, clamped (wide_edges_at, then row_masks, the scalar rows or coverage_block's SIMD
// evaluation), against the spans they stand for (wide_spans, walked in 128-bit integers from the
// triangle's first row), on blocks anywhere in the largest viewport: along the edges, where edges through
// samples make ties, and far from them, where the edges' values are beyond 64 bits and the clamp alone
// keeps their signs. And which triangles have near edges: those whose coordinate differences are all below
// 2^(50 - bits) pixels.
#include "coverage.h"
#include "scalar.h"
#include "setup.h"
#include "targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

constexpr int kSide = 1 << 24;  // the largest viewport's

// A triangle of the wide path with coordinate differences up to about 2^(reach + 1) pixels: a corner on
// a sample, a second a whole number of steps (p, q) from it, so that the edge between them runs through
// samples, and a third anywhere within reach of the first.
Corners wide_triangle(std::mt19937_64& rng, const Context& c, int reach) {
    const auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const auto on_grid = [&c](double x) { return std::ldexp(std::round(std::ldexp(x, c.bits)), -c.bits); };
    const double far = std::ldexp(1.0, std::uniform_int_distribution<int>(8, reach)(rng));
    const SamplePoint& o = c.offsets[rng() % c.offsets.size()];
    Corners v;
    v[0] = {std::floor(uniform(0, kSide)) + o.x, std::floor(uniform(0, kSide)) + o.y, 0};
    const double p = std::floor(uniform(-5, 6)), q = std::floor(uniform(-5, 6));
    const double steps = std::floor(far / std::max({std::abs(p), std::abs(q), 1.0}));
    v[1] = {v[0].x + p * steps, v[0].y + q * steps, 0};
    v[2] = {on_grid(v[0].x + uniform(-far, far)), on_grid(v[0].y + uniform(-far, far)), 0};
    return v;
}

// A block of the viewport: around a point of one of v's edges, or anywhere.
Block random_block(std::mt19937_64& rng, const Context& c, const Corners& v, int s) {
    const auto below = [&rng](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
    const int width = 1 + below(kRowLanes), rows = 1 + below(kRowLanes);
    double x = below(kSide), y = below(kSide);
    if (below(4) != 0) {
        const Vertex &a = v[static_cast<std::size_t>(below(3))], &b = v[static_cast<std::size_t>(below(3))];
        const double t = std::uniform_real_distribution<double>(0, 1)(rng);
        x = a.x + t * (b.x - a.x) - below(width);
        y = a.y + t * (b.y - a.y) - below(rows);
    }
    const int i0 = static_cast<int>(std::clamp(std::floor(x), 0.0, double(kSide - width)));
    const int j0 = static_cast<int>(std::clamp(std::floor(y), 0.0, double(kSide - rows)));
    return {i0, j0, width, rows, c.offsets[static_cast<std::size_t>(s)].x, c.offsets[static_cast<std::size_t>(s)].y};
}

TEST(WideRows, WalkedFromNearEdgesEqualTheSpansOnEveryBlock) {
    on_every_target([&] {
        std::mt19937_64 rng(20261129);
        int partly_covered = 0, clamped = 0, beyond_64_bits = 0, without = 0;
        for (const Precision precision : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
            for (const int samples : {1, 4}) {
                const Context c = make_context<Fault::none>({kSide, kSide}, samples, precision);
                const int limit = 50 - c.bits;  // near edges below 2^limit pixels
                for (int n = 0; n < 300; ++n) {
                    const Corners corners = wide_triangle(rng, c, limit + 1);
                    const std::optional<Placed> placed = place<Fault::none>(Triangle{corners}, c);
                    if (!placed || placed->path != Path::wide) continue;  // fixed4's range holds the viewport
                    const Corners& v = placed->v;
                    const std::array<bool, 3> owns = owning_edges<Fault::none>(v);
                    const std::optional<std::array<WideEdge, 3>> near = wide_edges(v, c.bits, owns, c.sx, c.sy);
                    double widest = 0;
                    for (int k = 0; k < 3; ++k) {
                        const Vertex &a = v[static_cast<std::size_t>(k)], &b = v[static_cast<std::size_t>((k + 1) % 3)];
                        widest = std::max({widest, std::abs(b.x - a.x), std::abs(b.y - a.y)});
                    }
                    ASSERT_EQ(near.has_value(), widest < std::ldexp(1.0, limit)) << widest;
                    if (!near) {
                        ++without;
                        continue;
                    }
                    for (int trial = 0; trial < 8; ++trial) {
                        const int s = static_cast<int>(rng() % c.offsets.size());
                        const Block b = random_block(rng, c, v, s);
                        RowEdges edges;
                        wide_edges_at(*near, c, b, s, edges.q, edges.p, edges.step);
                        std::uint64_t masks[kRowLanes], evaluated[kRowLanes];
                        row_masks(edges, b.width, b.rows, masks);
                        // The same edges evaluated sample by sample (coverage_block, covered_samples' way).
                        Coverage cov{.kind = Coverage::Kind::fixed};
                        for (int k = 0; k < 3; ++k) {
                            cov.e[k] = edges.q[k];
                            cov.dx[k] = edges.p[k];
                            cov.dy[k] = edges.step[k];
                        }
                        coverage_block(b, cov, evaluated);
                        std::vector<Span> spans(static_cast<std::size_t>(b.rows) * c.offsets.size());
                        wide_spans(v, c.bits, owns, c.offsets, b.i0, b.i0 + b.width - 1, b.j0, b.j0 + b.rows - 1,
                                   spans);
                        for (int r = 0; r < b.rows; ++r) {
                            const Span& span = spans[static_cast<std::size_t>(r) * c.offsets.size() +
                                                     static_cast<std::size_t>(s)];
                            const std::uint64_t expected = span_bits(span.lo, span.hi, b.i0);
                            ASSERT_EQ(masks[r], expected) << name(precision) << " triangle " << n << " row " << r;
                            ASSERT_EQ(evaluated[r], expected) << name(precision) << " triangle " << n << " row " << r;
                            ASSERT_EQ(fixed_row_coverage(edges.q, edges.p, edges.step, b.width, r), expected)
                                << name(precision) << " triangle " << n << " row " << r;
                            partly_covered += expected != 0 && expected != first_bits(b.width);
                        }
                        for (const WideEdge& f : *near) {
                            const Int128 value = Int128{f.a} * b.i0 + Int128{f.b} * b.j0 +
                                                 offset_term(f, c.bits, c.sx[static_cast<std::size_t>(s)],
                                                             c.sy[static_cast<std::size_t>(s)]);
                            const Int128 magnitude = value < 0 ? -value : value;
                            clamped += magnitude > kWideClamp;
                            beyond_64_bits += magnitude >> 63 != 0;
                        }
                    }
                }
            }
        // The cases are not all trivial: rows the edges cut, edges whose values at a block were clamped,
        // some beyond 64 bits, and triangles just past the limit.
        EXPECT_GT(partly_covered, 10000);
        EXPECT_GT(clamped, 1000);
        EXPECT_GT(beyond_64_bits, 1000);
        EXPECT_GT(without, 50);
    });
}

// The whole-tile test on near edges, against the spans: a rejected tile holds no covered sample, an
// accepted one only covered samples, at every sample index; tiles around the edges' points, with 1, 4 and
// 16 samples, where the sample offsets' own terms (WideEdge::least, greatest) differ.
TEST(WideRows, NearEdgesClassifyTilesAsTheirSpansDo) {
    std::mt19937_64 rng(20261130);
    int rejected = 0, accepted = 0;
    for (const Precision precision : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
        for (const int samples : {1, 4, 16}) {
            const Context c = make_context<Fault::none>({kSide, kSide}, samples, precision);
            for (int n = 0; n < 200; ++n) {
                const std::optional<Placed> placed =
                    place<Fault::none>(Triangle{wide_triangle(rng, c, 50 - c.bits)}, c);
                // Those without near edges left out before their setup, which would find their spans' bands
                // down the whole viewport.
                if (!placed || placed->path != Path::wide ||
                    !wide_edges(placed->v, c.bits, owning_edges<Fault::none>(placed->v), c.sx, c.sy))
                    continue;
                const detail::Setup t = setup_triangle<Fault::none>(*placed, c, true);
                for (int trial = 0; trial < 8; ++trial) {
                    const Block b = random_block(rng, c, t.p.v, 0);
                    const int i1 = b.i0 + b.width - 1, j1 = b.j0 + b.rows - 1;
                    const TileClass cls = classify(t, c, b.i0, i1, b.j0, j1);
                    if (cls == TileClass::partial) continue;
                    std::vector<Span> spans(static_cast<std::size_t>(b.rows) * c.offsets.size());
                    wide_spans(t.p.v, c.bits, t.owns, c.offsets, b.i0, i1, b.j0, j1, spans);
                    for (const Span& span : spans) {
                        if (cls == TileClass::reject) ASSERT_GT(span.lo, span.hi) << name(precision) << " " << n;
                        else ASSERT_TRUE(span.lo == b.i0 && span.hi == i1) << name(precision) << " " << n;
                    }
                    ++(cls == TileClass::reject ? rejected : accepted);
                }
            }
        }
    EXPECT_GT(rejected, 500);
    EXPECT_GT(accepted, 500);
}

}  // namespace
}  // namespace rast::fast::detail
