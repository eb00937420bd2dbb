// The rasterizer proper: screen tiles of 64 x 64 pixels, binned triangles composed in id order per tile
// (occluders, of a tile's area or more, first and nearest first: the (z, id) order makes the result the
// same either way), trivial reject / accept per tile, one SIMD kernel call per triangle, tile and sample
// index (a tiny triangle's coverage found with its run's, in stamps). Templated on the injected fault;
// render.cpp instantiates Fault::none, the testing target the others. This file is the threaded driver and
// a tile's merge of its bins; the stages are binning.h (bins; small triangles placed eight at a time,
// place_batch.h), occluders.h (the occluders' order over the scene), setup.h (placing and setting up a
// triangle), coverage.h (which samples; stamp.h for tiny blocks), tile_buffer.h (a thread's tile) and
// compose.h (a triangle into a tile), then line_pass.h (the lines, last).
#pragma once

#include "binning.h"
#include "compose.h"
#include "coverage.h"
#include "line_pass.h"
#include "occluders.h"
#include "setup.h"
#include "tile_buffer.h"
#include "validate.h"

#include <rast/fast.h>
#include <rast/fast_faults.h>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace rast::fast::detail {

// Starts loading what rasterize reads of a big triangle's setup (the fixed path's part comes first) one
// triangle ahead: the setups of a tile's triangles are scattered over the chunk, and each was a cache
// miss on first touch.
inline void prefetch(const Setup& s) {
    const auto address = [](const void* p) { return reinterpret_cast<std::uintptr_t>(p); };
    prefetch_bytes(address(&s), address(&s.classify_tiles) + sizeof(s.classify_tiles) - address(&s));
}

// One tile row of empty samples (kTile pixels of up to kMaxSamples), what an empty tile is copied out from.
struct EmptyRow {
    std::array<double, kTile * kMaxSamples> z;
    std::array<std::int32_t, kTile * kMaxSamples> ids;
};
inline constexpr EmptyRow kEmptyRow = [] {
    EmptyRow row{};
    row.z.fill(std::numeric_limits<double>::infinity());
    row.ids.fill(Framebuffer::kNoTriangle);
    return row;
}();

template <Fault F>
void render_tile(std::span<const Chunk> chunks, std::span<const SceneOccluders::Entry> occluders, std::size_t index,
                 const TileRect& rect, TileBuffer& tile, const SceneView& scene, Framebuffer& fb) {
    const int samples = static_cast<int>(scene.c.offsets.size());
    const int width = rect.i1 - rect.i0 + 1;
    // A tile no triangle reaches is written empty straight into the framebuffer, where its pixels' samples
    // are contiguous row by row: clearing the tile buffer and copying it out moves its bytes twice more
    // (2.5 ms for a 1024 x 1024 screen on one thread, half the time of a mesh that leaves most tiles empty).
    // Its rows are copied from kEmptyRow by copy_out, streamed as a one-sample tile's (filled by ordinary
    // stores, each line of the framebuffer was read first: an empty 1024 x 1024 frame took 1.03 ms, now
    // 0.65 ms, on an Intel Xeon VM).
    const bool empty = occluders.empty() && std::all_of(chunks.begin(), chunks.end(), [index](const Chunk& chunk) {
        return chunk.fixed_bins[index].empty() && chunk.small_bins[index].empty() && chunk.big_bins[index].empty();
    });
    if (empty) {
        const std::size_t at = fb.index(rect.i0, rect.j0);
        copy_out(kEmptyRow.z.data(), kEmptyRow.ids.data(), 0, fb.depth.data() + at, fb.ids.data() + at,
                 static_cast<std::ptrdiff_t>(fb.index(0, 1)), width * samples, rect.j1 - rect.j0 + 1);
        return;
    }
    tile.clear();
    // A big triangle, the setup of the one composed after it (where known) fetched meanwhile.
    const auto compose_big = [&](const Setup& setup, std::int32_t id, const Setup* next) {
        if (next) prefetch(*next);
        rasterize<F>(setup, id, rect, tile, scene);
    };
    // The occluders first, nearest first (occluders.h); then the rest in id order.
    for (std::size_t k = 0; k < occluders.size(); ++k)
        compose_big(*occluders[k].setup, occluders[k].id, k + 1 < occluders.size() ? occluders[k + 1].setup : nullptr);
    constexpr std::int32_t kEnd = std::numeric_limits<std::int32_t>::max();  // above every id (render checks)
    for (const Chunk& chunk : chunks) {
        const std::vector<SmallFixed>& fixed = chunk.fixed_bins[index];
        const std::vector<SmallTriangle>& small = chunk.small_bins[index];
        const std::vector<BigEntry>& big = chunk.big_bins[index];
        // The three lists are in id order; merged, the tile composes all its other triangles in id order.
        // The common lane's triangles before the next of the other two go in one tight loop, their planes
        // set up kPlaneBatch at a time.
        for (std::size_t f = 0, a = 0, b = 0;;) {
            const std::int32_t next_small = a < small.size() ? small[a].id : kEnd;
            const std::int32_t next_big = b < big.size() ? big[b].id : kEnd;
            const std::int32_t next_other = std::min(next_small, next_big);
            while (f < fixed.size() && fixed[f].id < next_other) {
                std::size_t n = 1;
                while (n < kPlaneBatch && f + n < fixed.size() && fixed[f + n].id < next_other) ++n;
                Plane planes[kPlaneBatch];
                PlaneBatch batch;
                const std::uint32_t narrow = small_planes({fixed.data() + f, n}, scene.c, planes, batch);
                // The narrow triangles whose block fits a stamp take their coverage from its masks; the
                // faulty twins' bugs are in the steps stamps skip, so they take none.
                StampMasks stamps;
                if (F == Fault::none && narrow != 0) stamps.find(batch, narrow, rect, scene.c);
                rasterize_run<F>({fixed.data() + f, n}, planes, narrow, stamps, rect, tile, scene);
                f += n;
            }
            if (next_other == kEnd) break;
            if (next_small < next_big) {
                // The small lane's triangles before the next of the other two, their planes set up
                // kPlaneBatch at a time.
                const std::int32_t until = std::min(next_big, f < fixed.size() ? fixed[f].id : kEnd);
                std::size_t n = 1;
                while (n < kPlaneBatch && a + n < small.size() && small[a + n].id < until) ++n;
                Plane planes[kPlaneBatch];
                placed_planes(n, [&](std::size_t k) -> const Placed& { return small[a + k].p; }, scene.c, planes);
                for (std::size_t k = 0; k < n; ++k, ++a)
                    rasterize<F>(setup_triangle<F>(small[a].p, scene.c, false, planes[k]), small[a].id, rect, tile,
                                 scene);
            } else {
                const Setup* next = b + 1 < big.size() ? &chunk.big[big[b + 1].setup] : nullptr;
                compose_big(chunk.big[big[b].setup], big[b].id, next);
                ++b;
            }
        }
    }
    if (samples == 1) {  // rows contiguous on both sides
        const std::size_t at = fb.index(rect.i0, rect.j0);
        copy_out(tile.z.data(), tile.ids.data(), tile.cols, fb.depth.data() + at, fb.ids.data() + at,
                 fb.viewport.width, width, rect.j1 - rect.j0 + 1);
        return;
    }
    for (int j = rect.j0; j <= rect.j1; ++j)
        for (int s = 0; s < samples; ++s) {
            const std::int32_t* ids = tile.ids.data() + tile.at(s, j - rect.j0, 0);
            const double* z = tile.z.data() + tile.at(s, j - rect.j0, 0);
            std::int32_t* to_ids = fb.ids.data() + fb.index(rect.i0, j, s);
            double* to_depth = fb.depth.data() + fb.index(rect.i0, j, s);
            for (int k = 0; k < width; ++k) {
                to_ids[k * samples] = ids[k];
                to_depth[k * samples] = z[k];
            }
        }
}

