// Highway compiles this file once per SIMD target (foreach_target) and dispatches to the best one the
// CPU supports at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "row_masks.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels.h"
#include "spans.h"

#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace rast::fast::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DI = hn::ScalableTag<std::int64_t>;

// RowSpans (spans.h) on as many rows at once as there are 64-bit lanes: lane l walks rows l, l + N, l + 2N,
// ..., its floor(E / d) and remainder stepped by N rows at a time with the same exact integer operations
// as RowQuotient::next_row. Lanes past the block's rows compute rows below it (in range: a few steps
// more), which no caller reads.
void RowMasks(const RowEdges& edges, int width, int rows, std::uint64_t* masks) {
    using V = hn::Vec<DI>;
    const DI di;
    const hn::RebindToUnsigned<DI> du;
    const int lanes = static_cast<int>(hn::Lanes(di));
    V quotient[3], remainder[3], step_quotient[3], step_remainder[3], divisor[3];
    int sign[3];
    for (int k = 0; k < 3; ++k) {
        const std::int64_t p = edges.p[k], d = column_divisor(p);
        sign[k] = sign_of(p);
        // Rows 0 to N - 1 for the lanes, then row N for the step of N rows.
        HWY_ALIGN std::int64_t q[HWY_MAX_BYTES / sizeof(std::int64_t)], r[HWY_MAX_BYTES / sizeof(std::int64_t)];
        RowQuotient<std::int64_t> walk(edges.q[k], edges.step[k], d);
        for (int l = 0; l < lanes; ++l, walk.next_row()) {
            q[l] = walk.value();
            r[l] = walk.remainder();
        }
        std::int64_t step_q = walk.value() - q[0], step_r = walk.remainder() - r[0];
        if (step_r < 0) {
            step_r += d;
            step_q -= 1;
        }
        quotient[k] = hn::Load(di, q);
        remainder[k] = hn::Load(di, r);
        step_quotient[k] = hn::Set(di, step_q);
        step_remainder[k] = hn::Set(di, step_r);
        divisor[k] = hn::Set(di, d);
    }
    // Columns are clamped to [-1, width] (RowSpans' clamp_to: one past either end means none).
    const V before = hn::Set(di, -1), after = hn::Set(di, width), last = hn::Set(di, width - 1);
    const V zero = hn::Zero(di), one = hn::Set(di, 1), top = hn::Set(di, 63);
    const auto all = hn::Set(du, ~std::uint64_t{0});
    for (int row = 0; row < rows; row += lanes) {
        V lo = zero, hi = last;
        auto none = hn::Lt(one, zero);  // no lane
        for (int k = 0; k < 3; ++k) {
            const V f = quotient[k];
            if (sign[k] > 0) lo = hn::Max(lo, hn::Min(hn::Max(hn::Neg(f), before), after));
            else if (sign[k] < 0) hi = hn::Min(hi, hn::Min(hn::Max(f, before), after));
            else none = hn::Or(none, hn::Lt(f, zero));
            quotient[k] = hn::Add(quotient[k], step_quotient[k]);
            remainder[k] = hn::Add(remainder[k], step_remainder[k]);
            const auto carry = hn::Not(hn::Lt(remainder[k], divisor[k]));
            remainder[k] = hn::IfThenElse(carry, hn::Sub(remainder[k], divisor[k]), remainder[k]);
            quotient[k] = hn::IfThenElse(carry, hn::Add(quotient[k], one), quotient[k]);
        }
        // Bits lo..hi: all ones shifted down to end at hi, and up to start at lo (both within 0..63
        // wherever the run is not empty).
        const auto from = hn::BitCast(du, hn::Min(hn::Max(lo, zero), top));
        const auto to = hn::BitCast(du, hn::Min(hn::Max(hi, zero), top));
        const auto run = hn::And(hn::Shr(all, hn::Sub(hn::BitCast(du, top), to)), hn::Shl(all, from));
        const auto empty = hn::Or(hn::RebindMask(du, none), hn::RebindMask(du, hn::Gt(lo, hi)));
        hn::StoreU(hn::IfThenZeroElse(empty, run), du, masks + row);
    }
}

}  // namespace rast::fast::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rast::fast::detail {

HWY_EXPORT(RowMasks);

void row_masks(const RowEdges& edges, int width, int rows, std::uint64_t* masks) {
    HWY_DYNAMIC_DISPATCH(RowMasks)(edges, width, rows, masks);
}

}  // namespace rast::fast::detail
#endif  // HWY_ONCE
