// The depth plane of a triangle in double-double arithmetic, with a rigorous error bound: the filter in
// front of the exact depths of exact_depth.h. It decides the nearest double to a depth (the classic
// rounding test) and most (z, id) comparisons without big integers and without changing the rounding mode.
//
// The plane is anchored at vertex 0: z(x, y) = z0 + p (x - x0) + q (y - y0), with p = A / W, q = B / W
// and W, A, B sums of products of the vertices' coordinates and their differences (W is twice the
// signed area), each summed exactly and rounded to a double-double with a bound. Every step
// below states its error; all bounds hold under round to nearest when no operation underflows or
// overflows, which the safe range guarantees (see in_safe_range).
//
// Each bound is a sum of terms (filters/weights.h): the roundings of the step, measured a posteriori on
// the values it rounded (u |result| for each rounded operation, u = 2^-53), and the errors its inputs
// already carry. The Weights policy weighs them; the engine's is Sound, and the tests weaken one term at
// a time (filter_bounds_test.cpp, docs/filters.md). Each final factor (1 + 2^-48) covers the rounding of
// the bound's own computation and the second-order terms, as stated: it is proven, not testable.
#pragma once

#include "double_double.h"

#include <rast/filters/weights.h>
#include <rast/scene.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

namespace rast::reference::detail {

// A value known to lie in [value - err, value + err], value = hi + lo.
struct Bounded {
    DoubleDouble value;
    double err = 0;
};

// The terms of the bounds below.
enum class SumTerm { rounding };                            // ProductSum
enum class QuotientTerm { rounding, dividend, divisor };    // divide
enum class AffineTerm { rounding, base, slope };            // affine and AffineLower
enum class DifferenceTerm { first, second };                // certain_sign_of_difference

// Coordinates 0 or of magnitude in [2^-100, 2^100] (sample positions, multiples of 1/16 up to 2^31, are
// too). Then every coordinate and every difference of two is 0 or a multiple of 2^-152 (the last bit of
// 2^-100) of magnitude at most 2^101; W, A and B are 0 or in [2^-304, 2^205]; p and q are 0 or in
// [2^-509, 2^509]; depths at samples stay below 2^612; and every product the evaluation forms is 0 or
// above 2^-900. Nothing underflows or overflows, so every error bound below holds.
inline bool in_safe_range(double v) {
    const double m = std::abs(v);
    return m == 0 || (m >= 0x1p-100 && m <= 0x1p100);
}

// A sum of exact products of double-doubles, as a double-double with its error bound. Each product
// x y is the exact sum of the two-products of the parts (two doubles each; four parts when a low part
// is not 0). Each part is added as Joldes, Muller and Popescu's DWPlusFP (2017) adds a double to a
// double-double, whose one rounded operation, t = sum.lo + s.lo, errs by at most u |t|: the bound is u
// times the sum of those |t| (SumTerm::rounding).
template <class Weights = filters::Sound>
class ProductSum {
public:
    void add(DoubleDouble x, DoubleDouble y) {
        term(x.hi, y.hi);
        // Differences of nearby coordinates are exact (Sterbenz), so the low parts are mostly 0.
        if (y.lo != 0) term(x.hi, y.lo);
        if (x.lo != 0) {
            term(x.lo, y.hi);
            if (y.lo != 0) term(x.lo, y.lo);
        }
    }
    Bounded sum() const {
        return {sum_, Weights::weight(SumTerm::rounding) * kUnitRoundoff * rounded_ * (1 + 0x1p-48)};
    }

private:
    void plus(double y) {  // DWPlusFP
        const DoubleDouble s = two_sum(sum_.hi, y);
        const double t = sum_.lo + s.lo;
        rounded_ += std::abs(t);
        sum_ = two_sum(s.hi, t);
    }
    void term(double x, double y) {
        const DoubleDouble product = two_prod(x, y);
        plus(product.hi);
        plus(product.lo);
    }

