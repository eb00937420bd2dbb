// bin_chunk (binning.h) as the library runs it, placing eight triangles at a time (place_batch.h), against
// the same function placing one at a time, as the faulty twins do (Fault::float_row_accumulation changes
// nothing in binning), in the fixed and the float modes: the same records in the same bins in the same
// order, and the same first bad triangle. The scenes mix tiny, small and big triangles with far-reaching
// ones whose box is clipped small (the batch leaves them undecided, and place_small_fixed finds many of
// them small), on viewports down to one tile and below the small lane's 32 pixels, with a depth or
// coordinate that is not finite at a random place in some.
#include "binning.h"
#include "targets.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

std::vector<Triangle> random_scene(std::mt19937_64& rng, const Context& c, std::size_t n) {
    std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
    const double w = c.vp.width, h = c.vp.height;
    std::vector<Triangle> scene(n);
    for (Triangle& t : scene) {
        const double cx = unit(rng) * w, cy = unit(rng) * h;
        const int shape = static_cast<int>(rng() % 4);
        for (int k = 0; k < 3; ++k) {
            Vertex& v = t.v[k];
            v.z = unit(rng);
            if (shape == 3 && k > 0) {  // far out: a box clipped small at the viewport's far corner
                v.x = w - 1 + c.coordinate_limit * unit(rng);
                v.y = h - 1 + c.coordinate_limit * unit(rng);
            } else {
                const double reach = shape == 0 ? 2 : shape == 1 ? 12 : shape == 2 ? 80 : 1;
                v.x = (shape == 3 ? w - 1 : cx) + reach * signed_unit(rng);
                v.y = (shape == 3 ? h - 1 : cy) + reach * signed_unit(rng);
            }
        }
    }
    if (rng() % 3 == 0) {  // one coordinate that is not finite
        const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
        double* field = &scene[rng() % n].v[rng() % 3].x + rng() % 3;
        *field = bad[rng() % 2];
    }
    return scene;
}

void expect_same_bins(const Chunk& got, const Chunk& want, const std::string& what) {
    ASSERT_EQ(got.non_finite, want.non_finite) << what;
    if (want.non_finite) return;  // the bins are not read then
    ASSERT_EQ(got.fixed_bins.size(), want.fixed_bins.size()) << what;
    for (std::size_t tile = 0; tile < want.fixed_bins.size(); ++tile) {
        const auto& g = got.fixed_bins[tile];
        const auto& e = want.fixed_bins[tile];
        ASSERT_EQ(g.size(), e.size()) << what << " tile " << tile;
        for (std::size_t k = 0; k < e.size(); ++k) {
            ASSERT_EQ(g[k].id, e[k].id) << what << " tile " << tile << " entry " << k;
            for (int corner = 0; corner < 3; ++corner) {
                ASSERT_EQ(g[k].x[corner], e[k].x[corner]) << what;
                ASSERT_EQ(g[k].y[corner], e[k].y[corner]) << what;
                ASSERT_EQ(std::bit_cast<std::uint64_t>(g[k].z[corner]), std::bit_cast<std::uint64_t>(e[k].z[corner]))
                    << what;
            }
            ASSERT_EQ(g[k].i_lo, e[k].i_lo) << what;
            ASSERT_EQ(g[k].i_hi, e[k].i_hi) << what;
            ASSERT_EQ(g[k].j_lo, e[k].j_lo) << what;
            ASSERT_EQ(g[k].j_hi, e[k].j_hi) << what;
            ASSERT_EQ(g[k].narrow, e[k].narrow) << what;
        }
    }
    for (std::size_t tile = 0; tile < want.small_bins.size(); ++tile) {
        const auto& g = got.small_bins[tile];
        const auto& e = want.small_bins[tile];
        ASSERT_EQ(g.size(), e.size()) << what;
        for (std::size_t k = 0; k < e.size(); ++k) {
            ASSERT_EQ(g[k].id, e[k].id) << what;
            for (int corner = 0; corner < 3; ++corner)
                for (const auto field : {&Vertex::x, &Vertex::y, &Vertex::z})
                    ASSERT_EQ(std::bit_cast<std::uint64_t>(g[k].p.v[corner].*field),
                              std::bit_cast<std::uint64_t>(e[k].p.v[corner].*field))
                        << what;
            ASSERT_EQ(g[k].p.i_lo, e[k].p.i_lo) << what;
            ASSERT_EQ(g[k].p.i_hi, e[k].p.i_hi) << what;
            ASSERT_EQ(g[k].p.j_lo, e[k].p.j_lo) << what;
            ASSERT_EQ(g[k].p.j_hi, e[k].p.j_hi) << what;
            ASSERT_EQ(g[k].p.path, e[k].p.path) << what;
        }
    }
    for (std::size_t tile = 0; tile < want.big_bins.size(); ++tile) {
        ASSERT_EQ(got.big_bins[tile].size(), want.big_bins[tile].size()) << what;
        for (std::size_t k = 0; k < want.big_bins[tile].size(); ++k)
            ASSERT_EQ(got.big_bins[tile][k].id, want.big_bins[tile][k].id) << what;
    }
    ASSERT_EQ(got.occluders.size(), want.occluders.size()) << what;
    for (std::size_t k = 0; k < want.occluders.size(); ++k) {
        ASSERT_EQ(got.occluders[k].id, want.occluders[k].id) << what;
        const Corners& g = got.big[got.occluders[k].setup].p.v;  // the setup its depth order is taken from
        const Corners& e = want.big[want.occluders[k].setup].p.v;
        for (int corner = 0; corner < 3; ++corner)
            ASSERT_EQ(std::bit_cast<std::uint64_t>(g[corner].z), std::bit_cast<std::uint64_t>(e[corner].z)) << what;
    }
}

