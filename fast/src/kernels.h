// The inner loops over one row of up to 64 samples of a tile, in SIMD with runtime dispatch (Highway).
// Bit k of a mask stands for the sample of pixel i0 + k. Every lane computes exactly what the scalar
// definition in the comments computes (integers, or the same IEEE operations without contraction), so
// the result does not depend on the instruction set.
#pragma once

#include <cstdint>

namespace rast::fast::detail {

inline constexpr int kRowLanes = 64;

// Fixed point: covered iff base[e] + k * step[e] >= 0 for the three edges (the tie bias is in base).
std::uint64_t coverage_fixed(const std::int64_t* base, const std::int64_t* step, int n);

// Float edge a -> b in T on one sample row y: E(px) = t1 - d3 * (px - ax), with t1 = (bx - ax) * (y - ay)
// and d3 = by - ay already rounded to T, px = T(i0 + k + sx). Covered iff E > 0, or E == 0 on an
// inclusive edge.
template <class T>
struct FloatEdgeRow {
    T ax, d3, t1;
    bool inclusive;
};
std::uint64_t coverage_float32(const FloatEdgeRow<float>* edges, int i0, float sx, int n);
std::uint64_t coverage_float64(const FloatEdgeRow<double>* edges, int i0, double sx, int n);

// The z-buffer on one sample row. z = z0 + (a * ((i0 + k + sx) - x0) + b_dy), error bound err. A covered
// sample is written (z, err, id) when the slot is empty and z finite, or when z + err < z' - err'
// (decided nearer); it is left when z - err > z' + err' (decided farther). The rest are returned
// undecided for the exact comparison. The buffers are read (not written) up to 64 lanes past i0.
struct DepthRow {
    double z0, a, b_dy, x0, err;
    std::int64_t id;
    int i0;
    double sx;
};
std::uint64_t depth_row(const DepthRow& row, std::uint64_t covered, double* z, double* err,
                        std::int64_t* ids);

}  // namespace rast::fast::detail
