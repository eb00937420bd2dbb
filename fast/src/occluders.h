// The scene's occluders (is_occluder, binning.h) in one order, nearest first, binned per tile: a tile
// composes them before its other triangles (render_tile, engine.h). The (z, id) order makes the
// framebuffer the same whatever order a tile composes its triangles in; composed first and nearest first,
// the occluders soon cover the tile, and its far depth (behind_tile) rejects more of the later triangles
// whole (docs/speed-history.md). One order for the whole scene, whatever the number of chunks: each chunk
// sorting its own made two threads compose every chunk's nearest occluders in turn, and merging the
// chunks' sorted bins in each tile cost more than it saved on scenes of many occluders.
#pragma once

#include "binning.h"
#include "setup.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rast::fast::detail {

class SceneOccluders {
public:
    // An occluder in a tile's bin.
    struct Entry {
        const Setup* setup;
        std::int32_t id;
    };

    // Takes every chunk's occluders, the chunks binned in full (their setups do not move until they are
    // binned again), and sorts them by their depth at the centroid, the mean of their corners' (finite:
    // render checked them; the sum of thirds may still round to an infinity, never to NaN), then id: tbb's
    // sort, in the caller's task arena.
    // By their nearest corner's depth, a steep triangle came before others that hide most of it: 10^3
    // random occluders of radius 64-128 px wrote 26% more samples.
    void gather(std::span<const Chunk> chunks, std::size_t tiles_x, std::size_t tiles) {
        tiles_x_ = tiles_x;
        bins_.resize(tiles);
        sorted_.clear();
        for (const Chunk& chunk : chunks)
            for (const BigEntry& o : chunk.occluders) {
                const Setup& s = chunk.big[o.setup];
                const Corners& v = s.p.v;
                sorted_.push_back({v[0].z / 3 + v[1].z / 3 + v[2].z / 3, o.id, &s, tile_of(s.p.i_lo), tile_of(s.p.i_hi),
                                   tile_of(s.p.j_lo), tile_of(s.p.j_hi)});
            }
        tbb::parallel_sort(sorted_.begin(), sorted_.end());
    }

    // Fills the bins of rows [ty0, ty1) of tiles with the sorted occluders that reach them, in order, in
    // one pass over them (a pass per row would cost rows x occluders on a tall screen). Ranges of rows
    // are independent: threads may bin them at once.
    void bin_rows(int ty0, int ty1) {
        for (auto bin = bins_.begin() + ty0 * tiles_x_; bin != bins_.begin() + ty1 * tiles_x_; ++bin) bin->clear();
        for (const Ranked& r : sorted_)
            for (int ty = std::max(r.ty0, ty0); ty <= std::min(r.ty1, ty1 - 1); ++ty)
                for (int tx = r.tx0; tx <= r.tx1; ++tx)
                    append(bins_[static_cast<std::size_t>(ty) * tiles_x_ + tx], {r.setup, r.id});
    }

    // Tile `index`'s occluders, nearest first.
    std::span<const Entry> of(std::size_t index) const { return bins_[index]; }

private:
    struct Ranked {
        double z;
        std::int32_t id;
        const Setup* setup;
        int tx0, tx1, ty0, ty1;  // the tiles its box reaches
        bool operator<(const Ranked& o) const { return z < o.z || (z == o.z && id < o.id); }
    };
    std::size_t tiles_x_ = 0;
    std::vector<Ranked> sorted_;
    std::vector<std::vector<Entry>> bins_;
};

}  // namespace rast::fast::detail
