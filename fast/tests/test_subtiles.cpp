// Hierarchical z's subtiles (tile_buffer.h, compose.h): which subtiles of a box a plane may be in front
// in (open_subtiles, on every SIMD target, against the test's definition at all four corners), the rows
// they leave to test (TrimmedRows), their far depths (TileBuffer::refresh_subtiles and refresh_far, and
// those a big triangle's covered subtiles take from its plane: cover_subtiles), and which triangles test
// them (fills_box).
#include "compose.h"
#include "targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <vector>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The plane's computed depth at a sample position, as every hierarchical-z test computes it.
double depth_at(const SubtileTest& t, double px, double py) { return t.z0 + (t.a * (px - t.x0) + t.b * (py - t.y0)); }

// The definition: subtile (bx, by) of the box is open unless the plane's smallest computed depth over the
// corners of its samples' rectangle there is beyond far + margin. Rounding is monotone, so that smallest
// corner is the one the slopes' signs pick.
std::uint64_t open_by_corners(const SubtileTest& t, const double* far) {
    std::uint64_t open = 0;
    for (int by = 0; by < kSubtiles; ++by)
        for (int bx = 0; bx < kSubtiles; ++bx) {
            const int x = t.ti + bx * kSubtile, y = t.tj + by * kSubtile;
            const int x0 = std::max(t.i0, x), x1 = std::min(t.i1, x + kSubtile - 1);
            const int y0 = std::max(t.j0, y), y1 = std::min(t.j1, y + kSubtile - 1);
            if (x0 > x1 || y0 > y1) continue;
            double nearest = kInf;
            for (const double px : {x0 + t.ox_min, x1 + t.ox_max})
                for (const double py : {y0 + t.oy_min, y1 + t.oy_max}) nearest = std::min(nearest, depth_at(t, px, py));
            const int at = by * kSubtiles + bx;
            if (!(nearest - far[at] > t.margin)) open |= std::uint64_t{1} << at;
        }
    return open;
}

// Random boxes in a tile at (64, 128), planes of either slope sign (and level ones), far depths within a
// few margins of the plane's depth at the tile's centre (some +infinity): every target agrees with the
// definition bit for bit, and both outcomes come up often.
TEST(Subtiles, OpenSubtilesIsTheCornerTestOnEveryTarget) {
    on_every_target([&] {
        std::mt19937_64 rng(20261127);
        std::uniform_real_distribution<double> unit(-1, 1);
        long open_seen = 0, hidden_seen = 0;
        for (int trial = 0; trial < 2000; ++trial) {
            const int ti = 64, tj = 128;
            int i0 = ti + static_cast<int>(rng() % 64), i1 = ti + static_cast<int>(rng() % 64);
            int j0 = tj + static_cast<int>(rng() % 64), j1 = tj + static_cast<int>(rng() % 64);
            if (i0 > i1) std::swap(i0, i1);
            if (j0 > j1) std::swap(j0, j1);
            const double slopes[] = {0.0, 1.0 / 64, -1.0 / 64, 0.37 * unit(rng)};
            SubtileTest t{0.5,  slopes[rng() % 4], 100.25, slopes[rng() % 4], 150.75, 1e-3,
                          0.125, 0.875,            0.0625, 0.9375,            ti,     tj,    i0, i1, j0, j1};
            double far[kSubtiles * kSubtiles];
            for (double& f : far) f = rng() % 8 == 0 ? kInf : depth_at(t, ti + 32, tj + 32) + 3 * t.margin * unit(rng);
            const std::uint64_t expected = open_by_corners(t, far);
            ASSERT_EQ(open_subtiles(t, far), expected) << "trial " << trial;
            open_seen += std::popcount(expected);
            int box = 0;
            for (int by = (j0 - tj) / kSubtile; by <= (j1 - tj) / kSubtile; ++by)
                box += (i1 - ti) / kSubtile - (i0 - ti) / kSubtile + 1;
            hidden_seen += box - std::popcount(expected);
        }
        EXPECT_GT(open_seen, 2000);
        EXPECT_GT(hidden_seen, 2000);
    });
}

