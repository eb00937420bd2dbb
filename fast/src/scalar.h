// Blocks of a few pixels in scalar code: a tiny triangle's block is smaller than the vector setup of a
// kernel call (kernels.h) costs. Sample by sample, the same operations as the kernels, so the result is
// bit-identical to theirs.
#pragma once

#include "kernels.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace rast::fast::detail {

// Blocks of up to this many samples are rasterized in scalar code: a vector kernel's setup and its
// branches on the rows' runs cost more (and stamps, stamp.h, are no larger).
inline constexpr int kScalarSamples = 16;

// The float edges of Coverage on row r of block b, in T.
template <class T>
std::uint64_t float_row_coverage(const Block& b, const Coverage& cov, int r) {
    const T py = T(double(b.j0 + r) + b.sy);
    std::uint64_t covered = 0;
    T t1[3];
    for (int e = 0; e < 3; ++e) t1[e] = T(cov.d1[e]) * (py - T(cov.ay[e]));
    for (int k = 0; k < b.width; ++k) {
        const T px = T(b.i0 + k) + T(b.sx);
        bool inside = true;
        for (int e = 0; e < 3; ++e) {
            const T value = t1[e] - T(cov.d3[e]) * (px - T(cov.ax[e]));
            inside = inside && (value > 0 || (value == 0 && cov.inclusive[e]));
        }
        covered |= std::uint64_t{inside} << k;
    }
    return covered;
}

// The integer edges of Coverage (e, dx, dy) on row r of a block `width` samples wide.
inline std::uint64_t fixed_row_coverage(const std::int64_t* e, const std::int64_t* dx, const std::int64_t* dy,
                                        int width, int r) {
    std::int64_t e0 = e[0] + r * dy[0], e1 = e[1] + r * dy[1], e2 = e[2] + r * dy[2];
    std::uint64_t covered = 0;
    for (int k = 0; k < width; ++k, e0 += dx[0], e1 += dx[1], e2 += dx[2])
        covered |= std::uint64_t{(e0 | e1 | e2) >= 0} << k;
    return covered;
}

// Row r of block b as Coverage defines it.
inline std::uint64_t row_coverage(const Block& b, const Coverage& cov, int r) {
    switch (cov.kind) {
        case Coverage::Kind::all: return first_bits(b.width);
        case Coverage::Kind::masks: return cov.masks[r];
        case Coverage::Kind::fixed: return fixed_row_coverage(cov.e, cov.dx, cov.dy, b.width, r);
        case Coverage::Kind::float32: return float_row_coverage<float>(b, cov, r);
        case Coverage::Kind::float64: return float_row_coverage<double>(b, cov, r);
    }
    return 0;
}

// The z-buffer test of depth_block (kernels.h) at one sample, slot `at` of rows, its x px and the plane's
// row term b_dy = b (py - y0): the same operations as the kernels' lanes. kPerSample: whether rows.err
// holds the stored depths' bounds. Answers whether the sample is left undecided.
template <bool kPerSample>
[[gnu::always_inline]] inline bool depth_sample(const DepthPlane& p, const DepthRows& rows, std::ptrdiff_t at, double px,
                                                double b_dy) {
    const double z = p.z0 + (p.a * (px - p.x0) + b_dy);
    const double stored = rows.z[at], stored_err = kPerSample ? rows.err[at] : p.stored_err;
    const double gap = stored - z, margin = p.err + stored_err;
    if (gap > margin) {
        rows.z[at] = z;
        if constexpr (kPerSample) rows.err[at] = p.err;
        rows.ids[at] = p.id;
        return false;
    }
    return !(gap < -margin);
}

// depth_block (kernels.h), one sample at a time, the coverage of row r given by row_mask(r).
template <bool kPerSample, class RowMask>
[[gnu::always_inline]] inline bool depth_rows_scalar(const Block& b, RowMask row_mask, const DepthPlane& p,
                                                     const DepthRows& rows, std::uint64_t* undecided) {
    bool any = false;
    for (int r = 0; r < b.rows; ++r) {
        const double py = double(b.j0 + r) + b.sy;
        const double b_dy = p.b * (py - p.y0);
        std::uint64_t open = 0;
        for (std::uint64_t m = row_mask(r); m != 0; m &= m - 1) {
            const int k = std::countr_zero(m);
            const double px = double(b.i0 + k) + b.sx;
            if (depth_sample<kPerSample>(p, rows, r * rows.stride + k, px, b_dy)) open |= std::uint64_t{1} << k;
        }
        undecided[r] = open;
        any = any || open != 0;
    }
    return any;
}

// depth_rows_scalar with the bounds as rows keeps them.
template <class RowMask>
bool depth_rows_scalar(const Block& b, RowMask row_mask, const DepthPlane& p, const DepthRows& rows,
                       std::uint64_t* undecided) {
    return with_stored_bounds(rows, [&](auto per_sample) {
        return depth_rows_scalar<per_sample>(b, row_mask, p, rows, undecided);
    });
}

inline bool depth_block_scalar(const Block& b, const Coverage& cov, const DepthPlane& p, const DepthRows& rows,
                               std::uint64_t* undecided) {
    // The float edges in lanes (float_row_masks evaluates a block one vector wide at every sample, as
    // float_row_coverage defines it): sample by sample, with a branch each, they were a fifth of float32's
    // time on tiny triangles.
    if (cov.kind == Coverage::Kind::float32 || cov.kind == Coverage::Kind::float64) {
        std::uint64_t masks[kRowLanes];
        float_row_masks(cov, b, masks);
        return depth_rows_scalar(b, [&](int r) { return masks[r]; }, p, rows, undecided);
    }
    return depth_rows_scalar(b, [&](int r) { return row_coverage(b, cov, r); }, p, rows, undecided);
}

}  // namespace rast::fast::detail
