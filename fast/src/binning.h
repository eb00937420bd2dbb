// Binning, one stage of the fast path (engine.h): each triangle of a contiguous id range placed, set up
// where it is big, and appended to the bins of the screen tiles its bounding box reaches, in id order
// (the occluders set aside for occluders.h, which orders them over the whole scene).
#pragma once

#include "place_batch.h"
#include "setup.h"
#include "validate.h"

#include <rast/fast_faults.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace rast::fast::detail {

inline bool is_small(const Placed& p) { return p.path != Path::wide && is_small(p.i_lo, p.i_hi, p.j_lo, p.j_hi); }

struct SmallTriangle {
    Placed p;
    std::int32_t id;
};

// A big triangle's entry in a tile's bin: its id beside the index of its setup, so that merging the
// bins by id reads no setup it does not rasterize yet.
struct BigEntry {
    std::int32_t id;
    std::uint32_t setup;  // index into Chunk::big
};

// The triangles of one contiguous id range, binned per tile in id order but for the occluders, listed
// apart in id order.
struct Chunk {
    std::optional<std::size_t> non_finite;  // the first triangle with a non-finite coordinate: binning stopped there
    std::vector<Setup> big;
    std::vector<std::vector<SmallFixed>> fixed_bins;
    std::vector<std::vector<SmallTriangle>> small_bins;
    std::vector<std::vector<BigEntry>> big_bins;
    std::vector<BigEntry> occluders;  // is_occluder's, set up in big
};

// An occluder: a triangle of a tile's area or more, which with a few like it covers a tile (its area off
// the screen counts too: a heuristic). Taking boxes of two tiles each way instead let long thin
// triangles in, which cover little.
inline bool is_occluder(const Placed& p) {
    return twice_area(p.v) >= 2.0 * kTile * kTile;  // placed corners are counter-clockwise
}

inline constexpr std::uintptr_t kCacheLine = 64;

// Starts loading every cache line of the bytes [address, address + size), size > 0, for writing if
// kWrite: an address every 64 bytes and the last byte, so that no line is skipped, in a loop whose trip
// count depends on the size alone (unrolled where it is a constant; stepping over the lines themselves
// depended on the alignment and cost 4% of a tiny triangle's instructions). An address, not a pointer:
// it may lie past an array's end, and a prefetch never faults.
template <bool kWrite = false>
void prefetch_bytes(std::uintptr_t address, std::size_t size) {
    for (std::size_t offset = 0; offset < size; offset += kCacheLine)
        __builtin_prefetch(reinterpret_cast<const void*>(address + offset), kWrite);
    __builtin_prefetch(reinterpret_cast<const void*>(address + size - 1), kWrite);
}

// Appends to a tile's bin. The bins are written at as many places as there are tiles, each cache line
// for the first time: the lines of the record kAppendAhead places after this one are fetched now, for
// writing, rather than when that record comes. Binning small triangles spent twice its share of
// instructions in time; fetching the next record's last line only missed the line a record starts every
// 64 / gcd(64, size) records, and came too late to hide the writes (tiny triangles' rendering 4% faster
// three records ahead).
inline constexpr std::size_t kAppendAhead = 3;

template <class Record>
void append(std::vector<Record>& bin, const Record& record) {
    bin.push_back(record);
    const std::uintptr_t next = reinterpret_cast<std::uintptr_t>(bin.data() + bin.size());
    prefetch_bytes<true>(next + (kAppendAhead - 1) * sizeof(Record), sizeof(Record));
}

// What place_small_batch needs of the context.
inline PlaceGrid place_grid(const Context& c) {
    return {double(std::int64_t{1} << c.bits), c.unit, c.coordinate_limit,
            double(c.sx_min), double(c.sx_max), double(c.sy_min), double(c.sy_max),
            double(c.vp.width), double(c.vp.height), double(kSmallSide)};
}

// What place_float_batch needs of the context: the grid is the pixel.
inline PlaceGrid float_place_grid(const Context& c) {
    return {1, 1, std::numeric_limits<double>::infinity(), c.ox_min, c.ox_max, c.oy_min, c.oy_max,
            double(c.vp.width), double(c.vp.height), double(kSmallSide)};
}