// By hand, one sample at each pixel's centre, margin 0.25, a box of the whole tile at (0, 0) unless said.
SubtileTest centred(double z0, double a, double x0, int i0, int i1, int j0, int j1) {
    return {z0, a, x0, 0, 0.5, 0.25, 0.5, 0.5, 0.5, 0.5, 0, 0, i0, i1, j0, j1};
}

// A level plane at 0.75 is behind a subtile exactly when its far depth is below 0.5: at 0.5 the gap equals
// the margin, which decides nothing; +infinity (an empty sample) never hides. Only the box's subtiles
// answer.
TEST(Subtiles, OpenSubtilesDecidesOnlyBeyondTheMargin) {
    on_every_target([&] {
        double far[kSubtiles * kSubtiles];
        std::fill(std::begin(far), std::end(far), 0.0);
        far[0] = 0.5;
        far[1] = 0.5 - 0x1p-20;
        far[2] = kInf;
        far[3] = 0.75;
        EXPECT_EQ(open_subtiles(centred(0.75, 0, 0, 0, 63, 0, 63), far), 0b1101u);
        // Columns 8 to 23 of the first band: subtiles 1 and 2.
        EXPECT_EQ(open_subtiles(centred(0.75, 0, 0, 8, 23, 0, 7), far), 0b100u);
        // Rows 8 to 15: the second band, all at 0.
        EXPECT_EQ(open_subtiles(centred(0.75, 0, 0, 0, 63, 8, 15), far), 0u);
    });
}

// A slope along x, far depths all 0, over the first band: with a = 1/64 and x0 = 0.5 the nearest sample
// of subtile bx is its first, at depth bx / 8, open while bx / 8 <= 0.25 (bx <= 2); with a = -1/64 and
// x0 = 63.5 it is its last, at (7 - bx) / 8, open from bx = 5. Taking the other corner turns both round.
TEST(Subtiles, OpenSubtilesTakesEachSubtilesNearestCorner) {
    on_every_target([&] {
        double far[kSubtiles * kSubtiles];
        std::fill(std::begin(far), std::end(far), 0.0);
        EXPECT_EQ(open_subtiles(centred(0, 1.0 / 64, 0.5, 0, 63, 0, 7), far), 0b00000111u);
        EXPECT_EQ(open_subtiles(centred(0, -1.0 / 64, 63.5, 0, 63, 0, 7), far), 0b11100000u);
        // A box from column 12: subtile 1's part starts there, at depth 11.5 / 64 < 0.25: still open.
        EXPECT_EQ(open_subtiles(centred(0, 1.0 / 64, 0.5, 12, 63, 0, 7), far), 0b00000110u);
    });
}

// The rows a big triangle's subtiles leave, by hand, in the tile at (64, 128) over the box of pixels
// [70, 100] x [131, 148] (bands 0 to 2, subtile columns 0 to 4): band 0 open in columns 1 and 3 keeps
// pixels 72 to 95 (bits 2 to 25 from 70); band 1 closed keeps nothing; band 2 open in columns 0 and 4
// keeps the whole row (70 to 100) of rows 144 to 148. Only band 1 open, in column 2: its rows alone
// (136 to 143) are left, pixels 80 to 87.
TEST(Subtiles, TrimmedRowsKeepEachBandsOpenSpan) {
    const TileRect rect{64, 127, 128, 191};
    TrimmedRows rows;
    int j0 = 131, j1 = 148;
    const std::uint64_t open = 0b01010u | std::uint64_t{0b10001} << (2 * kSubtiles);
    rows.trim(open, rect, 70, 100, j0, j1);
    EXPECT_TRUE(rows.trimmed);
    EXPECT_EQ(j0, 131);
    EXPECT_EQ(j1, 148);
    for (int r = 0; r <= 17; ++r) {
        const int y = 131 + r;
        const std::uint64_t expected = y < 136 ? first_bits(24) << 2 : y < 144 ? 0 : first_bits(31);
        EXPECT_EQ(rows.keep[r], expected) << "row " << y;
    }
    rows.trim(std::uint64_t{0b100} << kSubtiles, rect, 70, 100, j0, j1);
    EXPECT_TRUE(rows.trimmed);
    EXPECT_EQ(j0, 136);
    EXPECT_EQ(j1, 143);
    for (int r = 0; r <= 7; ++r) EXPECT_EQ(rows.keep[r], first_bits(8) << 10) << "row " << 136 + r;
    // Every subtile of the box open: nothing trimmed.
    j0 = 131;
    j1 = 148;
    rows.trim(~std::uint64_t{0}, rect, 70, 100, j0, j1);
    EXPECT_FALSE(rows.trimmed);
    EXPECT_EQ(j0, 131);
    EXPECT_EQ(j1, 148);
    for (int r = 0; r <= 17; ++r) EXPECT_EQ(rows.keep[r], first_bits(31)) << "row " << 131 + r;
}

