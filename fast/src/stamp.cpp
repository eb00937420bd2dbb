// Highway compiles this file once per SIMD target (foreach_target) and dispatches to the best one the
// CPU supports at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "stamp.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "scalar.h"
#include "stamp.h"

#include <algorithm>
#include <bit>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace rast::fast::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Lanes of 32 bits: DT's the batch's triangles (the setup, and Masks' coverage), DS's a stamp's samples
// (Mask's). Every value computed fits (narrow_edges) where it is read; vector integer arithmetic wraps
// around elsewhere (the positions past a triangle's block), and those are masked off.
using DT = hn::CappedTag<std::int32_t, kPlaneBatch>;
using DS = hn::ScalableTag<std::int32_t>;

// fixed_edges then fixed_edges_at (setup.h, coverage.h) for every lane: edge k runs from corner k to
// corner k + 1; E = a (X - ax) + b (Y - ay) - bias at the block's first sample (X, Y), with a = ay - by,
// b = bx - ax, and bias 0 on an owning edge (owns_ties), 1 on the others. Answers the lanes whose block
// fits a stamp.
std::uint32_t SetUp(const PlaneBatch& t, const StampGrid& g, StampEdges& out) {
    const DT d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto past_side = hn::Set(d, kStampSide + 1), one = hn::Set(d, 1);
    std::uint32_t fits = 0;
    for (int first = 0; first < kPlaneBatch; first += lanes) {
        const auto i0 = hn::Max(hn::Set(d, g.i0), hn::LoadU(d, t.i_lo + first));
        const auto j0 = hn::Max(hn::Set(d, g.j0), hn::LoadU(d, t.j_lo + first));
        const auto width = hn::Add(hn::Sub(hn::Min(hn::Set(d, g.i1), hn::LoadU(d, t.i_hi + first)), i0), one);
        const auto rows = hn::Add(hn::Sub(hn::Min(hn::Set(d, g.j1), hn::LoadU(d, t.j_hi + first)), j0), one);
        hn::StoreU(width, d, out.width + first);
        hn::StoreU(rows, d, out.rows + first);
        std::uint8_t bytes[8] = {};
        const auto small = hn::Lt(hn::Mul(width, rows), hn::Set(d, kScalarSamples + 1));
        hn::StoreMaskBits(d, hn::And(hn::And(hn::Lt(width, past_side), hn::Lt(rows, past_side)), small), bytes);
        std::uint32_t bits = 0;
        std::memcpy(&bits, bytes, sizeof bits);
        fits |= bits << first;
        // Pixel indices times 2^bits stay below 2^31 wherever a block is read (the viewport is in range).
        const auto x = hn::Add(hn::ShiftLeftSame(i0, g.bits), hn::Set(d, g.sx));
        const auto y = hn::Add(hn::ShiftLeftSame(j0, g.bits), hn::Set(d, g.sy));
        for (int k = 0; k < 3; ++k) {
            const int n = (k + 1) % 3;
            const auto ax = hn::LoadU(d, t.x[k] + first), ay = hn::LoadU(d, t.y[k] + first);
            const auto bx = hn::LoadU(d, t.x[n] + first), by = hn::LoadU(d, t.y[n] + first);
            const auto a = hn::Sub(ay, by), b = hn::Sub(bx, ax);
            const auto owns = hn::Or(hn::Lt(by, ay), hn::And(hn::Eq(by, ay), hn::Lt(bx, ax)));
            // - bias: -1 on the others, 0 on the owning edges (whose mask vector is -1).
            const auto e = hn::Sub(hn::Sub(hn::Add(hn::Mul(a, hn::Sub(x, ax)), hn::Mul(b, hn::Sub(y, ay))), one),
                                   hn::VecFromMask(d, owns));
            hn::StoreU(e, d, out.e[k] + first);
            hn::StoreU(hn::ShiftLeftSame(a, g.bits), d, out.dx[k] + first);
            hn::StoreU(hn::ShiftLeftSame(b, g.bits), d, out.dy[k] + first);
        }
    }
    return fits;
}

// The mask of triangle k: its edges over the stamp's samples, position p = kStampSide r + c in lane
// order, as many vectors as its rows take.
std::uint64_t Mask(const StampEdges& t, int k) {
    const DS d;
    constexpr int kSide = kStampSide;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto position = hn::Iota(d, 0);
    const auto column = hn::And(position, hn::Set(d, kSide - 1)), row = hn::ShiftRight<3>(position);
    static_assert(kSide == 8, "row = position >> 3");
    hn::Vec<DS> value[3], dx[3], dy[3], down[3];
    for (int e = 0; e < 3; ++e) {
        dx[e] = hn::Set(d, t.dx[e][k]);
        dy[e] = hn::Set(d, t.dy[e][k]);
        down[e] = hn::Set(d, t.dy[e][k] * (lanes / kSide));
        value[e] = hn::Add(hn::Set(d, t.e[e][k]), hn::Add(hn::Mul(column, dx[e]), hn::Mul(row, dy[e])));
    }
    const int positions = t.rows[k] * kSide;
    std::uint64_t covered = 0;
    for (int p = 0; p < positions; p += lanes) {
        // All three are >= 0 exactly when their bitwise or is > -1.
        const auto inside = hn::Gt(hn::Or(hn::Or(value[0], value[1]), value[2]), hn::Set(d, -1));
        std::uint8_t bytes[8] = {};
        hn::StoreMaskBits(d, inside, bytes);
        std::uint64_t bits = 0;
        std::memcpy(&bits, bytes, sizeof bits);
        covered |= bits << p;
        // The next vector's positions: lanes / kSide rows down where a vector holds whole rows, else
        // evaluated afresh.
        for (int e = 0; e < 3; ++e) {
            if (lanes >= kSide) {
                value[e] = hn::Add(value[e], down[e]);
            } else {
                const auto next = hn::Add(position, hn::Set(d, p + lanes));
                value[e] = hn::Add(hn::Set(d, t.e[e][k]),
                                   hn::Add(hn::Mul(hn::And(next, hn::Set(d, kSide - 1)), dx[e]),
                                           hn::Mul(hn::ShiftRight<3>(next), dy[e])));
            }
        }
    }
    // Only the block's samples: its first `width` columns of each of its rows.
    const std::uint64_t row_bits = (std::uint64_t{1} << t.width[k]) - 1;
    const std::uint64_t rows = t.rows[k] == kSide ? ~std::uint64_t{0} : (std::uint64_t{1} << (kSide * t.rows[k])) - 1;
    return covered & row_bits * 0x0101010101010101u & rows;
}

