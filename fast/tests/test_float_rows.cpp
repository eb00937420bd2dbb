// float_row_masks, the float modes' rows of covered samples found by search, against the float edges
// evaluated at every sample (float_row_coverage, the scalar depth test's own), on each SIMD target: edges
// through samples (E = 0 on either tie rule), parallel to the rows or columns, coordinates where float32
// rounds x to fewer distinct values than there are columns, and magnitudes whose products overflow.
#include "kernels.h"
#include "scalar.h"
#include "targets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

// A block of random size; its corner near the origin, near float32's last odd integers or beyond 2^20,
// where (i + sx) rounds in float32, or negative; sample offsets in sixteenths.
Block random_block(std::mt19937_64& rng) {
    const int width = std::uniform_int_distribution<int>(1, kRowLanes)(rng);
    const int rows = std::uniform_int_distribution<int>(1, kRowLanes)(rng);
    const int place = std::uniform_int_distribution<int>(0, 3)(rng);
    const int lo = place == 0 ? 0 : place == 1 ? (1 << 20) : place == 2 ? (1 << 23) - 2 * kRowLanes : -(1 << 22);
    std::uniform_int_distribution<int> corner(lo, lo + 4 * kRowLanes), sixteenth(0, 15);
    return {corner(rng), corner(rng), width, rows, sixteenth(rng) / 16.0, sixteenth(rng) / 16.0};
}

// Edge k of a Coverage (its values in the mode's type, as Coverage keeps them): through a sample of the
// block nudged by a few units of its last place or not at all, or horizontal, vertical, huge (its
// products overflow float32 or even double), or with a start beyond the type's range.
void random_edge(std::mt19937_64& rng, const Block& b, bool single, Coverage& c, int k) {
    const auto in_type = [single](double v) { return single ? double(float(v)) : v; };
    std::uniform_int_distribution<int> column(0, b.width - 1), row(0, b.rows - 1), shape(0, 11);
    std::uniform_real_distribution<double> unit(-1, 1);
    const double px = b.i0 + column(rng) + b.sx, py = b.j0 + row(rng) + b.sy;
    const int s = shape(rng);
    const double overflow = single ? 3e37 : 5e306;  // finite, but times a few rows' y - ay beyond the type
    const double scale = s == 0 ? 1e30 : s == 1 ? 1e300 : s == 2 ? 1e-40 : s == 8 ? overflow : 64;
    double dx = unit(rng) * scale, dy = unit(rng) * scale;
    if (s == 3) dy = 0;
    if (s == 4) dx = 0;
    const double nudge = s == 5 ? std::nextafter(0.0, 1.0) : s == 6 ? unit(rng) * 1e-3 : 0;
    c.ax[k] = in_type(s == 7 ? px + 1e39 : px + nudge);
    c.ay[k] = in_type(py);
    c.d1[k] = in_type(dx);
    c.d3[k] = in_type(dy);
    c.inclusive[k] = rng() & 1;
}

TEST(FloatRowMasks, EqualTheFloatEdgesAtEverySampleOnEveryTarget) {
    on_every_target([&] {
        std::mt19937_64 rng(20261128);
        int partly_covered = 0, ties = 0;
        for (int trial = 0; trial < 20000; ++trial) {
            const Block b = random_block(rng);
            const bool single = trial % 2 == 0;
            Coverage c;
            c.kind = single ? Coverage::Kind::float32 : Coverage::Kind::float64;
            for (int k = 0; k < 3; ++k) random_edge(rng, b, single, c, k);
            // One edge alone decides most rows: the others then cover everything.
            if (trial % 3 == 0)
                for (int k = 1; k < 3; ++k) {
                    c.d1[k] = c.d3[k] = 0;
                    c.inclusive[k] = true;
                }
            std::uint64_t masks[kRowLanes];
            float_row_masks(c, b, masks);
            for (int r = 0; r < b.rows; ++r) {
                const std::uint64_t expected = row_coverage(b, c, r);
                ASSERT_EQ(masks[r], expected) << "trial " << trial << " row " << r;
                partly_covered += expected != 0 && expected != first_bits(b.width);
                const double y = double(b.j0 + r) + b.sy;
                for (int k = 0; k < 3 && single; ++k) {
                    const float t1 = float(c.d1[k]) * (float(y) - float(c.ay[k]));
                    ties += t1 - float(c.d3[k]) * (float(b.i0) + float(b.sx) - float(c.ax[k])) == 0;
                }
            }
        }
        EXPECT_GT(partly_covered, 50000);  // the cases are not all trivial
        EXPECT_GT(ties, 1000);             // samples on an edge decided by its rule
    });
}

}  // namespace
}  // namespace rast::fast::detail
