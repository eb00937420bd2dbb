// The SIMD depth tests (depth_block for every coverage kind, depth_runs, depth_small) against the scalar
// one of scalar.h, sample by sample, on each SIMD target: the same stored depths, bounds and ids
// afterwards, and the same samples left undecided; depth_small_run against depth_small. Then the tile's
// whole-buffer kernels.
#include "kernels.h"
#include "scalar.h"
#include "targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

// A tile's rows with a vector of padding, as TileBuffer keeps them; the block's first sample at column
// `origin` of the first row. At the right edge (origin + width = kStride) a kernel's reads past a block row
// land in the next row, and past the last one in the padding: AddressSanitizer sees any further.
struct Rows {
    static constexpr std::ptrdiff_t kStride = kRowLanes;
    std::vector<double> z, err;
    std::vector<std::int32_t> ids;
    bool per_sample = false;
    std::ptrdiff_t origin = 0;
    DepthRows view() {
        return {z.data() + origin, per_sample ? err.data() + origin : nullptr, ids.data() + origin, kStride};
    }
};

// Block b's rows, every slot empty, the block's first sample at `origin`: the block's rows end the
// buffer's, then the padding.
Rows empty_rows(const Block& b, bool per_sample, std::ptrdiff_t origin) {
    Rows rows;
    rows.origin = origin;
    const std::size_t size = static_cast<std::size_t>(Rows::kStride) * b.rows + kRowLanes;
    rows.z.assign(size, std::numeric_limits<double>::infinity());
    rows.err.assign(size, 0);
    rows.ids.assign(size, -1);
    rows.per_sample = per_sample;
    return rows;
}

// Stored depths around the plane's at the block's samples: some empty, some equal to it (undecided
// within the bounds), most clearly nearer or farther.
Rows random_rows(std::mt19937_64& rng, const Block& b, const DepthPlane& p, bool per_sample, bool at_right_edge) {
    Rows rows = empty_rows(b, per_sample, at_right_edge ? Rows::kStride - b.width : 0);
    std::uniform_int_distribution<int> kind(0, 9);
    std::uniform_real_distribution<double> offset(-0.01, 0.01);
    for (int r = 0; r < b.rows; ++r)
        for (int k = 0; k < b.width; ++k) {
            const std::size_t at = static_cast<std::size_t>(rows.origin + r * Rows::kStride + k);
            const int what = kind(rng);
            if (what == 0) continue;  // empty
            const double px = double(b.i0 + k) + b.sx, py = double(b.j0 + r) + b.sy;
            const double z = p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0));
            rows.z[at] = what <= 3 ? z : z + offset(rng);
            rows.err[at] = per_sample ? p.stored_err * (what % 2 == 0 ? 1 : 0.5) : 0;
            rows.ids[at] = 1000 + what;
        }
    return rows;
}

Block random_block(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> side(1, kRowLanes), origin(0, 1000), sixteenth(0, 15);
    return {origin(rng), origin(rng), side(rng), side(rng), sixteenth(rng) / 16.0, sixteenth(rng) / 16.0};
}

DepthPlane random_plane(std::mt19937_64& rng, const Block& b) {
    std::uniform_real_distribution<double> unit(0, 1), slope(-0.01, 0.01);
    return {unit(rng), slope(rng), double(b.i0), slope(rng), double(b.j0), 1e-12, 1e-12, 7};
}

// Integer edges of a random triangle around the block, 32-bit sized: |dx|, |dy| < 2^12 and values within
// 2^31 over the block, so that depth_small can take them too.
Coverage random_fixed(std::mt19937_64& rng, const Block& b) {
    std::uniform_int_distribution<std::int64_t> step(-4095, 4095);
    std::uniform_int_distribution<int> col(0, b.width - 1), row(0, b.rows - 1);
    Coverage c;
    c.kind = Coverage::Kind::fixed;
    for (int k = 0; k < 3; ++k) {
        c.dx[k] = step(rng);
        c.dy[k] = step(rng);
        // Zero at a random sample of the block, moved a little towards the inside.
        c.e[k] = -(c.dx[k] * col(rng) + c.dy[k] * row(rng)) + 2000;
    }
    return c;
}