// Storage for the scene's samples, kept when fb already has the size: every sample is written anyway
// (render_tile copies whole tiles).
inline void fit(Framebuffer& fb, Viewport vp, int samples) {
    const std::size_t size = static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height) *
                             static_cast<std::size_t>(samples);
    fb.viewport = vp;
    fb.samples = samples;
    fb.ids.resize(size);
    fb.depth.resize(size);
}

// What a render allocates, kept by a Renderer for the next one: the chunks' bins, the occluders', a tile
// buffer per thread and the threads' arena (Renderer, fast.h, says why).
struct Workspace {
    std::vector<Chunk> chunks;
    SceneOccluders occluders;  // names setups in chunks[k].big: valid from its gather to the render's end
    // One per thread of the arena, by its index there, fitted by the thread's first tile of a render (a
    // thread that gets no tile costs nothing).
    std::vector<TileBuffer> tiles;
    std::uint64_t renders = 0;
    std::unique_ptr<tbb::task_arena> arena;
    int arena_threads = -1;  // Options::threads the arena was made for
};

// max_threads (fast.h).
inline int thread_limit() {
    return static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

template <Fault F>
void render_scene(const Scene& scene, const Options& options, Framebuffer& fb, Workspace& ws) {
    validate(scene.viewport, scene.samples);
    validate(options.precision);
    validate_threads(options.threads);
    if (scene.triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw std::invalid_argument("rast::fast: more triangles than 32-bit ids can name");
    const std::vector<std::int32_t> ids = scene.lines.empty() ? std::vector<std::int32_t>{} : checked_lines(scene);

    const Context c = make_context<F>(scene.viewport, scene.samples, options.precision);
    const SceneView view{scene.triangles, c};
    // Up to 2^18 tiles each way: their count needs 64 bits.
    const std::size_t tiles_x = static_cast<std::size_t>(c.vp.width + kTile - 1) / kTile;
    const std::size_t tiles = tiles_x * static_cast<std::size_t>((c.vp.height + kTile - 1) / kTile);

    if (!ws.arena || ws.arena_threads != options.threads) {
        const int concurrency = options.threads == 0 ? int{tbb::task_arena::automatic}
                                                     : std::min(options.threads, thread_limit());
        ws.arena = std::make_unique<tbb::task_arena>(concurrency);
        ws.arena_threads = options.threads;
    }
    tbb::task_arena& arena = *ws.arena;
    // Contiguous id ranges, binned in parallel; every tile visits them in order, so it still composes
    // its triangles in id order (the occluders aside), whatever the number of chunks. Binning is about a
    // quarter of a tiny triangle's instructions (scripts/stage-budget) and sets up the big triangles, so
    // it is shared out. The count is a multiple of the workers, so that chunks of equal size share out
    // evenly (2000 big triangles in 7 chunks once kept one of two threads binning 4/7 of the time, while
    // their setup was half their instructions): one per worker, up to four where each still gets
    // kChunkTriangles. A chunk costs about 10^5 instructions of its own (a bin per tile, merged per tile),
    // which the bunny's 3674 triangles in 8 chunks did not earn back. A scene too small to give every
    // worker kMinChunkTriangles is binned in as many chunks as it fills.
    const std::size_t n = scene.triangles.size();
    constexpr std::size_t kChunkTriangles = 1024, kMinChunkTriangles = 128;
    const std::size_t workers = static_cast<std::size_t>(arena.max_concurrency());
    const std::size_t chunk_count =
        workers == 1 ? 1
                     : std::min(workers * std::clamp<std::size_t>(n / (kChunkTriangles * workers), 1, 4),
                                std::max<std::size_t>(1, n / kMinChunkTriangles));
    std::vector<Chunk>& chunks = ws.chunks;
    chunks.resize(chunk_count);
    ws.tiles.resize(workers);
    const std::uint64_t render = ++ws.renders;
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunk_count, 1), [&](const auto& r) {
            for (std::size_t k = r.begin(); k != r.end(); ++k)
                bin_chunk<F>(chunks[k], k * n / chunk_count, (k + 1) * n / chunk_count, view, tiles_x, tiles);
        });
    });
    // The chunks are in id order, so the first one that stopped holds the first bad triangle. The
    // framebuffer is untouched until the scene is known to be valid.
    for (const Chunk& chunk : chunks)
        if (chunk.non_finite) validate(scene.triangles[*chunk.non_finite], *chunk.non_finite);
    // The occluders in one order, binned in about four ranges of tile rows a worker.
    arena.execute([&] {
        ws.occluders.gather(chunks, tiles_x, tiles);
        const int rows = static_cast<int>(tiles / tiles_x);
        const int grain = std::max(1, rows / static_cast<int>(4 * workers));
        tbb::parallel_for(tbb::blocked_range<int>(0, rows, grain),
                          [&](const auto& r) { ws.occluders.bin_rows(r.begin(), r.end()); });
    });
    fit(fb, c.vp, scene.samples);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles, 1), [&](const auto& r) {
            TileBuffer& tile = ws.tiles.at(static_cast<std::size_t>(tbb::this_task_arena::current_thread_index()));
            tile.fit(render, scene.samples, c.vp);
            for (std::size_t index = r.begin(); index != r.end(); ++index) {
                const int i0 = static_cast<int>(index % tiles_x) * kTile, j0 = static_cast<int>(index / tiles_x) * kTile;
                const TileRect rect{i0, std::min(i0 + kTile, c.vp.width) - 1, j0, std::min(j0 + kTile, c.vp.height) - 1};
                render_tile<F>(chunks, ws.occluders.of(index), index, rect, tile, view, fb);
            }
        });
    });
    if (!scene.lines.empty()) draw_lines(scene, c, ids, fb);
}