// Lane k of a batch (place_batch.h) as place_small_fixed would have filled its record.
inline SmallFixed small_fixed_of(const PlacedBatch& b, int k, std::int32_t id) {
    SmallFixed s;
    for (int corner = 0; corner < 3; ++corner) {
        s.z[corner] = b.z[corner][k];
        s.x[corner] = b.x[corner][k];
        s.y[corner] = b.y[corner][k];
    }
    s.i_lo = b.i_lo[k];
    s.i_hi = b.i_hi[k];
    s.j_lo = b.j_lo[k];
    s.j_hi = b.j_hi[k];
    s.id = id;
    s.narrow = b.narrow >> k & 1;
    return s;
}

// The screen tile of a pixel index inside the viewport, which is not negative: unsigned division is a
// shift.
inline int tile_of(int pixel) { return static_cast<int>(static_cast<unsigned>(pixel) / kTile); }

// Places the triangles [begin, end), appends each to its tiles' bins and sets up the big ones into
// chunk.big; the occluders go to chunk.occluders.
template <Fault F>
void bin_triangles(Chunk& chunk, std::size_t begin, std::size_t end, const SceneView& scene, std::size_t tiles_x,
                   std::size_t tiles) {
    const bool lean = is_fixed(scene.c.precision) && scene.c.fixed_fits;
    if (lean) {
        // Room for a uniform spread with some slack, so that most bins never reallocate and copy; pages
        // of it never written are never touched.
        const std::size_t expected = (end - begin) / tiles;
        for (std::vector<SmallFixed>& bin : chunk.fixed_bins) bin.reserve(expected + expected / 2 + 8);
    }
    const auto bin_small_placed = [&](const Placed& placed, std::size_t id) {
        for (int ty = tile_of(placed.j_lo); ty <= tile_of(placed.j_hi); ++ty)
            for (int tx = tile_of(placed.i_lo); tx <= tile_of(placed.i_hi); ++tx)
                append(chunk.small_bins[static_cast<std::size_t>(ty) * tiles_x + tx],
                       {placed, static_cast<std::int32_t>(id)});
    };
    const auto bin_small = [&](const SmallFixed& record) {
        for (int ty = tile_of(record.j_lo); ty <= tile_of(record.j_hi); ++ty)
            for (int tx = tile_of(record.i_lo); tx <= tile_of(record.i_hi); ++tx)
                append(chunk.fixed_bins[static_cast<std::size_t>(ty) * tiles_x + tx], record);
    };
    // Triangle id, placed in `lane` (and `record` where it is small_fixed), into the bins; false where a
    // coordinate is not finite, which stops the binning.
    const auto bin = [&](std::size_t id, Lane lane, const SmallFixed& record) {
        const Triangle& triangle = scene.triangles[id];
        // Checked here rather than in a pass of its own: the triangles are read once. The small lane
        // only takes corners whose x and y are within the fixed range, hence finite.
        const bool finite = lane == Lane::general ? is_finite(triangle)
                                                  : std::isfinite(triangle.v[0].z) && std::isfinite(triangle.v[1].z) &&
                                                        std::isfinite(triangle.v[2].z);
        if (!finite) {
            chunk.non_finite = id;
            return false;
        }
        if (lane == Lane::culled) return true;
        if (lane == Lane::small_fixed) {
            bin_small(record);
            return true;
        }
        const std::optional<Placed> placed = place<F>(triangle, scene.c);
        if (!placed) return true;
        if (is_small(*placed)) {
            bin_small_placed(*placed, id);
            return true;
        }
        const BigEntry entry{static_cast<std::int32_t>(id), static_cast<std::uint32_t>(chunk.big.size())};
        chunk.big.push_back(setup_triangle<F>(*placed, scene.c, true));
        if (is_occluder(*placed)) {
            chunk.occluders.push_back(entry);
            return true;
        }
        for (int ty = tile_of(placed->j_lo); ty <= tile_of(placed->j_hi); ++ty)
            for (int tx = tile_of(placed->i_lo); tx <= tile_of(placed->i_hi); ++tx)
                append(chunk.big_bins[static_cast<std::size_t>(ty) * tiles_x + tx], entry);
        return true;
    };
    // The batch's gathers do not train the hardware's prefetcher the way a stream of loads does: the
    // triangles of the batch four ahead are fetched now (tiny triangles' rendering 8-10% faster; two to
    // sixteen batches ahead alike).
    const auto prefetch_ahead = [&](std::size_t id) {
        const std::uintptr_t batch_at = reinterpret_cast<std::uintptr_t>(scene.triangles.data() + id);
        prefetch_bytes(batch_at + 4 * kPlaceBatch * sizeof(Triangle), kPlaceBatch * sizeof(Triangle));
    };
    // The library places kPlaceBatch triangles at a time; the injected faults reach place_small_fixed's
    // own steps, so the faulty twins place one at a time. Each bin stays in id order: the lanes the batch
    // leaves undecided are placed first, then the batch's small triangles go to the fixed bins in lane
    // order, then its others, in order, to theirs; the first bad triangle of the chunk is the first
    // general one that is (the small, culled and undecided lanes are finite).
    if (lean && F == Fault::none) {
        const PlaceGrid grid = place_grid(scene.c);
        PlacedBatch batch;
        SmallFixed decided[kPlaceBatch];  // the undecided lanes that place_small_fixed found small
        for (std::size_t id = begin; id != end;) {
            const int n = static_cast<int>(std::min<std::size_t>(kPlaceBatch, end - id));
            prefetch_ahead(id);
            place_small_batch(&scene.triangles[id], n, grid, batch);
            std::uint32_t small = batch.small, general = batch.general;
            for (std::uint32_t lanes = batch.undecided; lanes != 0; lanes &= lanes - 1) {
                const int k = std::countr_zero(lanes);
                const auto named = static_cast<std::int32_t>(id + k);
                const Lane lane = place_small_fixed<F>(scene.triangles[id + k], named, scene.c, decided[k]);
                small |= std::uint32_t{lane == Lane::small_fixed} << k;
                general |= std::uint32_t{lane == Lane::general} << k;
            }
            for (std::uint32_t lanes = small; lanes != 0; lanes &= lanes - 1) {
                const int k = std::countr_zero(lanes);
                if (batch.small >> k & 1) bin_small(small_fixed_of(batch, k, static_cast<std::int32_t>(id + k)));
                else bin_small(decided[k]);
            }
            for (std::uint32_t lanes = general; lanes != 0; lanes &= lanes - 1) {
                const int k = std::countr_zero(lanes);
                if (!bin(id + k, Lane::general, decided[k])) return;
            }
            id += static_cast<std::size_t>(n);
        }
        return;
    }
    // The float modes', likewise: a batch's lanes in order, each small one binned as placed, the ones the
    // batch leaves to place by bin.
    if (!is_fixed(scene.c.precision) && F == Fault::none) {
        const PlaceGrid grid = float_place_grid(scene.c);
        FloatPlacedBatch batch;
        for (std::size_t id = begin; id != end;) {
            const int n = static_cast<int>(std::min<std::size_t>(kPlaceBatch, end - id));
            prefetch_ahead(id);
            place_float_batch(&scene.triangles[id], n, grid, batch);
            for (int k = 0; k < n; ++k) {
                if (batch.small >> k & 1) {
                    Placed placed;
                    for (int corner = 0; corner < 3; ++corner)
                        placed.v[corner] = {batch.x[corner][k], batch.y[corner][k], batch.z[corner][k]};
                    placed.i_lo = batch.i_lo[k];
                    placed.i_hi = batch.i_hi[k];
                    placed.j_lo = batch.j_lo[k];
                    placed.j_hi = batch.j_hi[k];
                    placed.path = Path::floating;
                    bin_small_placed(placed, id + k);
                } else if (!(batch.culled >> k & 1) && !bin(id + k, Lane::general, SmallFixed{})) {
                    return;
                }
            }
            id += static_cast<std::size_t>(n);
        }
        return;
    }
    for (std::size_t id = begin; id != end; ++id) {
        SmallFixed record{};  // read only where place_small_fixed filled it, which GCC cannot tell
        const auto named = static_cast<std::int32_t>(id);
        const Lane lane = lean ? place_small_fixed<F>(scene.triangles[id], named, scene.c, record) : Lane::general;
        if (!bin(id, lane, record)) return;
    }
}

template <Fault F>
void bin_chunk(Chunk& chunk, std::size_t begin, std::size_t end, const SceneView& scene, std::size_t tiles_x,
               std::size_t tiles) {
    // Emptied, keeping the bins' storage of the last render (Workspace).
    chunk.non_finite.reset();
    chunk.big.clear();
    chunk.occluders.clear();
    const auto empty_bins = [tiles](auto& bins) {
        bins.resize(tiles);
        for (auto& bin : bins) bin.clear();
    };
    empty_bins(chunk.fixed_bins);
    empty_bins(chunk.small_bins);
    empty_bins(chunk.big_bins);
    bin_triangles<F>(chunk, begin, end, scene, tiles_x, tiles);
}

}  // namespace rast::fast::detail