// Integer edges of Coverage::Kind::fixed that fit 32 bits (random_fixed's), in depth_small's form.
SmallEdges small_edges_of(const Coverage& c) {
    SmallEdges small;
    for (int k = 0; k < 3; ++k) {
        small.e[k] = static_cast<std::int32_t>(c.e[k]);
        small.dx[k] = static_cast<std::int32_t>(c.dx[k]);
        small.dy[k] = static_cast<std::int32_t>(c.dy[k]);
    }
    return small;
}

// Float edges of a random counter-clockwise triangle that overlaps the block.
Coverage random_float(std::mt19937_64& rng, const Block& b, bool single) {
    std::uniform_real_distribution<double> x(b.i0 - 8.0, b.i0 + b.width + 8.0), y(b.j0 - 8.0, b.j0 + b.rows + 8.0);
    double vx[3], vy[3];
    for (int k = 0; k < 3; ++k) {
        vx[k] = x(rng);
        vy[k] = y(rng);
    }
    if ((vx[1] - vx[0]) * (vy[2] - vy[0]) - (vy[1] - vy[0]) * (vx[2] - vx[0]) < 0) {
        std::swap(vx[1], vx[2]);
        std::swap(vy[1], vy[2]);
    }
    Coverage c;
    c.kind = single ? Coverage::Kind::float32 : Coverage::Kind::float64;
    const auto in_type = [single](double v) { return single ? double(float(v)) : v; };
    for (int k = 0; k < 3; ++k) {
        const int n = (k + 1) % 3;
        c.ax[k] = in_type(vx[k]);
        c.ay[k] = in_type(vy[k]);
        c.d1[k] = in_type(in_type(vx[n]) - c.ax[k]);
        c.d3[k] = in_type(in_type(vy[n]) - c.ay[k]);
        c.inclusive[k] = k != 1;
    }
    return c;
}

// One run per row, as the wide path's spans give them.
Coverage random_masks(std::mt19937_64& rng, const Block& b, std::uint64_t* masks) {
    for (int r = 0; r < b.rows; ++r) {
        std::uniform_int_distribution<int> col(0, b.width);
        int from = col(rng), to = col(rng);
        if (from > to) std::swap(from, to);
        masks[r] = first_bits(to) & ~first_bits(from);
    }
    Coverage c;
    c.kind = Coverage::Kind::masks;
    c.masks = masks;
    return c;
}

// The rows and, where the block left samples undecided (`any`, the kernels write them only then), those.
void expect_same(Rows& got, Rows& want, const std::uint64_t* got_open, const std::uint64_t* want_open, bool any,
                 const Block& b, const char* what) {
    for (int r = 0; any && r < b.rows; ++r) ASSERT_EQ(got_open[r], want_open[r]) << what << " row " << r;
    ASSERT_EQ(got.ids, want.ids) << what;
    ASSERT_EQ(got.z, want.z) << what;
    if (got.per_sample) {
        ASSERT_EQ(got.err, want.err) << what;
    }
}

// A kernel's undecided rows before the call: set, so that a row it fails to write shows.
std::uint64_t* poisoned(std::uint64_t (&open)[kRowLanes]) {
    std::fill(std::begin(open), std::end(open), ~std::uint64_t{0});
    return open;
}

// What the scalar test did to a block: whether it left any sample undecided, and whether it wrote any.
struct Outcome {
    bool undecided = false, written = false;
};

