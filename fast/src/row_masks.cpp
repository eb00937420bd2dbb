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

// floor(Q / d) and its remainder Q - floor(Q / d) d, in [0, d), for a Q that is a whole number of rows'
// steps: a step of n rows from a step of one, without dividing.
struct Stride {
    std::int64_t quotient, remainder;
    Stride twice(std::int64_t d) const {
        const std::int64_t r = 2 * remainder, carry = r >= d;
        return {2 * quotient + carry, r - carry * d};
    }
};

// quotient and remainder advanced by a step's (both remainders in [0, d): at most one carry), as
// RowQuotient::next_row does.
HWY_INLINE void Advance(hn::Vec<DI>& quotient, hn::Vec<DI>& remainder, hn::Vec<DI> step_quotient,
                        hn::Vec<DI> step_remainder, hn::Vec<DI> d) {
    quotient = hn::Add(quotient, step_quotient);
    remainder = hn::Add(remainder, step_remainder);
    const auto carry = hn::Gt(remainder, hn::Sub(d, hn::Set(DI(), 1)));  // remainder >= d, no mask negated
    remainder = hn::IfThenElse(carry, hn::Sub(remainder, d), remainder);
    quotient = hn::IfThenElse(carry, hn::Add(quotient, hn::Set(DI(), 1)), quotient);
}

// RowSpans (spans.h) on as many rows at once as there are 64-bit lanes: lane l walks rows l, l + N, l + 2N,
// ..., its floor(E / d) and remainder stepped by N rows at a time with the same exact integer operations
// as RowQuotient::next_row. Lanes past the block's rows compute rows below it (in range: a few steps
// more), which no caller reads.
void RowMasks(const RowEdges& edges, int width, int rows, std::uint64_t* masks) {
    using V = hn::Vec<DI>;
    const DI di;
    const hn::RebindToUnsigned<DI> du;
    const int lanes = static_cast<int>(hn::Lanes(di));
    const V zero = hn::Zero(di), one = hn::Set(di, 1), lane = hn::Iota(di, 0);
    V quotient[3], remainder[3], step_quotient[3], step_remainder[3], divisor[3];
    int sign[3];
    for (int k = 0; k < 3; ++k) {
        const std::int64_t p = edges.p[k], d = column_divisor(p);
        sign[k] = sign_of(p);
        // Lane l starts at row l: row 0 plus the strides of 1, 2, 4, ... rows its index is made of (scalar
        // values stored for a vector load stalled on the store forwarding: 65% of this kernel's time).
        const std::int64_t q0 = floor_div(edges.q[k], d), s0 = floor_div(edges.step[k], d);
        Stride stride{s0, edges.step[k] - s0 * d};
        V q = hn::Set(di, q0), r = hn::Set(di, edges.q[k] - q0 * d);
        const V dv = hn::Set(di, d);
        for (int span = 1; span < lanes; span *= 2, stride = stride.twice(d)) {
            const auto taken = hn::TestBit(lane, hn::Set(di, span));
            Advance(q, r, hn::IfThenElseZero(taken, hn::Set(di, stride.quotient)),
                    hn::IfThenElseZero(taken, hn::Set(di, stride.remainder)), dv);
        }
        quotient[k] = q;
        remainder[k] = r;
        step_quotient[k] = hn::Set(di, stride.quotient);  // the stride of N rows
        step_remainder[k] = hn::Set(di, stride.remainder);
        divisor[k] = dv;
    }
    // Columns are clamped to [-1, width] (RowSpans' clamp_to: one past either end means none).
    const V before = hn::Set(di, -1), after = hn::Set(di, width), last = hn::Set(di, width - 1);
    const V top = hn::Set(di, 63);
    const auto all = hn::Set(du, ~std::uint64_t{0});
    for (int row = 0; row < rows; row += lanes) {
        V lo = zero, hi = last;
        auto none = hn::Lt(one, zero);  // no lane
        for (int k = 0; k < 3; ++k) {
            const V f = quotient[k];
            if (sign[k] > 0) lo = hn::Max(lo, hn::Min(hn::Max(hn::Neg(f), before), after));
            else if (sign[k] < 0) hi = hn::Min(hi, hn::Min(hn::Max(f, before), after));
            else none = hn::Or(none, hn::Lt(f, zero));
            Advance(quotient[k], remainder[k], step_quotient[k], step_remainder[k], divisor[k]);
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