// A tile 20 x 12 pixels (the viewport's corner: subtiles 8 x 8, 8 x 8, 4 x 8 over 8 x 4), 4 samples,
// random depths in [-1, 1], and the largest of subtile (bx, by), 2 + kSubtiles by + bx, planted at a random
// place of it in a different sample plane for each.
constexpr int kPlantedSamples = 4, kPlantedWidth = 20, kPlantedHeight = 12;

void plant(TileBuffer& tile) {
    tile.fit(1, kPlantedSamples, {kPlantedWidth, kPlantedHeight});
    tile.clear();
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> depth(-1, 1);
    for (std::size_t k = 0; k < tile.size; ++k) tile.z[k] = depth(rng);
    const int widths[] = {8, 8, 4}, heights[] = {8, 4};
    for (int by = 0; by < 2; ++by)
        for (int bx = 0; bx < 3; ++bx) {
            const int s = (by * 3 + bx) % kPlantedSamples;
            const int row = by * kSubtile + static_cast<int>(rng() % heights[by]);
            const int col = bx * kSubtile + static_cast<int>(rng() % widths[bx]);
            tile.z[tile.at(s, row, col)] = 2 + by * kSubtiles + bx;
        }
}

void expect_planted_band(const TileBuffer& tile, int by) {
    for (int bx = 0; bx < 3; ++bx)
        EXPECT_EQ(tile.subtile_far[by * kSubtiles + bx], 2 + by * kSubtiles + bx) << bx << ", " << by;
}

// Each subtile's far depth is its largest over all its samples; an empty sample makes its subtile's
// +infinity, and the tile's.
TEST(Subtiles, RefreshTakesEachSubtilesLargestOverItsSamples) {
    TileBuffer tile;
    plant(tile);
    tile.refresh_subtiles(kPlantedSamples, kPlantedWidth, kPlantedHeight);
    EXPECT_FALSE(tile.subtiles_due);
    expect_planted_band(tile, 0);
    expect_planted_band(tile, 1);
    EXPECT_EQ(tile.far, 2 + kSubtiles + 2);
    tile.z[tile.at(3, 9, 17)] = kInf;  // subtile (2, 1)
    tile.refresh_subtiles(kPlantedSamples, kPlantedWidth, kPlantedHeight);
    EXPECT_EQ(tile.subtile_far[kSubtiles + 2], kInf);
    EXPECT_EQ(tile.subtile_far[kSubtiles + 1], 2 + kSubtiles + 1);
    EXPECT_EQ(tile.far, kInf);
}

// The tile's own refresh finds the subtiles' far depths on the way, so they are not due after it, unless
// it stopped at a band with an empty sample: the bands before are found, the tile's far depth is +infinity
// and the subtiles are due.
TEST(Subtiles, RefreshFarFindsTheSubtilesOrStopsAtAnEmptyBand) {
    TileBuffer tile;
    plant(tile);
    tile.subtiles_due = true;
    tile.since_far = 5;
    tile.refresh_far(kPlantedSamples, kPlantedWidth, kPlantedHeight);
    EXPECT_FALSE(tile.subtiles_due);
    EXPECT_EQ(tile.since_far, 0u);
    expect_planted_band(tile, 0);
    expect_planted_band(tile, 1);
    EXPECT_EQ(tile.far, 2 + kSubtiles + 2);
    tile.z[tile.at(2, 10, 3)] = kInf;  // subtile (0, 1)
    tile.refresh_far(kPlantedSamples, kPlantedWidth, kPlantedHeight);
    EXPECT_TRUE(tile.subtiles_due);
    expect_planted_band(tile, 0);
    EXPECT_EQ(tile.far, kInf);
}