template <Fault F>
std::vector<std::size_t> covered_by(const Triangle& triangle, Viewport vp, int samples, Precision precision) {
    validate(vp, samples);
    validate(precision);
    validate(triangle, 0);
    const Context c = make_context<F>(vp, samples, precision);
    std::vector<std::size_t> out;
    const std::optional<Placed> placed = place<F>(triangle, c);
    if (!placed) return out;
    const Setup t = setup_triangle<F>(*placed, c, false);
    std::uint64_t masks[kTile], covered[kTile];
    std::vector<Span> wide;
    for (int j0 = t.p.j_lo; j0 <= t.p.j_hi; j0 += kTile) {
        const int rows = std::min(kTile, t.p.j_hi - j0 + 1);
        if (t.p.path == Path::wide && !t.near) {
            wide.resize(static_cast<std::size_t>(rows) * samples);
            spans_of(t, c, j0, j0 + rows - 1, wide);
        }
        for (int s = 0; s < samples; ++s)
            for (int i0 = t.p.i_lo; i0 <= t.p.i_hi; i0 += kTile) {
                const Block b{i0, j0, std::min(kTile, t.p.i_hi - i0 + 1), rows, c.offsets[s].x, c.offsets[s].y};
                coverage_block(b, coverage_of<F>(t, c, b, s, wide, masks), covered);
                for (int r = 0; r < b.rows; ++r)
                    for (std::uint64_t m = covered[r]; m != 0; m &= m - 1) {
                        const std::size_t i = static_cast<std::size_t>(i0 + std::countr_zero(m));
                        out.push_back((static_cast<std::size_t>(j0 + r) * vp.width + i) * samples + s);
                    }
            }
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace rast::fast::detail
