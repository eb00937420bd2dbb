// stamp_masks (stamp.h) against the scalar definition of a block's coverage, fixed_edges then
// fixed_edges_at and fixed_row_coverage (setup.h, coverage.h, scalar.h), on every SIMD target: every
// narrow triangle's block and edges, which triangles of a run get stamps (narrow, and their block within
// the tile at most 8 x 8 and 16 pixels), and for those, every sample of every row and their blocks'
// samples in all, for each fixed mode and sample count, the masks found either way (stamps_at_once).
// Corners on sample positions and level edges put samples exactly on edges, where only the tie rule
// decides; triangles straddle the tile's sides, and blocks from 1 x 9 to 9 x 9 pixels sit either side of
// the stamp's limits.
#include "compose.h"
#include "targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

// A triangle near the tile, its corners often on sample positions or sharing a row.
Triangle random_triangle(std::mt19937_64& rng, const Context& c, const TileRect& rect) {
    std::uniform_real_distribution<double> where(rect.i0 - 8, rect.i1 + 9), unit(-1, 1);
    std::uniform_int_distribution<int> kind(0, 3);
    const double cx = where(rng), cy = where(rng) - rect.i0 + rect.j0;
    // Reaches from tiny to 9 pixels, and slivers 9 pixels long.
    const double reaches[][2] = {{1.2, 1.2}, {2, 2}, {4.5, 4.5}, {4.5, 0.6}, {0.6, 4.5}};
    const auto& reach = reaches[rng() % 5];
    Triangle t;
    for (Vertex& v : t.v) {
        v = {cx + reach[0] * unit(rng), cy + reach[1] * unit(rng), 0.5};
        if (kind(rng) == 0) {  // on a sample of its pixel
            const SamplePoint o = c.offsets[rng() % c.offsets.size()];
            v.x = std::floor(v.x) + o.x;
            v.y = std::floor(v.y) + o.y;
        }
    }
    if (kind(rng) == 0) t.v[1].y = t.v[0].y;  // a level edge
    return t;
}

