// Highway compiles this file once per SIMD target (foreach_target) and dispatches to the best one the
// CPU supports at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels.h"

#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace rast::fast::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D>
std::uint64_t mask_bits(D d, hn::Mask<D> m) {
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(d, m, bytes);
    std::uint64_t bits = 0;
    std::memcpy(&bits, bytes, (hn::Lanes(d) + 7) / 8);
    return bits;
}

template <class D>
hn::Mask<D> lanes_of(D d, std::uint64_t bits) {
    std::uint8_t bytes[8];
    std::memcpy(bytes, &bits, sizeof bytes);
    return hn::LoadMaskBits(d, bytes);
}

std::uint64_t first_n(int n) { return n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1; }

std::uint64_t CoverageFixed(const std::int64_t* base, const std::int64_t* step, int n) {
    const hn::ScalableTag<std::int64_t> d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    HWY_ALIGN std::int64_t start[3][HWY_MAX_BYTES / sizeof(std::int64_t)];
    for (int e = 0; e < 3; ++e)
        for (int k = 0; k < lanes; ++k) start[e][k] = base[e] + k * step[e];
    auto e0 = hn::Load(d, start[0]), e1 = hn::Load(d, start[1]), e2 = hn::Load(d, start[2]);
    const auto s0 = hn::Set(d, step[0] * lanes), s1 = hn::Set(d, step[1] * lanes),
               s2 = hn::Set(d, step[2] * lanes);
    const auto zero = hn::Zero(d);
    std::uint64_t covered = 0;
    for (int k = 0; k < n; k += lanes) {
        // All three are >= 0 exactly when their bitwise or has a clear sign bit.
        const auto outside = hn::Lt(hn::Or(hn::Or(e0, e1), e2), zero);
        covered |= (mask_bits(d, hn::Not(outside))) << k;
        e0 = hn::Add(e0, s0);
        e1 = hn::Add(e1, s1);
        e2 = hn::Add(e2, s2);
    }
    return covered & first_n(n);
}

template <class T, class Edge>
std::uint64_t CoverageFloat(const Edge* edges, int i0, T sx, int n) {
    const hn::ScalableTag<T> d;
    const hn::RebindToSigned<decltype(d)> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto zero = hn::Zero(d);
    std::uint64_t covered = 0;
    for (int k = 0; k < n; k += lanes) {
        // i0 + k + lane converts exactly (|i| < 2^24), so this is T(i + sx) rounded once.
        const auto px = hn::Add(hn::ConvertTo(d, hn::Iota(di, i0 + k)), hn::Set(d, sx));
        auto inside = hn::FirstN(d, static_cast<std::size_t>(lanes));
        for (int e = 0; e < 3; ++e) {
            const Edge& edge = edges[e];
            const auto value =
                hn::Sub(hn::Set(d, edge.t1), hn::Mul(hn::Set(d, edge.d3), hn::Sub(px, hn::Set(d, edge.ax))));
            const auto on_edge = hn::And(hn::Eq(value, zero),
                                         hn::FirstN(d, edge.inclusive ? static_cast<std::size_t>(lanes) : 0));
            inside = hn::And(inside, hn::Or(hn::Gt(value, zero), on_edge));
        }
        covered |= mask_bits(d, inside) << k;
    }
    return covered & first_n(n);
}

std::uint64_t CoverageFloat32(const FloatEdgeRow<float>* edges, int i0, float sx, int n) {
    return CoverageFloat<float>(edges, i0, sx, n);
}

std::uint64_t CoverageFloat64(const FloatEdgeRow<double>* edges, int i0, double sx, int n) {
    return CoverageFloat<double>(edges, i0, sx, n);
}

std::uint64_t DepthRowImpl(const DepthRow& row, std::uint64_t covered, double* z, double* err,
                           std::int64_t* ids) {
    const hn::ScalableTag<double> d;
    const hn::RebindToSigned<decltype(d)> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto z0 = hn::Set(d, row.z0), a = hn::Set(d, row.a), b_dy = hn::Set(d, row.b_dy),
               x0 = hn::Set(d, row.x0), e = hn::Set(d, row.err), sx = hn::Set(d, row.sx);
    const auto id = hn::Set(di, row.id);
    const auto none = hn::Zero(di);
    // px = i + sx for the lanes: sums of integers below 2^25 and multiples of 1/16, exact.
    const auto advance = hn::Set(d, static_cast<double>(lanes));
    auto px = hn::Add(hn::Iota(d, static_cast<double>(row.i0)), sx);
    std::uint64_t undecided = 0;
    for (int k = 0; k < kRowLanes && covered >> k != 0; k += lanes, px = hn::Add(px, advance)) {
        const std::uint64_t bits = (covered >> k) & first_n(lanes);
        if (bits == 0) continue;
        const auto depth = hn::Add(z0, hn::Add(hn::Mul(a, hn::Sub(px, x0)), b_dy));
        const auto stored = hn::LoadU(d, z + k), stored_err = hn::LoadU(d, err + k);
        const auto stored_id = hn::LoadU(di, ids + k);
        const auto finite = hn::IsFinite(depth);
        const auto empty = hn::RebindMask(d, hn::Lt(stored_id, none));
        const auto nearer = hn::Lt(hn::Add(depth, e), hn::Sub(stored, stored_err));
        const auto farther = hn::Gt(hn::Sub(depth, e), hn::Add(stored, stored_err));
        const auto mask = lanes_of(d, bits);
        const auto write = hn::And(mask, hn::Or(hn::And(empty, finite), hn::And(hn::Not(empty), nearer)));
        hn::StoreU(hn::IfThenElse(write, depth, stored), d, z + k);
        hn::StoreU(hn::IfThenElse(write, e, stored_err), d, err + k);
        hn::StoreU(hn::IfThenElse(hn::RebindMask(di, write), id, stored_id), di, ids + k);
        const auto open = hn::AndNot(hn::Or(write, hn::And(hn::Not(empty), farther)), mask);
        undecided |= mask_bits(d, open) << k;
    }
    return undecided;
}

}  // namespace rast::fast::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rast::fast::detail {

HWY_EXPORT(CoverageFixed);
HWY_EXPORT(CoverageFloat32);
HWY_EXPORT(CoverageFloat64);
HWY_EXPORT(DepthRowImpl);

std::uint64_t coverage_fixed(const std::int64_t* base, const std::int64_t* step, int n) {
    return HWY_DYNAMIC_DISPATCH(CoverageFixed)(base, step, n);
}

std::uint64_t coverage_float32(const FloatEdgeRow<float>* edges, int i0, float sx, int n) {
    return HWY_DYNAMIC_DISPATCH(CoverageFloat32)(edges, i0, sx, n);
}

std::uint64_t coverage_float64(const FloatEdgeRow<double>* edges, int i0, double sx, int n) {
    return HWY_DYNAMIC_DISPATCH(CoverageFloat64)(edges, i0, sx, n);
}

std::uint64_t depth_row(const DepthRow& row, std::uint64_t covered, double* z, double* err,
                        std::int64_t* ids) {
    return HWY_DYNAMIC_DISPATCH(DepthRowImpl)(row, covered, z, err, ids);
}

}  // namespace rast::fast::detail
#endif  // HWY_ONCE
