// Highway compiles this file once per SIMD target (foreach_target) and dispatches to the best one the
// CPU supports at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "place_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "place_batch.h"

#include <rast/filters/orientation.h>

#include <algorithm>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace rast::fast::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::CappedTag<double, kPlaceBatch>;
using DI = hn::RebindToSigned<D>;
using DI32 = hn::Rebind<std::int32_t, D>;
using V = hn::Vec<D>;

// A triangle is nine doubles: corner k's x, y, z at 3k, 3k + 1, 3k + 2.
static_assert(sizeof(Triangle) == 9 * sizeof(double));

template <class Mask>
std::uint32_t bits_of(Mask m, int first) {
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(D(), m, bytes);
    std::uint32_t bits = 0;
    std::memcpy(&bits, bytes, sizeof bits);
    return bits << first;
}

// Corner k of the triangles t[first, first + count) in lanes: x[k], y[k], z[k]. The lanes past the count
// read the last triangle again.
HWY_INLINE void GatherCorners(const Triangle* t, int first, int count, V* x, V* y, V* z) {
    const D d;
    const DI di;
    const auto lane = hn::Min(hn::Iota(di, 0), hn::Set(di, count - 1));
    const auto index = hn::Add(hn::ShiftLeft<3>(lane), lane);  // 9 doubles a triangle
    const double* base = &t[first].v[0].x;
    for (int k = 0; k < 3; ++k) {
        x[k] = hn::GatherIndex(d, base + 3 * k, index);
        y[k] = hn::GatherIndex(d, base + 3 * k + 1, index);
        z[k] = hn::GatherIndex(d, base + 3 * k + 2, index);
    }
}

HWY_INLINE V MinOf(const V* c) { return hn::Min(hn::Min(c[0], c[1]), c[2]); }
HWY_INLINE V MaxOf(const V* c) { return hn::Max(hn::Max(c[0], c[1]), c[2]); }

// Corner k counter-clockwise: a clockwise triangle's corners 1 and 2 trade places.
template <class Mask>
HWY_INLINE V CounterClockwise(const V* c, int k, Mask clockwise) {
    return k == 0 ? c[0] : hn::IfThenElse(clockwise, c[3 - k], c[k]);
}

// The lanes `small` of v, whole numbers below 2^31, as int32 at to[first, ...): the other lanes are stored
// as zero, which converts.
template <class Mask>
HWY_INLINE void StoreSmallInts(V v, Mask small, std::int32_t* to, int first) {
    const DI32 di32;
    hn::StoreU(hn::DemoteTo(di32, hn::IfThenElseZero(small, v)), di32, to + first);
}