// The masks of the batch's triangles all at once (at least those of `which`), over `width` columns and
// `rows` rows (at least those of every block in `which`): lane k is triangle k, and a vector is a stamp
// position (column c of row r, E = e + c dx + r dy); a lane gathers its row's columns as the bits of its
// int32, cleared past its own block, and each row goes into the triangles' masks at its place. One
// triangle at a time, three edges broadcast and stepped over a row of lanes cost as much again as the two
// or three rows of a tiny triangle's block.
void Masks(const StampEdges& t, std::uint32_t which, int width, int rows, std::uint64_t* masks) {
    const DT d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    std::fill_n(masks, kPlaneBatch, std::uint64_t{0});
    const auto one = hn::Set(d, 1), outside = hn::Set(d, -1);
    for (int first = 0; first < kPlaneBatch; first += lanes) {
        if ((which >> first & ((std::uint32_t{1} << lanes) - 1)) == 0) continue;  // no stamp in these lanes
        hn::Vec<DT> e[3], dx[3], dy[3];
        for (int k = 0; k < 3; ++k) {
            e[k] = hn::LoadU(d, t.e[k] + first);
            dx[k] = hn::LoadU(d, t.dx[k] + first);
            dy[k] = hn::LoadU(d, t.dy[k] + first);
        }
        const auto block_width = hn::LoadU(d, t.width + first), block_rows = hn::LoadU(d, t.rows + first);
        auto row = hn::Zero(d);
        for (int r = 0; r < rows; ++r, row = hn::Add(row, one)) {
            auto v0 = e[0], v1 = e[1], v2 = e[2];
            auto column = hn::Zero(d), bit = one, bits = hn::Zero(d);
            for (int c = 0; c < width; ++c, column = hn::Add(column, one), bit = hn::Add(bit, bit)) {
                // All three are >= 0 exactly when their bitwise or is > -1.
                const auto inside = hn::And(hn::Gt(hn::Or(hn::Or(v0, v1), v2), outside), hn::Lt(column, block_width));
                bits = hn::Or(bits, hn::IfThenElseZero(inside, bit));
                v0 = hn::Add(v0, dx[0]);
                v1 = hn::Add(v1, dx[1]);
                v2 = hn::Add(v2, dx[2]);
            }
            HWY_ALIGN std::int32_t row_bits[kPlaneBatch];
            hn::Store(hn::IfThenElseZero(hn::Lt(row, block_rows), bits), d, row_bits);
            for (int k = 0; k < lanes; ++k)
                masks[first + k] |= std::uint64_t{static_cast<std::uint32_t>(row_bits[k])} << (kStampSide * r);
            for (int k = 0; k < 3; ++k) e[k] = hn::Add(e[k], dy[k]);
        }
    }
}

Stamped StampMasks(const PlaneBatch& batch, std::uint32_t narrow, const StampGrid& grid, StampEdges& edges,
                   std::uint64_t* masks) {
    Stamped stamped{SetUp(batch, grid, edges) & narrow, 0};
    int width = 0, rows = 0, rows_each = 0, count = 0;
    for (std::uint32_t left = stamped.triangles; left != 0; left &= left - 1) {
        const int k = std::countr_zero(left);
        stamped.samples += static_cast<std::uint32_t>(edges.width[k] * edges.rows[k]);
        width = std::max(width, edges.width[k]);
        rows = std::max(rows, edges.rows[k]);
        rows_each += edges.rows[k];
        ++count;
    }
    if (stamps_at_once(width, rows, count, rows_each)) {
        Masks(edges, stamped.triangles, width, rows, masks);
    } else {
        for (std::uint32_t left = stamped.triangles; left != 0; left &= left - 1) {
            const int k = std::countr_zero(left);
            masks[k] = Mask(edges, k);
        }
    }
    return stamped;
}

}  // namespace rast::fast::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rast::fast::detail {

HWY_EXPORT(StampMasks);

Stamped stamp_masks(const PlaneBatch& batch, std::uint32_t narrow, const StampGrid& grid, StampEdges& edges,
                    std::uint64_t* masks) {
    return HWY_DYNAMIC_DISPATCH(StampMasks)(batch, narrow, grid, edges, masks);
}

}  // namespace rast::fast::detail
#endif  // HWY_ONCE
