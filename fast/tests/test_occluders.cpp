// SceneOccluders (occluders.h): whatever the number of chunks a scene is binned in, each tile's occluders
// are those of the scene whose box reaches it, nearest corner's depth first, then lower id first. The
// expectation is built triangle by triangle from place() and is_occluder, apart from the chunks; the
// depths come from a few values so that ties between occluders are common.
#include "occluders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace rast::fast::detail {
namespace {

std::vector<Triangle> big_triangles(std::mt19937_64& rng, Viewport vp, std::size_t n) {
    std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
    const double depths[] = {0.25, 0.5, 0.75};
    std::vector<Triangle> scene(n);
    for (Triangle& t : scene) {
        // Radius 20 to 150 px: some below a tile's area (not occluders), some reaching off the screen.
        const double cx = unit(rng) * vp.width, cy = unit(rng) * vp.height, r = 20 + 130 * unit(rng);
        for (Vertex& v : t.v) v = {cx + r * signed_unit(rng), cy + r * signed_unit(rng), depths[rng() % 3]};
    }
    return scene;
}

TEST(Occluders, EachTileHasTheSceneOccludersReachingItNearestFirstForAnyChunkCount) {
    std::mt19937_64 rng(20261127);
    std::size_t occluders = 0, entries = 0;
    for (const Viewport vp : {Viewport{256, 256}, Viewport{300, 177}, Viewport{40, 30}})
        for (int trial = 0; trial < 10; ++trial) {
            const Context c = make_context<Fault::none>(vp, 1, Precision::fixed8);
            const std::vector<Triangle> triangles = big_triangles(rng, vp, 1 + rng() % 120);
            const SceneView scene{triangles, c};
            const std::size_t tiles_x = (vp.width + kTile - 1) / kTile;
            const std::size_t tiles_y = (vp.height + kTile - 1) / kTile;

            // (nearest corner's depth, id) of each occluder reaching a tile, sorted.
            std::vector<std::vector<std::pair<double, std::int32_t>>> want(tiles_x * tiles_y);
            for (std::size_t id = 0; id < triangles.size(); ++id) {
                const std::optional<Placed> p = place<Fault::none>(triangles[id], c);
                if (!p || is_small(*p) || !is_occluder(*p)) continue;
                ++occluders;
                const double z = std::min({p->v[0].z, p->v[1].z, p->v[2].z});
                for (int ty = p->j_lo / kTile; ty <= p->j_hi / kTile; ++ty)
                    for (int tx = p->i_lo / kTile; tx <= p->i_hi / kTile; ++tx)
                        want[static_cast<std::size_t>(ty) * tiles_x + tx].emplace_back(z, static_cast<std::int32_t>(id));
            }
            for (auto& bin : want) std::sort(bin.begin(), bin.end());

            for (const std::size_t chunk_count : {1, 2, 3, 7}) {
                const std::string what = "viewport " + std::to_string(vp.width) + "x" + std::to_string(vp.height) +
                                         ", trial " + std::to_string(trial) + ", " + std::to_string(chunk_count) +
                                         " chunks";
                std::vector<Chunk> chunks(chunk_count);
                const std::size_t n = triangles.size();
                for (std::size_t k = 0; k < chunk_count; ++k)
                    bin_chunk<Fault::none>(chunks[k], k * n / chunk_count, (k + 1) * n / chunk_count, scene, tiles_x,
                                           tiles_x * tiles_y);
                SceneOccluders order;
                order.gather(chunks, tiles_x, tiles_x * tiles_y);
                for (std::size_t ty = 0; ty < tiles_y; ++ty) order.bin_row(ty);
                for (std::size_t tile = 0; tile < want.size(); ++tile) {
                    const std::span<const SceneOccluders::Entry> got = order.of(tile);
                    ASSERT_EQ(got.size(), want[tile].size()) << what << ", tile " << tile;
                    for (std::size_t k = 0; k < got.size(); ++k) {
                        ASSERT_EQ(got[k].id, want[tile][k].second) << what << ", tile " << tile << ", entry " << k;
                        const Corners& v = got[k].setup->p.v;  // the setup is this triangle's
                        ASSERT_EQ(std::min({v[0].z, v[1].z, v[2].z}), want[tile][k].first) << what;
                    }
                    entries += got.size();
                }
            }
        }
    EXPECT_GT(occluders, 300u);  // the scenes hold occluders, and tiles many of them
    EXPECT_GT(entries, 4000u);
}

}  // namespace
}  // namespace rast::fast::detail