TEST(Stamps, EqualTheScalarCoverageOnEveryTarget) {
    // A tile inside a small viewport, and the last tile of one as large as fixed16's range allows, where
    // the block's first sample in grid units is largest.
    struct Where {
        Viewport vp;
        TileRect rect;
    };
    const Where places[] = {{{256, 256}, {64, 127, 64, 127}}, {{8128, 8128}, {8064, 8127, 8064, 8127}}};
    on_every_target([&] {
        std::mt19937_64 rng(20261127);
        int stamped = 0, refused = 0, on_edge = 0;
        int at_once = 0, one_at_a_time = 0;  // runs whose stamps stamp_masks finds either way (stamps_at_once)
        for (const auto& [vp, rect] : places)
            for (const Precision precision : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
                for (const int samples : {1, 4, 8, 16}) {
                    const Context c = make_context<Fault::none>(vp, samples, precision);
                    ASSERT_TRUE(c.fixed_fits);
                    for (int trial = 0; trial < 200; ++trial) {
                        std::vector<SmallFixed> run;
                        while (run.size() < static_cast<std::size_t>(1 + trial % kPlaneBatch)) {
                            SmallFixed record;
                            const Triangle t = random_triangle(rng, c, rect);
                            if (place_small_fixed<Fault::none>(t, 7, c, record) == Lane::small_fixed &&
                                record.i_hi >= rect.i0 && record.i_lo <= rect.i1 && record.j_hi >= rect.j0 &&
                                record.j_lo <= rect.j1)
                                run.push_back(record);
                        }
                        Plane planes[kPlaneBatch];
                        PlaneBatch batch;
                        const std::uint32_t narrow = small_planes(run, c, planes, batch);
                        StampMasks stamps;
                        if (narrow != 0) stamps.find(batch, narrow, rect, c);  // as render_tile calls it
                        std::size_t block_samples = 0;
                        int widest = 0, tallest = 0, count = 0, rows_each = 0;
                        for (std::size_t k = 0; k < run.size(); ++k) {
                            const SmallFixed& t = run[k];
                            const int i0 = std::max(rect.i0, t.i_lo), i1 = std::min(rect.i1, t.i_hi);
                            const int j0 = std::max(rect.j0, t.j_lo), j1 = std::min(rect.j1, t.j_hi);
                            const bool fits = i1 - i0 < kStampSide && j1 - j0 < kStampSide &&
                                              (i1 - i0 + 1) * (j1 - j0 + 1) <= kScalarSamples;
                            const bool want = (narrow >> k & 1) && fits;
                            ASSERT_EQ((stamps.triangles >> k & 1) != 0, want) << "trial " << trial << " triangle " << k;
                            if (want) {
                                ++stamped;
                                block_samples += static_cast<std::size_t>((i1 - i0 + 1) * (j1 - j0 + 1) * samples);
                                widest = std::max(widest, i1 - i0 + 1);
                                tallest = std::max(tallest, j1 - j0 + 1);
                                ++count;
                                rows_each += j1 - j0 + 1;
                            } else {
                                ++refused;
                            }
                            const std::array<FixedEdge, 3> edges = fixed_edges<Fault::none>(t.x, t.y);
                            for (int s = 0; s < samples && (narrow >> k & 1); ++s) {
                                const Block b{i0, j0, i1 - i0 + 1, j1 - j0 + 1, c.offsets[s].x, c.offsets[s].y};
                                std::int64_t e[3], dx[3], dy[3];
                                fixed_edges_at(edges, c, b, s, e, dx, dy);
                                // Every narrow triangle's block and its edges, as rasterize_small takes
                                // them for depth_small.
                                const StampEdges& set_up = stamps.edges[s];
                                ASSERT_EQ(set_up.width[k], b.width) << "trial " << trial << " triangle " << k;
                                ASSERT_EQ(set_up.rows[k], b.rows) << "trial " << trial << " triangle " << k;
                                const SmallEdges lane = small_edges(set_up, static_cast<int>(k));
                                for (int m = 0; m < 3; ++m) {
                                    ASSERT_EQ(lane.e[m], e[m]) << "trial " << trial << " triangle " << k;
                                    ASSERT_EQ(lane.dx[m], dx[m]) << "trial " << trial << " triangle " << k;
                                    ASSERT_EQ(lane.dy[m], dy[m]) << "trial " << trial << " triangle " << k;
                                }
                                if (!want) continue;
                                const std::uint64_t mask = stamps.masks[s][k];
                                for (int r = 0; r < kStampSide; ++r) {
                                    const std::uint64_t got = mask >> (kStampSide * r) & first_bits(kStampSide);
                                    const std::uint64_t row =
                                        r < b.rows ? fixed_row_coverage(e, dx, dy, b.width, r) : 0;
                                    ASSERT_EQ(got, row) << "trial " << trial << " triangle " << k << " sample " << s
                                                        << " row " << r;
                                    for (int col = 0; col < b.width && r < b.rows; ++col) {
                                        bool on = false;
                                        for (int k = 0; k < 3; ++k) {
                                            const std::int64_t v = e[k] + col * dx[k] + r * dy[k];
                                            on = on || v == 0 || v == -1;
                                        }
                                        on_edge += on;
                                    }
                                }
                            }
                        }
                        ASSERT_EQ(stamps.samples, block_samples) << "trial " << trial;
                        if (count > 0) ++(stamps_at_once(widest, tallest, count, rows_each) ? at_once : one_at_a_time);
                    }
                }
        // Both outcomes are common, and many samples lie on an edge or beside it (E = 0 or -1, the bias
        // included).
        EXPECT_GT(stamped, 3000) << refused;
        EXPECT_GT(refused, 300) << stamped;
        EXPECT_GT(on_edge, 1000);
        // Both ways of finding a run's masks are held to the definition.
        EXPECT_GT(at_once, 500) << one_at_a_time;
        EXPECT_GT(one_at_a_time, 500) << at_once;
    });
}

}  // namespace
}  // namespace rast::fast::detail