// The kernels and depth_block_scalar on one block against the scalar test on Coverage's definition, sample
// by sample (row_coverage), which did `outcome`; a wrong answer is fatal.
void expect_kernels_agree(const Block& b, const DepthPlane& p, const Coverage& cov, const Rows& start,
                          const char* trial, Outcome& outcome) {
    SCOPED_TRACE(trial);
    Rows want = start, got = start, scalar = start;
    std::uint64_t want_open[kRowLanes], got_open[kRowLanes];
    const auto defined = [&](int r) { return row_coverage(b, cov, r); };
    const bool want_any = depth_rows_scalar(b, defined, p, want.view(), want_open);
    outcome = {want_any, want.ids != start.ids};
    ASSERT_EQ(depth_block_scalar(b, cov, p, scalar.view(), poisoned(got_open)), want_any);
    expect_same(scalar, want, got_open, want_open, want_any, b, "depth_block_scalar");
    ASSERT_EQ(depth_block(b, cov, p, got.view(), poisoned(got_open)), want_any);
    expect_same(got, want, got_open, want_open, want_any, b, "depth_block");
    if (cov.kind != Coverage::Kind::fixed && cov.kind != Coverage::Kind::masks) return;
    // The same rows as runs, and the integer edges in 32-bit lanes.
    std::uint64_t covered[kRowLanes];
    for (int r = 0; r < b.rows; ++r) covered[r] = row_coverage(b, cov, r);
    Rows runs = start;
    ASSERT_EQ(depth_runs(b, covered, p, runs.view(), poisoned(got_open)), want_any);
    expect_same(runs, want, got_open, want_open, want_any, b, "depth_runs");
    if (cov.kind != Coverage::Kind::fixed) return;
    const SmallEdges small = small_edges_of(cov);
    Rows lanes = start;
    ASSERT_EQ(depth_small(b, small, p, lanes.view(), poisoned(got_open)), want_any);
    expect_same(lanes, want, got_open, want_open, want_any, b, "depth_small");
}

TEST(DepthKernels, EqualTheScalarDepthTestOnEveryTarget) {
    on_every_target([&] {
        std::mt19937_64 rng(20261124);
        int undecided_blocks = 0, written_blocks = 0;
        for (int trial = 0; trial < 2000; ++trial) {
            const Block b = random_block(rng);
            DepthPlane p = random_plane(rng, b);
            // Now and then a plane whose bound is infinite, in both bound modes and at either edge: the
            // kernels decide none of its samples.
            if (trial % 7 == 3) p.err = std::numeric_limits<double>::infinity();
            const bool per_sample = trial % 2 == 1;
            std::uint64_t masks[kRowLanes];
            const int kind = trial % 5;
            const Coverage cov = kind == 0   ? Coverage{}
                                 : kind == 1 ? random_fixed(rng, b)
                                 : kind == 2 ? random_masks(rng, b, masks)
                                             : random_float(rng, b, kind == 3);
            const Rows start = random_rows(rng, b, p, per_sample, trial / 2 % 2 == 1);
            Outcome outcome;
            expect_kernels_agree(b, p, cov, start, ("trial " + std::to_string(trial)).c_str(), outcome);
            if (HasFatalFailure()) return;
            undecided_blocks += outcome.undecided;
            written_blocks += outcome.written;
        }
        // Every width the column kernel of depth_small takes (up to four vectors of eight lanes) and the
        // first beyond, in both modes and at the right edge: the random blocks above meet few of them.
        for (int width = 1; width <= 33; ++width)
            for (int mode = 0; mode < 4; ++mode) {
                std::uniform_int_distribution<int> origin(0, 1000), rows(1, 12);
                const Block b{origin(rng), origin(rng), width, rows(rng), 0.5, 0.5};
                const DepthPlane p = random_plane(rng, b);
                const Rows start = random_rows(rng, b, p, mode % 2 == 1, mode / 2 == 1);
                Outcome outcome;
                expect_kernels_agree(b, p, random_fixed(rng, b), start, ("width " + std::to_string(width)).c_str(),
                                     outcome);
                if (HasFatalFailure()) return;
            }
        // The cases are not all trivial: many blocks write, many leave samples to the exact comparison.
        EXPECT_GT(written_blocks, 1500) << undecided_blocks;
        EXPECT_GT(undecided_blocks, 1500) << written_blocks;
    });
}