    DoubleDouble sum_;
    double rounded_ = 0;  // the sum of |t| over the additions
};

// x / y, given |y.hi| (1 - 2^-50) > 4 y.err. With q = RN(x.hi / y.hi), the remainder x.hi - q y.hi is
// a double (the FMA computes it exactly), so R = x - q y = remainder + x.lo - q y.lo exactly, computed as
// r with two roundings: t = remainder + x.lo (error below u |t|) and the FMA r = t - q y.lo (below u |r|).
// The correction c = RN(r / y.hi) errs by at most u |c| more, and dividing by y.hi rather than y by
// |R| |y.lo| / (|y| |y.hi|) <= |r| |y.lo| / |y.hi|^2 (1 + 2^-50): QuotientTerm::rounding. The inputs' own
// errors add x.err / |y| (dividend) and |x/y| y.err / |y| (divisor), with |x/y| <= |q| (1 + 2^-50) and
// |y| >= |y.hi| (1 - 2^-50) - y.err.
template <class Weights = filters::Sound>
Bounded divide(const Bounded& x, const Bounded& y) {
    const double q = x.value.hi / y.value.hi;
    const double remainder = std::fma(-q, y.value.hi, x.value.hi);
    const double t = remainder + x.value.lo;
    const double r = std::fma(-q, y.value.lo, t);
    const double c = r / y.value.hi;
    const double ahi = std::abs(y.value.hi);
    const double rounding = (kUnitRoundoff * (std::abs(t) + std::abs(r)) + std::abs(r) * std::abs(y.value.lo) / ahi) / ahi +
                            kUnitRoundoff * std::abs(c);
    const double least_y = ahi * (1 - 0x1p-50) - y.err;
    const double dividend = x.err / least_y;
    const double divisor = std::abs(q) * (1 + 0x1p-50) * y.err / least_y;
    return {two_sum(q, c), (Weights::weight(QuotientTerm::rounding) * rounding +
                            Weights::weight(QuotientTerm::dividend) * dividend +
                            Weights::weight(QuotientTerm::divisor) * divisor) *
                               (1 + 0x1p-48)};
}

// base + slope (v - origin), v and origin in the safe range. With d = v - origin exactly (two-sum) and
// m = slope.hi d.hi exactly (two-product), the rest is slope.hi d.lo + slope.lo d.hi + m.lo, computed by
// two FMAs, t1 = slope.lo d.hi + m.lo and rest = slope.hi d.lo + t1; with s = base.hi + m.hi exactly, the
// low parts add in two more roundings, t2 = base.lo + rest and t3 = t2 + s.lo, and s.hi + t3 is exact.
// Each rounding errs by at most u times its result, and the dropped slope.lo d.lo adds its magnitude:
// AffineTerm::rounding. The inputs' own errors add base.err (base) and slope.err |v - origin| (slope),
// with |v - origin| <= |d.hi| (1 + u).
template <class Weights = filters::Sound>
Bounded affine(const Bounded& base, const Bounded& slope, double v, double origin) {
    const DoubleDouble d = two_sum(v, -origin);
    const DoubleDouble m = two_prod(slope.value.hi, d.hi);
    const double t1 = std::fma(slope.value.lo, d.hi, m.lo);
    const double rest = std::fma(slope.value.hi, d.lo, t1);
    const DoubleDouble s = two_sum(base.value.hi, m.hi);
    const double t2 = base.value.lo + rest;
    const double t3 = t2 + s.lo;
    const double rounding = kUnitRoundoff * (std::abs(t1) + std::abs(rest) + std::abs(t2) + std::abs(t3)) +
                            std::abs(slope.value.lo) * std::abs(d.lo);
    return {two_sum(s.hi, t3), (Weights::weight(AffineTerm::rounding) * rounding +
                                Weights::weight(AffineTerm::base) * base.err +
                                Weights::weight(AffineTerm::slope) * slope.err * std::abs(d.hi)) *
                                   (1 + 0x1p-48)};
}

// A lower bound on the value affine(base, slope, v, origin) encloses, in a fifth of its operations: the
// cheap test in front of it. With d, m and s the rounded v - origin, slope.hi d and base.hi + m, the
// exact value is base + slope (v - origin), which differs from s by at most
//   |base.lo| + base.err                                 (AffineTerm::base)
//   + (|slope.lo| + slope.err) |v - origin|               (AffineTerm::slope)
//   + |slope.hi| u |d| + u |m| <= 2^-52 |slope.hi| |d| (1 + u)   (rounding d and m)
//   + u |s|                                               (rounding s),
// with |v - origin| <= |d| (1 + 2u). Subtracting the bound from s rounds by at most u (|s| + bound). As
// |s| <= (|base.hi| + |slope.hi| |d| (1 + u)) (1 + u), the two u |s| are below 2^-51 (|base.hi| +
// |slope.hi| |d|); with the 2^-52 above, the roundings are AffineTerm::rounding. The bound is affine in
// |d| with coefficients fixed along a row, so a sample pays one multiply-add for it. The factors
// (1 + 2^-48) cover the remaining u bound and the rounding of the coefficients and of the bound.
template <class Weights = filters::Sound>
class AffineLower {
public:
    AffineLower(const Bounded& base, const Bounded& slope, double origin)
        : base_(base.value.hi),
          slope_(slope.value.hi),
          origin_(origin),
          at_origin_((Weights::weight(AffineTerm::base) * (std::abs(base.value.lo) + base.err) +
                      Weights::weight(AffineTerm::rounding) * 0x1p-51 * std::abs(base.value.hi)) *
                     (1 + 0x1p-48)),
          per_d_((Weights::weight(AffineTerm::slope) * (std::abs(slope.value.lo) + slope.err) * (1 + 0x1p-50) +
                  Weights::weight(AffineTerm::rounding) * (0x1p-52 * (1 + 0x1p-50) + 0x1p-51) *
                      std::abs(slope.value.hi)) *
                 (1 + 0x1p-48)) {}

