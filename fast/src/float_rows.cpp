// The float modes' covered samples of a block, row by row, each edge's crossing found by a search rather
// than an evaluation at every sample. Highway compiles this file once per SIMD target (foreach_target) and
// dispatches to the best one the CPU supports at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "float_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace rast::fast::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Coverage::Kind::float32 / float64 in T, rows in lanes. Along a row, E = T(d1 (py - ay)) - d3 (px - ax) is
// monotone in the column, every operation being correctly rounded on a monotone px (an infinity or NaN
// product is constant along the row or, for an infinite d3, changes once, at px = ax, where E is NaN and
// the sample not covered), so the columns an edge covers are the first n of the block where d3 > 0, the
// last width - n where d3 < 0, all or none where d3 = 0. n is estimated from the exact line and confirmed,
// or else found by bisection in bit_width(width) steps, each evaluating E exactly as the definition does:
// px = T(T(i0 + column) + sx), its integer part exact (|i| < 2^24 in float), one rounding added. A row's
// run is the three ranges' intersection.
//
// With d1 and d3 finite, E is monotone from row to row too (t1 = d1 (py - ay) is never NaN then; E is NaN
// only where t1 and d3 (px - ax) are infinities of one sign, at the end of its column where E's order puts
// an uncovered sample), so an edge covers the whole block if it covers the corner where E is least, and
// none of it if not the corner where E is greatest: most edges of a partial tile need no search (a big
// triangle's tile usually meets one of its edges).
template <class T>
void FloatRows(const Coverage& c, const Block& b, std::uint64_t* masks) {
    const hn::ScalableTag<T> d;
    using V = hn::Vec<decltype(d)>;
    constexpr std::size_t kMaxLanes = hn::MaxLanes(d);
    const int lanes = static_cast<int>(hn::Lanes(d));
    const int steps = std::bit_width(static_cast<unsigned>(b.width));
    const V zero = hn::Zero(d), one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5)), width = hn::Set(d, T(b.width));
    const V i0 = hn::Set(d, T(b.i0)), sx = hn::Set(d, T(b.sx));
    T ax[3], ay[3], d1[3], d3[3];
    for (int e = 0; e < 3; ++e) {
        ax[e] = T(c.ax[e]);
        ay[e] = T(c.ay[e]);
        d1[e] = T(c.d1[e]);
        d3[e] = T(c.d3[e]);
    }
    // A block one vector wide (a small triangle's) is evaluated at every sample, columns in lanes: over so
    // few samples the searches' fixed costs are more than the evaluation.
    if (b.width <= lanes) {
        const V px = hn::Add(hn::Add(i0, hn::Iota(d, T(0))), sx);
        for (int r = 0; r < b.rows; ++r) {
            const T py = T(double(b.j0 + r) + b.sy);
            auto covered = hn::FirstN(d, static_cast<std::size_t>(b.width));
            for (int e = 0; e < 3; ++e) {
                const V t1 = hn::Set(d, d1[e] * (py - ay[e]));
                const V value = hn::Sub(t1, hn::Mul(hn::Set(d, d3[e]), hn::Sub(px, hn::Set(d, ax[e]))));
                auto inside = hn::Gt(value, zero);
                if (c.inclusive[e]) inside = hn::Or(inside, hn::Eq(value, zero));
                covered = hn::And(covered, inside);
            }
            std::uint8_t bytes[8] = {};
            hn::StoreMaskBits(d, covered, bytes);
            std::memcpy(&masks[r], bytes, 8);
        }
        return;
    }
    const auto covered_at = [&](int e, int r, int k) {
        const T px = T(b.i0) + T(k) + T(b.sx), py = T(double(b.j0 + r) + b.sy);
        const T value = d1[e] * (py - ay[e]) - d3[e] * (px - ax[e]);
        return value > 0 || (value == 0 && c.inclusive[e]);
    };
    bool search[3];
    for (int e = 0; e < 3; ++e) {
        search[e] = true;
        if (!std::isfinite(d1[e]) || !std::isfinite(d3[e])) continue;
        const int least_row = d1[e] >= 0 ? 0 : b.rows - 1, least_column = d3[e] >= 0 ? b.width - 1 : 0;
        if (covered_at(e, least_row, least_column)) {
            search[e] = false;
        } else if (!covered_at(e, b.rows - 1 - least_row, b.width - 1 - least_column)) {
            std::fill_n(masks, b.rows, std::uint64_t{0});
            return;
        }
    }
    // Each row's range so far, [first, end).
    constexpr std::size_t kSize = kRowLanes + kMaxLanes;
    HWY_ALIGN T py[kSize], first[kSize], end[kSize];
    const int rows = (b.rows + lanes - 1) / lanes * lanes;
    for (int r = 0; r < rows; ++r) {
        py[r] = T(double(b.j0 + r) + b.sy);  // T(y) rounded once
        first[r] = 0;
        end[r] = T(b.width);
    }
    const V start = hn::Add(i0, sx);  // about the block's first sample x, for the estimate
    for (int e = 0; e < 3; ++e) {
        if (!search[e]) continue;
        const V slope = hn::Set(d, d3[e]), x = hn::Set(d, ax[e]);
        const bool inclusive = c.inclusive[e], falling = d3[e] < 0;
        // Whether the row's range for the edge goes on past column `column` (covered there where d3 >= 0,
        // not covered where d3 < 0): E evaluated as the definition does.
        const auto ahead_at = [&](V t1, V column) {
            const V px = hn::Add(hn::Add(i0, column), sx);
            const V value = hn::Sub(t1, hn::Mul(slope, hn::Sub(px, x)));
            auto covered = hn::Gt(value, zero);
            if (inclusive) covered = hn::Or(covered, hn::Eq(value, zero));
            return falling ? hn::Not(covered) : covered;
        };
        for (int r = 0; r < rows; r += lanes) {
            const V t1 = hn::Mul(hn::Set(d, d1[e]), hn::Sub(hn::Load(d, py + r), hn::Set(d, ay[e])));
            // n, the first column not ahead: estimated where the exact line E = 0 crosses the row, and
            // taken where the evaluation confirms it (the column before ahead, n itself not); else, at
            // ties or where rounding moved the crossing, found by bisection.
            const V estimate = hn::Min(hn::Max(hn::Ceil(hn::Sub(hn::Add(x, hn::Div(t1, slope)), start)), zero), width);
            const auto before = hn::Or(hn::Eq(estimate, zero), ahead_at(t1, hn::Sub(estimate, one)));
            const auto after = hn::Or(hn::Eq(estimate, width), hn::Not(ahead_at(t1, estimate)));
            V n = estimate;
            if (!hn::AllTrue(d, hn::And(before, after))) {
                V lo = zero, hi = width;
                for (int k = 0; k < steps; ++k) {
                    const auto open = hn::Lt(lo, hi);
                    const V mid = hn::Floor(hn::Mul(hn::Add(lo, hi), half));
                    const auto ahead = hn::And(ahead_at(t1, mid), open);
                    lo = hn::IfThenElse(ahead, hn::Add(mid, one), lo);
                    hi = hn::IfThenElse(hn::AndNot(ahead, open), mid, hi);
                }
                n = lo;
            }
            if (falling) hn::Store(hn::Max(hn::Load(d, first + r), n), d, first + r);
            else hn::Store(hn::Min(hn::Load(d, end + r), n), d, end + r);
        }
    }
    // The ranges as bits, as many rows at a time as there are 64-bit lanes: all ones shifted down to end at
    // the range's last column and up to start at its first (both within 0..63 wherever it is not empty).
    const hn::ScalableTag<std::int64_t> di;
    const hn::Rebind<T, decltype(di)> dt;
    const hn::RebindToUnsigned<decltype(di)> du;
    const auto columns = [&](const T* at) {
        const hn::Rebind<std::int32_t, decltype(dt)> di32;
        if constexpr (sizeof(T) == 4) return hn::PromoteTo(di, hn::ConvertTo(di32, hn::Load(dt, at)));
        else return hn::ConvertTo(di, hn::Load(dt, at));
    };
    const auto all = hn::Set(du, ~std::uint64_t{0});
    const auto none = hn::Zero(di), top = hn::Set(di, 63), last = hn::Set(di, 1);
    for (int r = 0; r < b.rows; r += static_cast<int>(hn::Lanes(di))) {
        const auto from = columns(first + r), to = columns(end + r);
        const auto after = hn::BitCast(du, hn::Sub(top, hn::Min(hn::Max(hn::Sub(to, last), none), top)));
        const auto run = hn::And(hn::Shr(all, after), hn::Shl(all, hn::BitCast(du, hn::Min(from, top))));
        hn::StoreU(hn::IfThenElseZero(hn::RebindMask(du, hn::Gt(to, from)), run), du, masks + r);
    }
}

void FloatRowMasks(const Coverage& c, const Block& b, std::uint64_t* masks) {
    if (c.kind == Coverage::Kind::float32) FloatRows<float>(c, b, masks);
    else FloatRows<double>(c, b, masks);
}

}  // namespace rast::fast::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rast::fast::detail {

HWY_EXPORT(FloatRowMasks);

void float_row_masks(const Coverage& coverage, const Block& block, std::uint64_t* masks) {
    HWY_DYNAMIC_DISPATCH(FloatRowMasks)(coverage, block, masks);
}

}  // namespace rast::fast::detail
#endif  // HWY_ONCE