// The run kernel against depth_small on each of its entries in turn: a run of up to eight blocks of a
// tile (their rows at their own offsets, overlapping one another), stored depths around a plane that most
// entries share (coplanar twins: ties left undecided), in both bound modes. The run stops at the same
// entry with the same undecided rows, and leaves the tile's depths, bounds and ids the same; a call from
// the entry after it goes on. Each entry's margin takes the call's stored_err, not a bound of its own.
TEST(DepthKernels, SmallRunEqualsDepthSmallEntryByEntryOnEveryTarget) {
    on_every_target([&] {
        const DepthSmallRunKernel run_kernel = depth_small_run_kernel();
        std::mt19937_64 rng(20261128);
        int stops = 0, later_entries_tested = 0;
        for (int trial = 0; trial < 400; ++trial) {
            SCOPED_TRACE(::testing::Message() << "trial " << trial);
            const bool per_sample = trial % 2 == 1;
            const Block tile_block{0, 0, kRowLanes, kRowLanes, 0.5, 0.5};
            const DepthPlane shared = random_plane(rng, tile_block);
            Rows start = random_rows(rng, tile_block, shared, per_sample, false);
            std::uniform_int_distribution<int> count(1, 8), side(1, 40), origin(0, 23), other(0, 3);
            // Some stored depths 2.5e-12 from the shared plane's, beyond twice its own bound (1e-12) but
            // within the margin the call's stored_err (3e-12) makes: left undecided.
            for (int r = 0; r < kRowLanes; ++r)
                for (int k = 0; k < kRowLanes; ++k)
                    if (const int what = other(rng); what < 2 && start.ids[r * Rows::kStride + k] >= 0) {
                        const double px = k + 0.5, py = r + 0.5;
                        const double z = shared.z0 + (shared.a * (px - shared.x0) + shared.b * (py - shared.y0));
                        start.z[r * Rows::kStride + k] = z + (what == 0 ? 2.5e-12 : -2.5e-12);
                    }
            std::vector<SmallRunEntry> entries(static_cast<std::size_t>(count(rng)));
            for (std::size_t k = 0; k < entries.size(); ++k) {
                const int i0 = origin(rng), j0 = origin(rng);
                const Block b{i0, j0, side(rng), side(rng), 0.5, 0.5};
                const DepthPlane p = other(rng) == 0 ? random_plane(rng, b) : shared;
                entries[k] = {b, small_edges_of(random_fixed(rng, b)), p.z0, p.a, p.x0, p.b, p.y0, p.err,
                              static_cast<std::int32_t>(7 + k), j0 * Rows::kStride + i0};
            }
            const double stored_err = 3e-12;
            Rows want = start, got = start;
            for (std::size_t first = 0; first < entries.size();) {
                // depth_small one entry at a time, from `first` to the first that leaves samples undecided.
                std::uint64_t want_open[kRowLanes], got_open[kRowLanes];
                std::size_t stop = first;
                for (; stop < entries.size(); ++stop) {
                    const SmallRunEntry& e = entries[stop];
                    const DepthPlane p{e.z0, e.a, e.x0, e.b, e.y0, e.err, stored_err, e.id};
                    DepthRows rows = want.view();
                    rows.z += e.at;
                    rows.ids += e.at;
                    if (rows.err) rows.err += e.at;
                    if (depth_small(e.block, e.edges, p, rows, want_open)) break;
                }
                ASSERT_EQ(run_kernel(entries.data(), first, entries.size(), got.view(), stored_err, poisoned(got_open)),
                          stop);
                const bool any = stop < entries.size();
                expect_same(got, want, got_open, want_open, any, any ? entries[stop].block : entries[0].block,
                            "depth_small_run");
                if (HasFatalFailure()) return;
                stops += any;
                later_entries_tested += any && stop + 1 < entries.size();
                first = stop + 1;
            }
        }
        // The runs stop, and go on after a stop.
        EXPECT_GT(stops, 200) << later_entries_tested;
        EXPECT_GT(later_entries_tested, 100) << stops;
    });
}