// Whether every depth the tile holds in the subtile at bit `at` (in the whole tile for at = -1) is, exactly,
// at most the far depth f there plus stored_err (what behind_tile and open_subtiles rely on); an empty
// sample only under f = +infinity. A stored double at most f proves it at once (its exact depth is within
// stored_err of it); otherwise the exact depth, rounded to nearest, is compared.
bool far_bounds(TileBuffer& tile, const TileRect& rect, const Context& c, std::span<const Triangle> triangles,
                int at) {
    const double f = at < 0 ? tile.far : tile.subtile_far[at];
    if (f == kInf) return true;
    const double limit = std::nextafter(f + tile.stored_err, kInf);
    const int x0 = at < 0 ? 0 : at % kSubtiles * kSubtile, y0 = at < 0 ? 0 : at / kSubtiles * kSubtile;
    const int size = at < 0 ? kTile : kSubtile;
    for (int s = 0; s < static_cast<int>(c.offsets.size()); ++s)
        for (int row = y0; row < y0 + size; ++row)
            for (int col = x0; col < x0 + size; ++col) {
                const std::size_t slot = tile.at(s, row, col);
                const std::int32_t id = tile.ids[slot];
                if (id < 0) return false;
                if (tile.z[slot] <= f) continue;
                const Corners v = snapped(triangles[static_cast<std::size_t>(id)], c.precision).v;
                const double px = rect.i0 + col + c.offsets[s].x, py = rect.j0 + row + c.offsets[s].y;
                if (!(tile.planes.depth(id, v, px, py) <= limit)) return false;
            }
    return true;
}