// place_small_fixed's steps, in its terms (setup.h), for every lane at once.
void PlaceSmallBatch(const Triangle* t, int n, const PlaceGrid& g, PlacedBatch& out) {
    const D d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    out.small = out.culled = out.general = out.undecided = out.narrow = 0;
    const V scale = hn::Set(d, g.scale), unit = hn::Set(d, g.unit), limit = hn::Set(d, g.limit);
    const V round = hn::Set(d, 0x1.8p52), minus_one = hn::Set(d, -1), zero = hn::Zero(d);
    for (int first = 0; first < n; first += lanes) {
        const int count = std::min(lanes, n - first);  // the lanes past it are in no mask
        V x[3], y[3], z[3];
        GatherCorners(t, first, count, x, y, z);
        auto in_range = hn::FirstN(d, static_cast<std::size_t>(count));
        for (int k = 0; k < 3; ++k) {
            // Within the range (false for NaN); grid_units (snap.h): the sum rounds to an integer.
            in_range = hn::And(in_range, hn::And(hn::Le(hn::Abs(x[k]), limit), hn::Le(hn::Abs(y[k]), limit)));
            x[k] = hn::Sub(hn::Add(hn::Mul(x[k], scale), round), round);
            y[k] = hn::Sub(hn::Add(hn::Mul(y[k], scale), round), round);
        }
        // The cross product: its products exact below 2^53, and then their difference's sign and zero too.
        const V dx1 = hn::Sub(x[1], x[0]), dy1 = hn::Sub(y[1], y[0]);
        const V dx2 = hn::Sub(x[2], x[0]), dy2 = hn::Sub(y[2], y[0]);
        const V p = hn::Mul(dx1, dy2), q = hn::Mul(dy1, dx2);
        const auto exact = hn::Lt(hn::Max(hn::Abs(p), hn::Abs(q)), hn::Set(d, 0x1p53));
        const V cross = hn::Sub(p, q);
        // pixel_range in fixed units: floor division by 2^bits, exact; then clamped and clipped.
        const auto range = [&](V lo, V hi, double o_min, double o_max, double size, V& from, V& to) {
            const V top = hn::Set(d, size);
            from = hn::Neg(hn::Floor(hn::Mul(hn::Sub(hn::Set(d, o_max), lo), unit)));
            to = hn::Floor(hn::Mul(hn::Sub(hi, hn::Set(d, o_min)), unit));
            from = hn::Max(hn::Min(hn::Max(from, minus_one), top), zero);
            to = hn::Min(hn::Min(hn::Max(to, minus_one), top), hn::Sub(top, hn::Set(d, 1)));
            return hn::Le(from, to);
        };
        V i_lo, i_hi, j_lo, j_hi;
        const V x_min = MinOf(x), x_max = MaxOf(x), y_min = MinOf(y), y_max = MaxOf(y);
        const auto on_x = range(x_min, x_max, g.sx_min, g.sx_max, g.width, i_lo, i_hi);
        const auto on_y = range(y_min, y_max, g.sy_min, g.sy_max, g.height, j_lo, j_hi);
        // narrow_edges: 2 w (w + scale) + 1 < 2^31, w the larger extent; exact below 2^53, and a rounded
        // value of 2^53 or more is still past 2^31.
        const V w = hn::Max(hn::Sub(x_max, x_min), hn::Sub(y_max, y_min));
        const V bound = hn::Add(hn::Mul(hn::Add(w, w), hn::Add(w, scale)), hn::Set(d, 1));
        const auto narrow = hn::Lt(bound, hn::Set(d, 0x1p31));
        const V side = hn::Set(d, g.small_side);
        const auto small_box = hn::And(hn::Lt(hn::Sub(i_hi, i_lo), side), hn::Lt(hn::Sub(j_hi, j_lo), side));
        // Out of range: general; zero area or no pixel: culled; a box too big: general. A depth that is not
        // finite makes the lane general too, where the caller's check of every coordinate finds it.
        const auto finite = hn::And(hn::And(hn::IsFinite(z[0]), hn::IsFinite(z[1])), hn::IsFinite(z[2]));
        const auto decided = hn::And(hn::And(in_range, exact), finite);
        const auto culled = hn::And(decided, hn::Or(hn::Eq(cross, zero), hn::Not(hn::And(on_x, on_y))));
        const auto small = hn::AndNot(culled, hn::And(decided, small_box));
        const auto first_n = hn::FirstN(d, static_cast<std::size_t>(count));
        out.general |= bits_of(hn::AndNot(hn::And(in_range, finite), first_n), first);
        out.undecided |= bits_of(hn::AndNot(exact, hn::And(in_range, finite)), first);
        out.culled |= bits_of(culled, first);
        out.general |= bits_of(hn::AndNot(small, hn::AndNot(culled, decided)), first);
        out.small |= bits_of(small, first);
        out.narrow |= bits_of(hn::And(small, narrow), first);
        const auto clockwise = hn::Lt(cross, zero);
        for (int k = 0; k < 3; ++k) {  // only the small lanes are read
            StoreSmallInts(CounterClockwise(x, k, clockwise), small, out.x[k], first);
            StoreSmallInts(CounterClockwise(y, k, clockwise), small, out.y[k], first);
            hn::StoreU(CounterClockwise(z, k, clockwise), d, out.z[k] + first);
        }
        StoreSmallInts(i_lo, small, out.i_lo, first);
        StoreSmallInts(i_hi, small, out.i_hi, first);
        StoreSmallInts(j_lo, small, out.j_lo, first);
        StoreSmallInts(j_hi, small, out.j_hi, first);
    }
}

