// Highway compiles this file once per SIMD target (foreach_target) and dispatches to the best one the
// CPU supports at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "planes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "bounded.h"
#include "planes.h"

#include <cfloat>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace rast::fast::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::CappedTag<double, kPlaneBatch>;
using V = hn::Vec<D>;

// A Bounded (bounded.h) in lanes.
struct BoundedLanes {
    V v, e;
};

// make_plane and plane_over_box (setup.h) with the inputs' errors zero (planes.h), the Bounded operations
// written out as they evaluate, left to right. make_plane's b is (dx1 dz2 - dx2 dz1) / det, not
// -(dz1 dx2 - dz2 dx1) / det: on a flat plane that is -0, where make_plane's is +0.
void NarrowPlanes(PlaneBatch& t, const PlaneGrid& g) {
    const D d;
    const hn::Rebind<std::int32_t, D> di;
    const V u = hn::Set(d, kUnitDouble), tiny = hn::Set(d, DBL_TRUE_MIN), two_tiny = hn::Set(d, 2 * DBL_TRUE_MIN);
    const V unit = hn::Set(d, g.unit);
    for (int k = 0; k < kPlaneBatch; k += static_cast<int>(hn::Lanes(d))) {
        const auto whole = [&](const std::int32_t* p) { return hn::PromoteTo(d, hn::LoadU(di, p + k)); };
        // placed_of: grid units to pixels, exactly.
        const V x0 = hn::Mul(whole(t.x[0]), unit), y0 = hn::Mul(whole(t.y[0]), unit);
        const V dx1 = hn::Sub(hn::Mul(whole(t.x[1]), unit), x0), dy1 = hn::Sub(hn::Mul(whole(t.y[1]), unit), y0);
        const V dx2 = hn::Sub(hn::Mul(whole(t.x[2]), unit), x0), dy2 = hn::Sub(hn::Mul(whole(t.y[2]), unit), y0);
        const V det = hn::Sub(hn::Mul(dx1, dy2), hn::Mul(dx2, dy1)), abs_det = hn::Abs(det);
        const V z0 = hn::LoadU(d, t.z[0] + k);
        const V dz1 = hn::Sub(hn::LoadU(d, t.z[1] + k), z0), dz2 = hn::Sub(hn::LoadU(d, t.z[2] + k), z0);
        const BoundedLanes z1{dz1, hn::Mul(u, hn::Abs(dz1))}, z2{dz2, hn::Mul(u, hn::Abs(dz2))};
        const auto slope = [&](BoundedLanes z, V p, BoundedLanes w, V q) {
            const V m1 = hn::Mul(z.v, p), m2 = hn::Mul(w.v, q), n = hn::Sub(m1, m2);
            const V en = hn::Add(hn::Add(hn::Add(hn::Mul(hn::Abs(p), z.e), hn::Mul(hn::Abs(q), w.e)),
                                         hn::Mul(u, hn::Add(hn::Add(hn::Abs(m1), hn::Abs(m2)), hn::Abs(n)))),
                                 two_tiny);
            const V slope = hn::Div(n, det);
            return BoundedLanes{slope, hn::Add(hn::Add(hn::Div(en, abs_det), hn::Mul(u, hn::Abs(slope))), tiny)};
        };
        const BoundedLanes a = slope(z1, dy2, z2, dy1), b = slope(z2, dx1, z1, dx2);
        // plane_over_box: mul({|a|, a.e}, {reach, u reach}) along each axis, then |z0| + (tx + ty).
        const auto reach = [&](const std::int32_t* lo, double o_min, const std::int32_t* hi, double o_max, V v0) {
            return hn::Max(hn::Abs(hn::Sub(hn::Add(whole(lo), hn::Set(d, o_min)), v0)),
                           hn::Abs(hn::Sub(hn::Add(whole(hi), hn::Set(d, o_max)), v0)));
        };
        const auto term = [&](BoundedLanes s, V r) {
            const V magnitude = hn::Abs(s.v), r_e = hn::Mul(u, r), v = hn::Mul(magnitude, r);
            return BoundedLanes{v, hn::Add(hn::Add(hn::Add(hn::Add(hn::Mul(magnitude, r_e), hn::Mul(hn::Abs(r), s.e)),
                                                           hn::Mul(s.e, r_e)),
                                                   hn::Mul(u, hn::Abs(v))),
                                           tiny)};
        };
        const BoundedLanes tx = term(a, reach(t.i_lo, g.ox_min, t.i_hi, g.ox_max, x0));
        const BoundedLanes ty = term(b, reach(t.j_lo, g.oy_min, t.j_hi, g.oy_max, y0));
        const V sum = hn::Add(tx.v, ty.v), sum_e = hn::Add(hn::Add(tx.e, ty.e), hn::Mul(u, hn::Abs(sum)));
        const V z = hn::Add(hn::Abs(z0), sum), z_e = hn::Add(hn::Add(hn::Zero(d), sum_e), hn::Mul(u, hn::Abs(z)));
        const V err = hn::Mul(z_e, hn::Set(d, kSlack));
        hn::StoreU(a.v, d, t.a + k);
        hn::StoreU(b.v, d, t.b + k);
        hn::StoreU(hn::IfThenElse(hn::IsFinite(err), err, hn::Set(d, std::numeric_limits<double>::infinity())), d,
                   t.err + k);
    }
}