// Big triangles composed one by one into the tile at (64, 64) of a 128 x 128 viewport, 1 and 4 samples,
// fixed8 (integer edges), the float modes (the whole-tile margin) and fixed8 on a viewport too large for
// its 64-bit range (the wide path's near edges; its background's, far away, clamped): a random background, random
// triangles of either slope, right triangles whose legs run along a subtile's pixel centres, and copies
// of the one before with its corners turned (the same exact plane, a double plane of its own, ties to the
// lower id): after each, the far depths the covered subtiles took from the plane (without a refresh of
// the tile) bound what their subtiles hold, and so does the tile's. Most triangles cover some subtile
// whole.
TEST(Subtiles, CoveredSubtilesFarDepthsBoundWhatTheyHoldOnEveryTarget) {
    struct Variant {
        Precision precision;
        int side;  // of the viewport
        Path path;
    };
    const Variant variants[] = {{Precision::fixed8, 128, Path::fixed},
                                {Precision::float32, 128, Path::floating},
                                {Precision::float64, 128, Path::floating},
                                {Precision::fixed8, 1 << 22, Path::wide}};
    on_every_target([&] {
        for (const auto [precision, side, path] : variants) {
            SCOPED_TRACE(static_cast<int>(precision));
            SCOPED_TRACE(side);
            long lowered = 0, checked = 0;
            for (const int samples : {1, 4}) {
                const Context c = make_context<Fault::none>({side, side}, samples, precision);
                const TileRect rect{64, 127, 64, 127};
                std::mt19937_64 rng(20261128 + static_cast<std::uint64_t>(samples));
                std::uniform_real_distribution<double> unit(0, 1);
                for (int scene = 0; scene < 8; ++scene) {
                    std::vector<Triangle> triangles;
                    const double back = 0.9 + 0.05 * unit(rng);
                    const double r = path == Path::wide ? 0x1p29 : 200;  // the wide background's edges clamped
                    triangles.push_back(Triangle{{{{-r, -r, back}, {2 * r, -r, back}, {-r, 2 * r, back + 0.01}}}});
                    while (triangles.size() < 24) {
                        if (triangles.size() > 1 && rng() % 3 == 0) {
                            const auto& v = triangles.back().v;
                            triangles.push_back(Triangle{{v[1], v[2], v[0]}});
                            continue;
                        }
                        if (rng() % 4 == 0) {
                            // Legs along a subtile's first or last column and row of pixel centres: its samples
                            // there lie on the edges, covered by the tie rule on one side only.
                            const auto centre = [&] {
                                return 64 + 8 * static_cast<double>(rng() % 8) + (rng() % 2 ? 7.5 : 0.5);
                            };
                            const double x = centre(), y = centre();
                            const double dx = rng() % 2 ? 90 : -90, dy = rng() % 2 ? 90 : -90;
                            const double z = 0.1 + 0.8 * unit(rng);
                            triangles.push_back(Triangle{{{{x, y, z}, {x + dx, y, z + 0.01}, {x, y + dy, z + 0.02}}}});
                            continue;
                        }
                        const double cx = 64 + 64 * unit(rng), cy = 64 + 64 * unit(rng), r = 70 + 80 * unit(rng);
                        const double turn = 6.283185307179586 * unit(rng);
                        Triangle t;
                        for (int k = 0; k < 3; ++k) {
                            const double angle = turn + k * 2.0943951023931953;
                            t.v[static_cast<std::size_t>(k)] = {cx + r * std::cos(angle), cy + r * std::sin(angle),
                                                                0.1 + 0.8 * unit(rng)};
                        }
                        triangles.push_back(t);
                    }
                    const SceneView view{triangles, c};
                    TileBuffer tile;
                    tile.fit(1, samples, c.vp);
                    tile.clear();
                    for (std::size_t id = 0; id < triangles.size(); ++id) {
                        const std::optional<Placed> p = place<Fault::none>(triangles[id], c);
                        ASSERT_TRUE(p && p->path == path);
                        const detail::Setup t = setup_triangle<Fault::none>(*p, c, true);
                        double before[kSubtiles * kSubtiles];
                        std::copy(std::begin(tile.subtile_far), std::end(tile.subtile_far), before);
                        const std::size_t since = tile.since_far;
                        rasterize<Fault::none>(t, static_cast<std::int32_t>(id), rect, tile, view);
                        ASSERT_TRUE(far_bounds(tile, rect, c, triangles, -1)) << "triangle " << id;
                        if (tile.since_far <= since || tile.subtiles_due) continue;  // refreshed: read from the tile
                        for (int at = 0; at < kSubtiles * kSubtiles; ++at) {
                            if (!(tile.subtile_far[at] < before[at])) continue;
                            ++lowered;
                            ASSERT_TRUE(far_bounds(tile, rect, c, triangles, at)) << "triangle " << id << ", " << at;
                        }
                        ++checked;
                    }
                }
            }
            EXPECT_GT(checked, 100);
            EXPECT_GT(lowered, 2000);
        }
    });
}

// Which triangles test subtiles: one covering an eighth of its bounding box or more. A right triangle
// covers half its box; a sliver along the diagonal of a 100 x 100 box, 1/200 of it; (0, 0), (8, 8),
// (8, 6) exactly an eighth of its 8 x 8 box, in; with (8, 6.01), just less, out.
TEST(Subtiles, OnlyTrianglesThatFillTheirBoxTestThem) {
    const auto corners = [](double ax, double ay, double bx, double by, double cx, double cy) {
        return Corners{Vertex{ax, ay, 0}, Vertex{bx, by, 0}, Vertex{cx, cy, 0}};
    };
    EXPECT_TRUE(fills_box(corners(0, 0, 10, 0, 0, 10)));
    EXPECT_TRUE(fills_box(corners(0, 0, 0, 10, 10, 0)));  // either winding
    EXPECT_FALSE(fills_box(corners(0, 0, 100, 100, 100, 99)));
    EXPECT_TRUE(fills_box(corners(0, 0, 8, 8, 8, 6)));
    EXPECT_FALSE(fills_box(corners(0, 0, 8, 8, 8, 6.01)));
}

}  // namespace
}  // namespace rast::fast::detail