// The decision itself, by hand: stored depths z' = z + f (err + err') around the plane's z, for a block
// every sample of which is covered. A gap beyond the margin on either side is decided (written when the
// stored depth is the farther), one within it or at it is left to the exact comparison: a margin scaled
// either way, or the margin's own gap decided, fails, in the scalar test and in every kernel on every target.
TEST(DepthKernels, DecideExactlyTheGapsBeyondTheMargin) {
    // Every depth and stored depth in [0.5, 1), where the margin, 3 2^-41, is a whole number of units in
    // the last place: a gap of exactly +-margin (f = +-1) is left undecided.
    const DepthPlane p{0.75, 1e-3, 40, -2e-3, 7, 0x1p-41, 0x1p-40, 7};
    const double margin = p.err + p.stored_err;
    // Then the gaps at the margin as the block's only undecided samples.
    const std::vector<double> factor_sets[] = {{-3, -1.5, -1.1, -1, -0.9, -0.5, 0, 0.5, 0.9, 1, 1.1, 1.5, 3},
                                               {-3, -1, 1, 3}};
    for (const std::vector<double>& factors : factor_sets) {
        for (const bool per_sample : {false, true}) {
            SCOPED_TRACE(::testing::Message() << factors.size() << " gaps, a bound per sample: " << per_sample);
            const int count = static_cast<int>(factors.size());
            const Block b{40, 7, count, 3, 0.5, 0.5};
            Rows start = empty_rows(b, per_sample, 0);
            for (int r = 0; r < b.rows; ++r)
                for (int k = 0; k < count; ++k) {
                    const std::size_t at = static_cast<std::size_t>(r * Rows::kStride + k);
                    const double px = double(b.i0 + k) + b.sx, py = double(b.j0 + r) + b.sy;
                    start.z[at] = p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0)) + factors[k] * margin;
                    start.err[at] = per_sample ? p.stored_err : 0;
                    start.ids[at] = 100 + k;
                }
            const auto expect_decisions = [&](Rows& rows, const std::uint64_t* open, const char* what) {
                SCOPED_TRACE(what);
                for (int r = 0; r < b.rows; ++r)
                    for (int k = 0; k < count; ++k) {
                        const double f = factors[k];
                        const std::size_t at = static_cast<std::size_t>(r * Rows::kStride + k);
                        EXPECT_EQ(rows.ids[at], f > 1 ? p.id : 100 + k) << "f = " << f;
                        EXPECT_EQ((open[r] >> k) & 1, std::abs(f) <= 1 ? 1u : 0u) << "f = " << f;
                    }
            };
            std::uint64_t open[kRowLanes];
            Rows scalar = start;
            EXPECT_TRUE(depth_block_scalar(b, Coverage{}, p, scalar.view(), open));
            expect_decisions(scalar, open, "scalar");
            on_every_target([&] {
                Rows block = start, runs = start, lanes = start;
                EXPECT_TRUE(depth_block(b, Coverage{}, p, block.view(), poisoned(open)));
                expect_decisions(block, open, "depth_block");
                std::uint64_t covered[kRowLanes];
                for (int r = 0; r < b.rows; ++r) covered[r] = first_bits(count);
                EXPECT_TRUE(depth_runs(b, covered, p, runs.view(), poisoned(open)));
                expect_decisions(runs, open, "depth_runs");
                const SmallEdges inside{{1, 1, 1}, {0, 0, 0}, {0, 0, 0}};
                EXPECT_TRUE(depth_small(b, inside, p, lanes.view(), poisoned(open)));
                expect_decisions(lanes, open, "depth_small");
            });
        }
    }
}