// place<Fault::none>'s steps for the float modes (setup.h), for every lane at once.
void PlaceFloatBatch(const Triangle* t, int n, const PlaceGrid& g, FloatPlacedBatch& out) {
    const D d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    out.small = out.culled = 0;
    const V minus_one = hn::Set(d, -1), zero = hn::Zero(d);
    for (int first = 0; first < n; first += lanes) {
        const int count = std::min(lanes, n - first);  // the lanes past it are in no mask
        V x[3], y[3], z[3];
        GatherCorners(t, first, count, x, y, z);
        auto finite = hn::FirstN(d, static_cast<std::size_t>(count));
        for (int k = 0; k < 3; ++k)
            finite = hn::And(finite, hn::And(hn::IsFinite(x[k]), hn::And(hn::IsFinite(y[k]), hn::IsFinite(z[k]))));
        // filters::orientation(p = corner 0, q = corner 1, r = corner 2) with its Sound weights (1), as written
        // there, and its certain_sign: the lanes it leaves open (0) go to place's exact orientation.
        const V left = hn::Mul(hn::Sub(x[1], x[0]), hn::Sub(y[2], y[0]));
        const V right = hn::Mul(hn::Sub(y[1], y[0]), hn::Sub(x[2], x[0]));
        const V bound =
            hn::Add(hn::Mul(hn::Set(d, filters::kOrientationRelative), hn::Add(hn::Abs(left), hn::Abs(right))),
                    hn::Set(d, filters::kOrientationUnderflow));
        const V det = hn::Sub(left, right);
        const auto counter_clockwise = hn::Gt(det, bound), clockwise = hn::Lt(det, hn::Neg(bound));
        // pixel_range: clamped to [-1, size], where ceil and floor are its truncations corrected by one;
        // then clip_range.
        const auto range = [&](V lo, V hi, double o_min, double o_max, double size, V& from, V& to) {
            const V top = hn::Set(d, size);
            from = hn::Ceil(hn::Min(hn::Max(hn::Sub(lo, hn::Set(d, o_max)), minus_one), top));
            to = hn::Floor(hn::Min(hn::Max(hn::Sub(hi, hn::Set(d, o_min)), minus_one), top));
            from = hn::Max(from, zero);
            to = hn::Min(to, hn::Sub(top, hn::Set(d, 1)));
            return hn::Le(from, to);
        };
        V i_lo, i_hi, j_lo, j_hi;
        const auto on_x = range(MinOf(x), MaxOf(x), g.sx_min, g.sx_max, g.width, i_lo, i_hi);
        const auto on_y = range(MinOf(y), MaxOf(y), g.sy_min, g.sy_max, g.height, j_lo, j_hi);
        const V side = hn::Set(d, g.small_side);
        const auto small_box = hn::And(hn::Lt(hn::Sub(i_hi, i_lo), side), hn::Lt(hn::Sub(j_hi, j_lo), side));
        const auto decided = hn::And(finite, hn::Or(counter_clockwise, clockwise));
        const auto culled = hn::AndNot(hn::And(on_x, on_y), decided);
        const auto small = hn::And(hn::AndNot(culled, decided), small_box);
        out.culled |= bits_of(culled, first);
        out.small |= bits_of(small, first);
        for (int k = 0; k < 3; ++k) {  // only the small lanes are read
            hn::StoreU(CounterClockwise(x, k, clockwise), d, out.x[k] + first);
            hn::StoreU(CounterClockwise(y, k, clockwise), d, out.y[k] + first);
            hn::StoreU(CounterClockwise(z, k, clockwise), d, out.z[k] + first);
        }
        StoreSmallInts(i_lo, small, out.i_lo, first);
        StoreSmallInts(i_hi, small, out.i_hi, first);
        StoreSmallInts(j_lo, small, out.j_lo, first);
        StoreSmallInts(j_hi, small, out.j_hi, first);
    }
}

}  // namespace rast::fast::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rast::fast::detail {

HWY_EXPORT(PlaceSmallBatch);
HWY_EXPORT(PlaceFloatBatch);

void place_small_batch(const Triangle* t, int n, const PlaceGrid& grid, PlacedBatch& out) {
    HWY_DYNAMIC_DISPATCH(PlaceSmallBatch)(t, n, grid, out);
}

void place_float_batch(const Triangle* t, int n, const PlaceGrid& grid, FloatPlacedBatch& out) {
    HWY_DYNAMIC_DISPATCH(PlaceFloatBatch)(t, n, grid, out);
}

}  // namespace rast::fast::detail
#endif  // HWY_ONCE