    double operator()(double v) const {
        const double d = v - origin_;
        return (base_ + slope_ * d) - (at_origin_ + per_d_ * std::abs(d));
    }

private:
    double base_, slope_, origin_;
    double at_origin_, per_d_;  // the bound is at_origin_ + per_d_ |d|
};

class BoundedPlane {
public:
    // The plane of t, or nothing when a coordinate is outside the safe range or the area is too small
    // for the bound on W to keep its sign (then the exact depth decides everything).
    template <class Weights = filters::Sound>
    static std::optional<BoundedPlane> make(const Triangle& t) {
        for (const Vertex& v : t.v)
            if (!in_safe_range(v.x) || !in_safe_range(v.y) || !in_safe_range(v.z)) return std::nullopt;
        // W = (x1 - x0)(y2 - y0) - (x2 - x0)(y1 - y0); expanded the same way, A = sum z_k (y_k+1 - y_k+2)
        // and B = sum z_k (x_k+2 - x_k+1): differences of x and y only, which are often exact, and
        // the vertices' z, which then need not be.
        const auto& v = t.v;
        const auto difference = [&](int k, int l, double Vertex::*c) { return two_sum(v[k].*c, -(v[l].*c)); };
        ProductSum<Weights> w, a, b;
        w.add(difference(1, 0, &Vertex::x), difference(2, 0, &Vertex::y));
        w.add(difference(0, 2, &Vertex::x), difference(1, 0, &Vertex::y));
        const Bounded area = w.sum();
        if (!(std::abs(area.value.hi) * (1 - 0x1p-50) > 4 * area.err)) return std::nullopt;
        for (int k = 0; k < 3; ++k) {
            a.add({v[k].z, 0}, difference((k + 1) % 3, (k + 2) % 3, &Vertex::y));
            b.add({v[k].z, 0}, difference((k + 2) % 3, (k + 1) % 3, &Vertex::x));
        }
        const Bounded p = divide<Weights>(a.sum(), area);
        const Bounded q = divide<Weights>(b.sum(), area);
        return BoundedPlane(v[0], p, q);
    }