// A plane whose bound is infinite decides nothing: every covered sample is left to the exact comparison
// and none is written, also where its depth overflows (to +infinity beside an empty slot's, a gap that is
// NaN) and where the slot is empty, in the scalar test and in every kernel on every target. Two blocks:
// stored depths of every kind under a plane that overflows on its right, and every slot empty under one
// that overflows everywhere (every gap NaN).
TEST(DepthKernels, LeaveEverySampleOfAnInfiniteBoundUndecided) {
    const Block b{40, 7, 20, 3, 0.5, 0.5};
    std::uint64_t covered[kRowLanes];
    for (int r = 0; r < b.rows; ++r) covered[r] = first_bits(b.width) & ~first_bits(r);  // rows from column r
    const Coverage masks{Coverage::Kind::masks, covered};
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    for (const bool overflowing_everywhere : {false, true})
        for (const bool per_sample : {false, true}) {
            SCOPED_TRACE(::testing::Message() << "every gap NaN: " << overflowing_everywhere
                                              << ", a bound per sample: " << per_sample);
            // 1e308 + 1e307 (px - x0) overflows from px - x0 = 8 on; with x0 = i0 - 9.5, everywhere.
            const DepthPlane p{1e308, 1e307, overflowing_everywhere ? 30.5 : 40, 0, 7, kInfinity, 1e-12, 7};
            Rows start = empty_rows(b, per_sample, 0);
            for (int r = 0; !overflowing_everywhere && r < b.rows; ++r)
                for (int k = (r + 1) % 2; k < b.width; k += 2) {  // every other slot empty
                    const std::size_t at = static_cast<std::size_t>(r * Rows::kStride + k);
                    start.z[at] = k % 4 == 0 ? 1e308 : -1.0;
                    start.err[at] = per_sample ? 1e-12 : 0;
                    start.ids[at] = 100 + k;
                }
            const auto expect_nothing_decided = [&](const Rows& rows, const std::uint64_t* open, const char* what) {
                SCOPED_TRACE(what);
                EXPECT_EQ(rows.z, start.z);
                EXPECT_EQ(rows.ids, start.ids);
                EXPECT_EQ(rows.err, start.err);
                for (int r = 0; r < b.rows; ++r) EXPECT_EQ(open[r], covered[r]) << "row " << r;
            };
            std::uint64_t open[kRowLanes];
            Rows scalar = start;
            EXPECT_TRUE(depth_block_scalar(b, masks, p, scalar.view(), open));
            expect_nothing_decided(scalar, open, "scalar");
            on_every_target([&] {
                Rows runs = start, lanes = start;
                EXPECT_TRUE(depth_runs(b, covered, p, runs.view(), poisoned(open)));
                expect_nothing_decided(runs, open, "depth_runs");
                // Edge 0 is k - r at column k of row r, the others 1 everywhere: the same samples.
                const SmallEdges from_column{{0, 1, 1}, {1, 0, 0}, {-1, 0, 0}};
                EXPECT_TRUE(depth_small(b, from_column, p, lanes.view(), poisoned(open)));
                expect_nothing_decided(lanes, open, "depth_small");
            });
        }
}

// A margin that overflows although each bound is finite (err and the stored depths' near the largest
// double) decides nothing either, also where the gap overflows too (1.7e308 stored, the plane at -1e308):
// |gap| - margin would be NaN there. Both bound modes, every kernel.
TEST(DepthKernels, LeaveTheGapsOfAnOverflowingMarginUndecided) {
    const Block b{40, 7, 8, 2, 0.5, 0.5};
    const DepthPlane p{-1e308, 0, 40, 0, 7, 1e308, 1e308, 7};  // depth -1e308 everywhere
    std::uint64_t covered[kRowLanes];
    for (int r = 0; r < b.rows; ++r) covered[r] = first_bits(b.width);
    for (const bool per_sample : {false, true}) {
        SCOPED_TRACE(::testing::Message() << "a bound per sample: " << per_sample);
        Rows start = empty_rows(b, per_sample, 0);
        for (int r = 0; r < b.rows; ++r)
            for (int k = 0; k < b.width; ++k) {
                const std::size_t at = static_cast<std::size_t>(r * Rows::kStride + k);
                start.z[at] = 1.7e308;  // a gap of +infinity
                start.err[at] = per_sample ? 1e308 : 0;
                start.ids[at] = 100 + k;
            }
        std::uint64_t open[kRowLanes];
        on_every_target([&] {
            Rows runs = start, lanes = start;
            EXPECT_TRUE(depth_runs(b, covered, p, runs.view(), poisoned(open)));
            EXPECT_EQ(runs.ids, start.ids);
            for (int r = 0; r < b.rows; ++r) EXPECT_EQ(open[r], covered[r]) << "depth_runs, row " << r;
            const SmallEdges inside{{1, 1, 1}, {0, 0, 0}, {0, 0, 0}};
            EXPECT_TRUE(depth_small(b, inside, p, lanes.view(), poisoned(open)));
            EXPECT_EQ(lanes.ids, start.ids);
            for (int r = 0; r < b.rows; ++r) EXPECT_EQ(open[r], covered[r]) << "depth_small, row " << r;
        });
        Rows scalar = start;
        EXPECT_TRUE(depth_block_scalar(b, Coverage{}, p, scalar.view(), open));
        EXPECT_EQ(scalar.ids, start.ids);
        for (int r = 0; r < b.rows; ++r) EXPECT_EQ(open[r], covered[r]) << "scalar, row " << r;
    }
}

