// SceneOccluders (occluders.h): whatever the number of chunks a scene is binned in, each tile's occluders
// are those of the scene whose box reaches it, nearest centroid first (the mean of the corners' depths,
// taken in thirds), then lower id first, each with its own setup. The expectation is built triangle by
// triangle from place() and is_occluder, apart from the chunks; the depths come from a few values so that
// ties between occluders are common. One SceneOccluders and one set of chunks go through every case, as
// a Renderer's do from render to render.
#include "occluders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <tuple>
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

// The scene's occluders, placed as a chunk would place them: each tile's (centroid's depth, id),
// sorted, and each triangle's placement.
struct Expected {
    std::vector<std::vector<std::pair<double, std::int32_t>>> bins;
    std::vector<std::optional<Placed>> placed;
    std::size_t occluders = 0;
};

Expected expected(const std::vector<Triangle>& triangles, const Context& c, std::size_t tiles_x, std::size_t tiles_y) {
    Expected e{std::vector<std::vector<std::pair<double, std::int32_t>>>(tiles_x * tiles_y),
               std::vector<std::optional<Placed>>(triangles.size())};
    for (std::size_t id = 0; id < triangles.size(); ++id) {
        const std::optional<Placed> p = e.placed[id] = place<Fault::none>(triangles[id], c);
        if (!p || is_small(*p) || !is_occluder(*p)) continue;
        ++e.occluders;
        const double z = p->v[0].z / 3 + p->v[1].z / 3 + p->v[2].z / 3;
        for (int ty = p->j_lo / kTile; ty <= p->j_hi / kTile; ++ty)
            for (int tx = p->i_lo / kTile; tx <= p->i_hi / kTile; ++tx)
                e.bins[static_cast<std::size_t>(ty) * tiles_x + tx].emplace_back(z, static_cast<std::int32_t>(id));
    }
    for (auto& bin : e.bins) std::sort(bin.begin(), bin.end());
    return e;
}

// Tile by tile, the order's entries against the expected ones; answers how many there were.
std::size_t expect_bins(const SceneOccluders& order, const Expected& want, const std::string& what) {
    std::size_t entries = 0;
    for (std::size_t tile = 0; tile < want.bins.size(); ++tile) {
        const std::span<const SceneOccluders::Entry> got = order.of(tile);
        EXPECT_EQ(got.size(), want.bins[tile].size()) << what << ", tile " << tile;
        if (got.size() != want.bins[tile].size()) return entries;
        for (std::size_t k = 0; k < got.size(); ++k) {
            EXPECT_EQ(got[k].id, want.bins[tile][k].second) << what << ", tile " << tile << ", entry " << k;
            if (got[k].id != want.bins[tile][k].second) return entries;
            const Placed &p = got[k].setup->p, &q = *want.placed[static_cast<std::size_t>(got[k].id)];
            EXPECT_EQ(std::tie(p.i_lo, p.i_hi, p.j_lo, p.j_hi), std::tie(q.i_lo, q.i_hi, q.j_lo, q.j_hi)) << what;
            for (int corner = 0; corner < 3; ++corner)  // the setup is this triangle's
                EXPECT_EQ(std::tie(p.v[corner].x, p.v[corner].y, p.v[corner].z),
                          std::tie(q.v[corner].x, q.v[corner].y, q.v[corner].z))
                    << what;
        }
        entries += got.size();
    }
    return entries;
}

TEST(Occluders, EachTileHasTheSceneOccludersReachingItNearestFirstForAnyChunkCount) {
    std::mt19937_64 rng(20261127);
    std::size_t occluders = 0, entries = 0;
    SceneOccluders order;
    std::vector<Chunk> chunks;
    for (const Precision precision : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
        for (const Viewport vp : {Viewport{256, 256}, Viewport{300, 177}, Viewport{40, 30}, Viewport{64, 700}})
            for (int trial = 0; trial < 4; ++trial) {
                const Context c = make_context<Fault::none>(vp, 1, precision);
                const std::vector<Triangle> triangles = big_triangles(rng, vp, 1 + rng() % 120);
                const SceneView scene{triangles, c};
                const std::size_t tiles_x = (vp.width + kTile - 1) / kTile, tiles_y = (vp.height + kTile - 1) / kTile;
                const Expected want = expected(triangles, c, tiles_x, tiles_y);
                occluders += want.occluders;
                for (const std::size_t chunk_count : {1, 2, 3, 7}) {
                    chunks.resize(chunk_count);
                    const std::size_t n = triangles.size();
                    for (std::size_t k = 0; k < chunk_count; ++k)
                        bin_chunk<Fault::none>(chunks[k], k * n / chunk_count, (k + 1) * n / chunk_count, scene,
                                               tiles_x, tiles_x * tiles_y);
                    order.gather(chunks, tiles_x, tiles_x * tiles_y);
                    // In ranges of one to four rows, the last one ending at the screen's last row.
                    for (int ty = 0, rows = static_cast<int>(tiles_y); ty < rows;) {
                        const int end = std::min(rows, ty + 1 + static_cast<int>(rng() % 4));
                        order.bin_rows(ty, end);
                        ty = end;
                    }
                    entries += expect_bins(order, want,
                                           "precision " + std::to_string(static_cast<int>(precision)) + ", viewport " +
                                               std::to_string(vp.width) + "x" + std::to_string(vp.height) + ", trial " +
                                               std::to_string(trial) + ", " + std::to_string(chunk_count) + " chunks");
                    if (HasFailure()) return;
                }
            }
    EXPECT_GT(occluders, 300u);  // the scenes hold occluders, and tiles many of them
    EXPECT_GT(entries, 4000u);
}

}  // namespace
}  // namespace rast::fast::detail