TEST(Binning, EightAtATimeEqualsOneAtATime) {
    on_every_target([&] {
        std::mt19937_64 rng(20261127);
        std::size_t small_from_undecided = 0, undecided_lanes = 0;
        for (const Precision precision :
             {Precision::fixed4, Precision::fixed8, Precision::fixed16, Precision::float32, Precision::float64})
            for (const Viewport vp : {Viewport{100, 100}, Viewport{30, 20}, Viewport{300, 177}})
                for (const int samples : {1, 8}) {
                    const Context c = make_context<Fault::none>(vp, samples, precision);
                    const PlaceGrid grid = place_grid(c);
                    for (int trial = 0; trial < 20; ++trial) {
                        const std::vector<Triangle> triangles = random_scene(rng, c, 1 + rng() % 200);
                        const SceneView scene{triangles, c};
                        const std::size_t tiles_x = (vp.width + kTile - 1) / kTile;
                        const std::size_t tiles = tiles_x * ((vp.height + kTile - 1) / kTile);
                        Chunk got, want;
                        // A chunk from an id past 0, as the second of several would be.
                        const std::size_t begin = rng() % 3 == 0 ? triangles.size() / 3 : 0;
                        bin_chunk<Fault::none>(got, begin, triangles.size(), scene, tiles_x, tiles);
                        bin_chunk<Fault::float_row_accumulation>(want, begin, triangles.size(), scene, tiles_x, tiles);
                        expect_same_bins(got, want, "trial " + std::to_string(trial));
                        if (HasFatalFailure()) return;
                        // How often the fixed modes' undecided lanes were small: the case that must keep
                        // the order.
                        for (std::size_t id = begin; is_fixed(precision) && id < triangles.size(); id += kPlaceBatch) {
                            PlacedBatch batch;
                            const int n = static_cast<int>(std::min<std::size_t>(kPlaceBatch, triangles.size() - id));
                            place_small_batch(&triangles[id], n, grid, batch);
                            for (int k = 0; k < n; ++k) {
                                if (!(batch.undecided >> k & 1)) continue;
                                ++undecided_lanes;
                                SmallFixed record;
                                const Lane lane = place_small_fixed<Fault::none>(triangles[id + k], 0, c, record);
                                small_from_undecided += lane == Lane::small_fixed;
                            }
                        }
                    }
                }
        EXPECT_GT(small_from_undecided, 100u) << undecided_lanes;
    });
}

}  // namespace
}  // namespace rast::fast::detail