// The tile's two whole-buffer kernels at every length and alignment up to a few vectors: fill_far writes
// +infinity over exactly [0, n), farthest answers the largest value (+infinity where a slot is empty).
TEST(DepthKernels, FillFarAndFarthestCoverExactlyTheirRangeOnEveryTarget) {
    constexpr double kInf = std::numeric_limits<double>::infinity(), kUntouched = 7.5;
    on_every_target([&] {
        std::mt19937_64 rng(20261127);
        for (std::size_t offset = 0; offset < 4; ++offset)
            for (std::size_t n = 0; n <= 40; ++n) {
                std::vector<double> z(n + 8, kUntouched);
                fill_far(z.data() + offset, n);
                for (std::size_t k = 0; k < z.size(); ++k)
                    ASSERT_EQ(z[k], k >= offset && k < offset + n ? kInf : kUntouched) << n << " from " << offset;
                if (n == 0) continue;
                std::uniform_real_distribution<double> depth(-1, 1);
                for (std::size_t k = offset; k < offset + n; ++k) z[k] = depth(rng);
                const std::size_t top = offset + rng() % n;
                z[top] = 2;  // above the rest, and below the untouched slots around the range
                EXPECT_EQ(farthest(z.data() + offset, n), 2.0) << n << " from " << offset;
                z[offset + rng() % n] = kInf;
                EXPECT_EQ(farthest(z.data() + offset, n), kInf) << n << " from " << offset;
            }
    });
}

// farthest_subtiles answers each subtile column's largest depth over exactly its rows and columns: every
// width and row count of a tile, the largest value of subtile k planted at a random place as 2 + k, and
// everything outside the rows and columns (10, above them all) ignored; an empty slot makes its subtile's
// +infinity, and only its; nothing written past the last subtile.
TEST(DepthKernels, FarthestSubtilesTakesEachSubtilesLargestOnEveryTarget) {
    constexpr double kInf = std::numeric_limits<double>::infinity(), kOutside = 10, kUnwritten = -5;
    constexpr int kStride = 64;
    on_every_target([&] {
        std::mt19937_64 rng(20261127);
        std::uniform_real_distribution<double> depth(-1, 1);
        for (int width = 1; width <= kStride; ++width)
            for (int rows = 1; rows <= kSubtile; ++rows) {
                std::vector<double> z((rows + 1) * kStride + kSubtile, kOutside);
                for (int r = 0; r < rows; ++r)
                    for (int i = 0; i < width; ++i) z[r * kStride + i] = depth(rng);
                const int subtiles = (width + kSubtile - 1) / kSubtile;
                const auto slot_in = [&](int k) {
                    const int columns = std::min(kSubtile, width - k * kSubtile);
                    return static_cast<int>(rng() % rows) * kStride + k * kSubtile + static_cast<int>(rng() % columns);
                };
                for (int k = 0; k < subtiles; ++k) z[slot_in(k)] = 2 + k;
                double far[kStride / kSubtile + 1];
                std::fill(std::begin(far), std::end(far), kUnwritten);
                farthest_subtiles(z.data(), kStride, width, rows, far);
                for (int k = 0; k <= kStride / kSubtile; ++k)
                    ASSERT_EQ(far[k], k < subtiles ? 2 + k : kUnwritten) << width << " x " << rows << ", subtile " << k;
                const int empty = static_cast<int>(rng() % subtiles);
                z[slot_in(empty)] = kInf;
                farthest_subtiles(z.data(), kStride, width, rows, far);
                for (int k = 0; k < subtiles; ++k)
                    ASSERT_EQ(far[k], k == empty ? kInf : 2 + k) << width << " x " << rows << ", subtile " << k;
            }
    });
}