    // The depth along the sample row at height y (x = x0): z0 + q (y - y0).
    template <class Weights = filters::Sound>
    Bounded row(double y) const {
        return affine<Weights>(Bounded{{z0_, 0}, 0}, q_, y, y0_);
    }
    // The depth at (x, y), from the row at height y.
    template <class Weights = filters::Sound>
    Bounded at(const Bounded& row, double x) const {
        return affine<Weights>(row, p_, x, x0_);
    }
    // lower(row)(x) is a double at most the depth at (x, y), from the row at height y.
    template <class Weights = filters::Sound>
    AffineLower<Weights> lower(const Bounded& row) const {
        return AffineLower<Weights>(row, p_, x0_);
    }

private:
    BoundedPlane(const Vertex& anchor, const Bounded& p, const Bounded& q)
        : x0_(anchor.x), y0_(anchor.y), z0_(anchor.z), p_(p), q_(q) {}

    double x0_, y0_, z0_;
    Bounded p_, q_;
};

// The nearest double to the exact value z encloses, when the enclosure decides it. z.value.hi is the
// nearest double to z.value, and the exact value rounds to it too when it lies strictly between the
// midpoints to hi's neighbours. For 2^e <= |hi| < 2^(e+1) the midpoint away from zero is 2^(e-53) from
// hi, and so is the one toward zero unless |hi| = 2^e, where it is 2^(e-54). Measured away from zero,
// the exact value is lo +- err from hi. For hi = 0 or subnormal the masked exponent gives 0, deciding
// nothing. (Sums rounded to nearest are monotone, so comparing them with a power of two is exact.)
// err = 0 only when the value is exact, and then it is 0 (+ 0.0 turns a -0.0 from zero inputs into the
// +0.0 that the exact rounding gives).
inline std::optional<double> nearest(const Bounded& z) {
    if (z.err == 0) return z.value.hi + 0.0;
    constexpr std::uint64_t kExponent = 0x7ff0000000000000u, kSignificand = 0x000fffffffffffffu;
    const auto bits = std::bit_cast<std::uint64_t>(z.value.hi);
    const double away = std::bit_cast<double>(bits & kExponent) * 0x1p-53;
    const double toward = (bits & kSignificand) == 0 ? away * 0.5 : away;
    const double lo = z.value.hi < 0 ? -z.value.lo : z.value.lo;
    if (lo + z.err < away && z.err - lo < toward) return z.value.hi;
    return std::nullopt;
}

// The sign of a - b when the enclosures decide it, else 0: a - b is certainly positive when
// a.value - b.value > a.err + b.err (DifferenceTerm::first and ::second), certainly negative when
// a.value - b.value < -(a.err + b.err). Both comparisons are made exactly, as signs of sums of six doubles
// (the parts, and the weighted errors, whose weights are 1, 1/2 or 0: exact): the only slack is the
// enclosures' own. Called only where two rounded depths tie.
template <class Weights = filters::Sound>
int certain_sign_of_difference(const Bounded& a, const Bounded& b) {
    const double radius_a = Weights::weight(DifferenceTerm::first) * a.err;
    const double radius_b = Weights::weight(DifferenceTerm::second) * b.err;
    const double ah = a.value.hi, al = a.value.lo, bh = b.value.hi, bl = b.value.lo;
    if (exact_sign_of_sum(std::array{ah, -bh, al, -bl, -radius_a, -radius_b}) > 0) return 1;
    if (exact_sign_of_sum(std::array{ah, -bh, al, -bl, radius_a, radius_b}) < 0) return -1;
    return 0;
}

}  // namespace rast::reference::detail