// bounded.h's operations in lanes, with their weight 1 (filters::Sound) and the association of their sums.
HWY_INLINE BoundedLanes SubLanes(BoundedLanes x, BoundedLanes y) {
    const D d;
    const V v = hn::Sub(x.v, y.v);
    return {v, hn::Add(hn::Add(x.e, y.e), hn::Mul(hn::Set(d, kUnitDouble), hn::Abs(v)))};
}

HWY_INLINE BoundedLanes AddLanes(BoundedLanes x, BoundedLanes y) {
    const D d;
    const V v = hn::Add(x.v, y.v);
    return {v, hn::Add(hn::Add(x.e, y.e), hn::Mul(hn::Set(d, kUnitDouble), hn::Abs(v)))};
}

// Its own rounding, u |v| + 2^-1074, for a product or quotient.
HWY_INLINE V RoundingLanes(V v) {
    const D d;
    return hn::Add(hn::Mul(hn::Set(d, kUnitDouble), hn::Abs(v)), hn::Set(d, DBL_TRUE_MIN));
}

HWY_INLINE BoundedLanes MulLanes(BoundedLanes x, BoundedLanes y) {
    const V v = hn::Mul(x.v, y.v);
    const V e = hn::Add(hn::Add(hn::Mul(hn::Abs(x.v), y.e), hn::Mul(hn::Abs(y.v), x.e)), hn::Mul(x.e, y.e));
    return {v, hn::Add(e, RoundingLanes(v))};
}

HWY_INLINE BoundedLanes DivLanes(BoundedLanes x, BoundedLanes y) {
    const D d;
    const V v = hn::Div(x.v, y.v);
    const V reach = hn::Mul(hn::Add(hn::Abs(v), hn::Set(d, DBL_TRUE_MIN)), y.e);
    const V e = hn::Add(hn::Div(hn::Add(x.e, reach), hn::Sub(hn::Abs(y.v), y.e)), RoundingLanes(v));
    return {v, hn::IfThenElse(hn::Gt(hn::Abs(y.v), y.e), e, hn::Set(d, std::numeric_limits<double>::infinity()))};
}

void MakePlanes(CornerBatch& t, const PlaneGrid& g) {
    const D d;
    const hn::Rebind<std::int32_t, D> di;
    const V u = hn::Set(d, kUnitDouble), zero = hn::Zero(d);
    for (int k = 0; k < kPlaneBatch; k += static_cast<int>(hn::Lanes(d))) {
        const auto exact = [&](const double* p) { return BoundedLanes{hn::LoadU(d, p + k), zero}; };
        const auto whole = [&](const std::int32_t* p) { return hn::PromoteTo(d, hn::LoadU(di, p + k)); };
        const BoundedLanes x0 = exact(t.x[0]), y0 = exact(t.y[0]), z0 = exact(t.z[0]);
        const BoundedLanes dx1 = SubLanes(exact(t.x[1]), x0), dy1 = SubLanes(exact(t.y[1]), y0);
        const BoundedLanes dx2 = SubLanes(exact(t.x[2]), x0), dy2 = SubLanes(exact(t.y[2]), y0);
        const BoundedLanes dz1 = SubLanes(exact(t.z[1]), z0), dz2 = SubLanes(exact(t.z[2]), z0);
        const BoundedLanes det = SubLanes(MulLanes(dx1, dy2), MulLanes(dx2, dy1));
        const BoundedLanes a = DivLanes(SubLanes(MulLanes(dz1, dy2), MulLanes(dz2, dy1)), det);
        const BoundedLanes b = DivLanes(SubLanes(MulLanes(dx1, dz2), MulLanes(dx2, dz1)), det);
        // plane_over_box
        const auto reach = [&](const std::int32_t* lo, double o_min, const std::int32_t* hi, double o_max, V v0) {
            return hn::Max(hn::Abs(hn::Sub(hn::Add(whole(lo), hn::Set(d, o_min)), v0)),
                           hn::Abs(hn::Sub(hn::Add(whole(hi), hn::Set(d, o_max)), v0)));
        };
        const V reach_x = reach(t.i_lo, g.ox_min, t.i_hi, g.ox_max, x0.v);
        const V reach_y = reach(t.j_lo, g.oy_min, t.j_hi, g.oy_max, y0.v);
        const BoundedLanes tx = MulLanes({hn::Abs(a.v), a.e}, {reach_x, hn::Mul(u, reach_x)});
        const BoundedLanes ty = MulLanes({hn::Abs(b.v), b.e}, {reach_y, hn::Mul(u, reach_y)});
        const BoundedLanes z = AddLanes({hn::Abs(z0.v), zero}, AddLanes(tx, ty));
        const V err = hn::Mul(z.e, hn::Set(d, kSlack));
        hn::StoreU(a.v, d, t.a + k);
        hn::StoreU(b.v, d, t.b + k);
        hn::StoreU(hn::IfThenElse(hn::IsFinite(err), err, hn::Set(d, std::numeric_limits<double>::infinity())), d,
                   t.err + k);
    }
}

}  // namespace rast::fast::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rast::fast::detail {

HWY_EXPORT(NarrowPlanes);
HWY_EXPORT(MakePlanes);

void narrow_planes(PlaneBatch& batch, const PlaneGrid& grid) {
    HWY_DYNAMIC_DISPATCH(NarrowPlanes)(batch, grid);
}

void make_planes(CornerBatch& batch, const PlaneGrid& grid) { HWY_DYNAMIC_DISPATCH(MakePlanes)(batch, grid); }

}  // namespace rast::fast::detail
#endif  // HWY_ONCE