// The kernels a render resolves once (Context::depth_small, Context::depth_small_run) are the selected
// target's own: a different function on each target, as the tests that compare the targets' output need.
TEST(DepthKernels, SmallKernelsAreTheSelectedTargets) {
    std::set<DepthSmallKernel> kernels;
    std::set<DepthSmallRunKernel> run_kernels;
    on_every_target([&] {
        EXPECT_TRUE(kernels.insert(depth_small_kernel()).second);
        EXPECT_TRUE(run_kernels.insert(depth_small_run_kernel()).second);
    });
}

// The first element of `values` at the start of a cache line (within its first 64 bytes).
template <class T>
T* line_start(T* values) {
    const auto misaligned = reinterpret_cast<std::uintptr_t>(values) % 64;
    return values + (misaligned == 0 ? 0 : (64 - misaligned) / sizeof(T));
}

// copy_out at every alignment of the destination within a cache line (a row streams its whole lines and
// stores the rest), widths below a line and over several, and strides that move each row's alignment:
// exactly the rows' depths and ids land, and nothing around them is touched.
TEST(DepthKernels, CopyOutWritesExactlyTheTileRowsOnEveryTarget) {
    constexpr double kUntouched = 7.5;
    constexpr std::int32_t kUntouchedId = -7;
    on_every_target([&] {
        for (int width = 0; width <= 40; ++width)
            for (int rows = 1; rows <= 3; ++rows) {
                const std::ptrdiff_t stride = width + 3, to_stride = width + 5;
                std::vector<double> z(static_cast<std::size_t>(rows * stride));
                std::vector<std::int32_t> ids(z.size());
                for (std::size_t k = 0; k < z.size(); ++k) {
                    z[k] = 0.25 + static_cast<double>(k);
                    ids[k] = static_cast<std::int32_t>(k);
                }
                // From a line's start, so that offsets 0 to 15 take the destination's rows through every
                // alignment of their depths and ids within a line.
                for (std::ptrdiff_t offset = 0; offset < 16; ++offset) {
                    const std::size_t size = static_cast<std::size_t>(offset + rows * to_stride + 16);
                    std::vector<double> z_buffer(size + 8);
                    std::vector<std::int32_t> id_buffer(size + 16);
                    double* to_z = line_start(z_buffer.data());
                    std::int32_t* to_ids = line_start(id_buffer.data());
                    std::fill_n(to_z, size, kUntouched);
                    std::fill_n(to_ids, size, kUntouchedId);
                    copy_out(z.data(), ids.data(), stride, to_z + offset, to_ids + offset, to_stride, width, rows);
                    for (std::ptrdiff_t k = 0; k < static_cast<std::ptrdiff_t>(size); ++k) {
                        const std::ptrdiff_t r = (k - offset) / to_stride, col = (k - offset) % to_stride;
                        const bool inside = k >= offset && r < rows && col < width;
                        ASSERT_EQ(to_z[k], inside ? z[r * stride + col] : kUntouched)
                            << "width " << width << ", rows " << rows << ", offset " << offset << ", slot " << k;
                        ASSERT_EQ(to_ids[k], inside ? ids[r * stride + col] : kUntouchedId)
                            << "width " << width << ", rows " << rows << ", offset " << offset << ", slot " << k;
                    }
                }
            }
    });
}

}  // namespace
}  // namespace rast::fast::detail
