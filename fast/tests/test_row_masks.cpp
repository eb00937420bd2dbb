// row_masks, the fixed path's rows of covered samples, against the edge functions evaluated at every
// sample in 128-bit integers, on each SIMD target (its rows are walked as many at a time as it has
// 64-bit lanes).
#include "kernels.h"
#include "targets.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

// Bit i of row r: whether p[k] i + q[k] + r step[k] >= 0 for all three edges.
std::uint64_t expected_row(const RowEdges& e, int width, int r) {
    std::uint64_t bits = 0;
    for (int i = 0; i < width; ++i) {
        bool inside = true;
        for (int k = 0; k < 3; ++k)
            inside = inside && __int128{e.p[k]} * i + e.q[k] + __int128{e.step[k]} * r >= 0;
        if (inside) bits |= std::uint64_t{1} << i;
    }
    return bits;
}

// An edge through a random point of the block (so that rows are partly covered), or parallel to the rows
// or columns, or far from the block, with the fixed path's magnitudes (coefficients below 2^46: coordinate
// differences below 2^30, times 2^16; values below 2^61) and the wide path's near edges' (coefficients
// below 2^50, values at the first sample within 2^60: kWideStep and kWideClamp, exact.h and setup.h).
void random_edge(std::mt19937_64& rng, int width, int rows, RowEdges& e, int k) {
    const auto magnitude = [&rng] {
        const int bits = std::uniform_int_distribution<int>(0, 50)(rng);
        const auto m = static_cast<std::int64_t>(rng() >> (64 - bits - 1) >> 1);
        return rng() & 1 ? m : -m;
    };
    const int shape = std::uniform_int_distribution<int>(0, 9)(rng);
    e.p[k] = shape == 0 ? 0 : magnitude();
    e.step[k] = shape == 1 ? 0 : magnitude();
    const int i = std::uniform_int_distribution<int>(0, width - 1)(rng);
    const int r = std::uniform_int_distribution<int>(0, rows - 1)(rng);
    const std::int64_t nudge = std::uniform_int_distribution<std::int64_t>(-3, 3)(rng);
    const std::int64_t clamp = std::int64_t{1} << 60;
    e.q[k] = shape == 2   ? magnitude() * 1024
             : shape == 3 ? (rng() & 1 ? clamp : -clamp)
                          : -(e.p[k] * i + e.step[k] * r) + nudge;
}

TEST(RowMasks, EqualTheEdgeFunctionsAtEverySampleOnEveryTarget) {
    on_every_target([&] {
        std::mt19937_64 rng(20261124);
        int partly_covered = 0;
        for (int trial = 0; trial < 20000; ++trial) {
            const int width = std::uniform_int_distribution<int>(1, kRowLanes)(rng);
            const int rows = std::uniform_int_distribution<int>(1, kRowLanes)(rng);
            RowEdges edges;
            for (int k = 0; k < 3; ++k) random_edge(rng, width, rows, edges, k);
            std::uint64_t masks[kRowLanes];
            row_masks(edges, width, rows, masks);
            for (int r = 0; r < rows; ++r) {
                const std::uint64_t expected = expected_row(edges, width, r);
                ASSERT_EQ(masks[r], expected) << "trial " << trial << " row " << r;
                partly_covered += expected != 0 && expected != first_bits(width);
            }
        }
        EXPECT_GT(partly_covered, 100000);  // the cases are not all trivial
    });
}

}  // namespace
}  // namespace rast::fast::detail
