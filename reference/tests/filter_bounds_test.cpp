// The depth filters' bounds (bounded_depth.h), held from both sides on adversarial inputs: sound (the
// exact error never exceeds the bound) and sharp (the bound halved, or any one of its terms dropped,
// fails on them). The inputs come from hill climbs toward the largest error over the bound
// (filters/testing/adversary.h); their sizes are bounded here and larger in a campaign
// (RAST_FILTER_CLIMBS). Worst ratios are printed for docs/filters.md.
#include "bounded_depth.h"
#include "nearest_double.h"

#include <rast/filters/adversary.h>
#include <rast/filters/orientation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace rast::reference {
namespace {

using detail::AffineTerm;
using detail::Bounded;
using detail::DifferenceTerm;
using detail::DoubleDouble;
using detail::QuotientTerm;
using detail::SumTerm;
using filters::Sound;
using filters::testing::climb;
using filters::testing::climbs;
using filters::testing::Halved;
using filters::testing::ratio;
using filters::testing::Without;
using filters::testing::worst;

Rational exact(const DoubleDouble& x) { return Rational(x.hi) + Rational(x.lo); }

// The largest |value - v| over the values an enclosure allows, for v a function of two enclosed
// inputs: at the corners, as value is monotone in each input on the enclosure (the callers' values are
// affine in each, or a quotient with a divisor away from zero).
template <class F>
Rational widest(const Bounded& x, const Bounded& y, const Rational& computed, F value) {
    Rational worst = 0;
    for (const int sx : {-1, 1})
        for (const int sy : {-1, 1}) {
            const Rational v = value(exact(x.value) + sx * Rational(x.err), exact(y.value) + sy * Rational(y.err));
            worst = std::max(worst, Rational(abs(v - computed)));
        }
    return worst;
}

// A double-double of two doubles, as the plane's differences are: hi + lo normalized.
DoubleDouble pair(double a, double b) { return detail::two_sum(a, b); }

// The cases whose inputs carry no error of their own: the first family of each generator below.
template <class Inputs>
std::vector<Inputs> exact_inputs(const std::vector<Inputs>& cases) {
    std::vector<Inputs> exact;
    for (std::size_t n = 0; n < cases.size(); n += 3) exact.push_back(cases[n]);
    return exact;
}

// --- ProductSum -----------------------------------------------------------------------------------

using SumInputs = std::array<double, 12>;  // three products (a + b)(c + d), nearly cancelling

template <class Weights>
double sum_ratio(const SumInputs& in) {
    detail::ProductSum<Weights> sum;
    Rational value = 0;
    for (int k = 0; k < 3; ++k) {
        const DoubleDouble x = pair(in[4 * k], in[4 * k + 1]), y = pair(in[4 * k + 2], in[4 * k + 3]);
        sum.add(x, y);
        value += exact(x) * exact(y);
    }
    const Bounded s = sum.sum();
    return ratio(abs(exact(s.value) - value), s.err);
}

// Products whose low parts are not 0 and whose sum cancels to a few ulps of the largest: the third
// product is about minus the sum of the first two.
std::vector<SumInputs> sum_cases(int count) {
    std::mt19937_64 rng(33);
    std::uniform_real_distribution<double> unit(1, 2);
    std::vector<SumInputs> cases;
    for (int n = 0; n < count; ++n) {
        SumInputs in;
        for (int k = 0; k < 3; ++k) {
            in[4 * k] = unit(rng), in[4 * k + 1] = std::ldexp(unit(rng), -54);
            in[4 * k + 2] = unit(rng), in[4 * k + 3] = std::ldexp(unit(rng), -54);
        }
        in[8] = -(in[0] * in[2] + in[4] * in[6]) / in[10];
        climb(in, sum_ratio<Sound>, rng, 400);
        cases.push_back(in);
    }
    return cases;
}

TEST(FilterBounds, ProductSum) {
    const auto cases = sum_cases(climbs(60));
    const double sound = worst(cases, sum_ratio<Sound>);
    std::printf("ProductSum: worst error / bound %.3f\n", sound);
    EXPECT_LE(sound, 1.0);
    EXPECT_GT(worst(cases, sum_ratio<Halved>), 1.0);
    EXPECT_GT(worst(cases, sum_ratio<Without<SumTerm::rounding>>), 1.0);
}

// --- divide ---------------------------------------------------------------------------------------

// x = (x0 + x1) +- xe, y = (y0 + y1) +- ye.
using QuotientInputs = std::array<double, 6>;

Bounded enclosure(double a, double b, double err) { return {pair(a, b), err}; }

template <class Weights>
double quotient_ratio(const QuotientInputs& in) {
    const Bounded x = enclosure(in[0], in[1], in[2]), y = enclosure(in[3], in[4], in[5]);
    const Bounded q = detail::divide<Weights>(x, y);
    const Rational worst = widest(x, y, exact(q.value), [](const Rational& a, const Rational& b) { return a / b; });
    return ratio(worst, q.err);
}

// Three families: exact inputs (the roundings alone), a dividend with an error, a divisor with one.
std::vector<QuotientInputs> quotient_cases(int count) {
    std::mt19937_64 rng(34);
    std::uniform_real_distribution<double> unit(1, 2);
    std::vector<QuotientInputs> cases;
    for (int n = 0; n < count; ++n) {
        const int family = n % 3;
        QuotientInputs in{unit(rng), std::ldexp(unit(rng) - 1.5, -53), family == 1 ? std::ldexp(unit(rng), -60) : 0,
                          unit(rng), std::ldexp(unit(rng) - 1.5, -53), family == 2 ? std::ldexp(unit(rng), -60) : 0};
        climb(in, quotient_ratio<Sound>, rng, 300);
        cases.push_back(in);
    }
    return cases;
}

TEST(FilterBounds, Divide) {
    const auto cases = quotient_cases(climbs(60));
    const double sound = worst(cases, quotient_ratio<Sound>);
    std::printf("divide: worst error / bound %.3f, of exact inputs (the roundings alone) %.3f\n", sound,
                worst(exact_inputs(cases), quotient_ratio<Sound>));
    EXPECT_LE(sound, 1.0);
    EXPECT_GT(worst(cases, quotient_ratio<Halved>), 1.0);
    EXPECT_GT(worst(cases, quotient_ratio<Without<QuotientTerm::rounding>>), 1.0);
    EXPECT_GT(worst(cases, quotient_ratio<Without<QuotientTerm::dividend>>), 1.0);
    EXPECT_GT(worst(cases, quotient_ratio<Without<QuotientTerm::divisor>>), 1.0);
}

// --- affine and its lower bound -------------------------------------------------------------------

// base = (b0 + b1) +- be, slope = (s0 + s1) +- se, at v with origin o.
using AffineInputs = std::array<double, 8>;

template <class Weights>
double affine_ratio(const AffineInputs& in) {
    const Bounded base = enclosure(in[0], in[1], in[2]), slope = enclosure(in[3], in[4], in[5]);
    const Bounded z = detail::affine<Weights>(base, slope, in[6], in[7]);
    const Rational d = Rational(in[6]) - Rational(in[7]);
    const Rational worst =
        widest(base, slope, exact(z.value), [&](const Rational& b, const Rational& s) { return b + s * d; });
    return ratio(worst, z.err);
}

// How far below the least enclosed value the lower bound lies, over the scale of the values: negative
// where the bound is unsound.
template <class Weights>
double lower_slack(const AffineInputs& in) {
    const Bounded base = enclosure(in[0], in[1], in[2]), slope = enclosure(in[3], in[4], in[5]);
    const double lower = detail::AffineLower<Weights>(base, slope, in[7])(in[6]);
    const Rational d = Rational(in[6]) - Rational(in[7]);
    const Rational least = exact(base.value) - Rational(base.err) + exact(slope.value) * d - Rational(slope.err) * abs(d);
    const Rational scale = abs(Rational(in[0])) + abs(Rational(in[3]) * d);
    return static_cast<double>(Rational((least - Rational(lower)) / scale));
}

// Base and slope times distance nearly cancelling (the plane evaluated near its zero), v and origin
// some binades apart (so that v - origin rounds), low parts and errors by family: exact inputs, a base
// with an error, a slope with one.
std::vector<AffineInputs> affine_cases(int count, std::uint64_t seed, int error_binade,
                                       double (*score)(const AffineInputs&)) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(1, 2);
    std::uniform_int_distribution<int> binades(-8, 8);
    std::vector<AffineInputs> cases;
    for (int n = 0; n < count; ++n) {
        const int family = n % 3;
        const double v = std::ldexp(unit(rng), binades(rng)), origin = std::ldexp(unit(rng), -20);
        const double slope = unit(rng);
        const double error = std::ldexp(unit(rng), error_binade);
        AffineInputs in{-slope * (v - origin), std::ldexp(unit(rng) - 1.5, -52), family == 1 ? error : 0,
                        slope,                 std::ldexp(unit(rng) - 1.5, -53), family == 2 ? error : 0,
                        v,                     origin};
        climb(in, score, rng, 300);
        cases.push_back(in);
    }
    return cases;
}

template <class Weights>
double least_lower_slack(const std::vector<AffineInputs>& cases) {
    double least = 1;
    for (const AffineInputs& in : cases) least = std::min(least, lower_slack<Weights>(in));
    return least;
}

TEST(FilterBounds, Affine) {
    const auto cases = affine_cases(climbs(60), 35, -60, affine_ratio<Sound>);
    const double sound = worst(cases, affine_ratio<Sound>);
    std::printf("affine: worst error / bound %.3f, of exact inputs (the roundings alone) %.3f\n", sound,
                worst(exact_inputs(cases), affine_ratio<Sound>));
    EXPECT_LE(sound, 1.0);
    EXPECT_GT(worst(cases, affine_ratio<Halved>), 1.0);
    EXPECT_GT(worst(cases, affine_ratio<Without<AffineTerm::rounding>>), 1.0);
    EXPECT_GT(worst(cases, affine_ratio<Without<AffineTerm::base>>), 1.0);
    EXPECT_GT(worst(cases, affine_ratio<Without<AffineTerm::slope>>), 1.0);
}

// The lower bound's climb goes toward the smallest slack, the place where a weaker bound breaks first.
// Its rounding terms are a priori, a few ulps of the magnitudes: the inputs' errors must exceed them to
// be seen, as they do where the enclosures come from a long computation.
TEST(FilterBounds, AffineLower) {
    const auto cases =
        affine_cases(climbs(60), 36, -40, [](const AffineInputs& in) { return -lower_slack<Sound>(in); });
    EXPECT_GE(least_lower_slack<Sound>(cases), 0.0);
    EXPECT_LT(least_lower_slack<Halved>(cases), 0.0);
    EXPECT_LT(least_lower_slack<Without<AffineTerm::rounding>>(cases), 0.0);
    EXPECT_LT(least_lower_slack<Without<AffineTerm::base>>(cases), 0.0);
    EXPECT_LT(least_lower_slack<Without<AffineTerm::slope>>(cases), 0.0);
}

// --- end to end: a weakened bound changes a framebuffer ----------------------------------------------

// corpus/filters/orientation-halved-flips-a-centre.tri: the centre (24.5, 16.5) lies left of p -> q by
// 7.6e-15, inside the triangle, and the reference covers it. The double determinant errs the other way,
// by 0.57 of the orientation filter's bound: the filter leaves the sign to CGAL, but halved it would
// answer "right", and a reference built on it would leave pixel (24, 16) empty.
TEST(FilterBounds, HalvedOrientationFlipsACentre) {
    const Vertex p{0x1.e002a9a706b47p-9, 0x1.83a8488be8176p-12, 0}, q{0x1.2230d0aad74edp+6, 0x1.86e6e87125c75p+5, 0};
    const double x = 24.5, y = 16.5;
    const Rational exact_det =
        (Rational(q.x) - Rational(p.x)) * (Rational(y) - Rational(p.y)) - (Rational(q.y) - Rational(p.y)) * (Rational(x) - Rational(p.x));
    EXPECT_GT(exact_det, 0);
    EXPECT_EQ(filters::orientation(p.x, p.y, q.x, q.y, x, y).certain_sign(), 0);
    EXPECT_EQ(filters::orientation<Halved>(p.x, p.y, q.x, q.y, x, y).certain_sign(), -1);
    Scene scene;
    scene.viewport = {80, 50};
    scene.triangles = {Triangle{{p, q, Vertex{0, 40, 0}}}};
    const Framebuffer fb = render(scene);
    EXPECT_EQ(fb.id(24, 16), 0);
    EXPECT_TRUE(covers(scene.triangles[0], x, y));
}

// --- the sign of a difference ---------------------------------------------------------------------

// Hand-made: a = 1 +- 2^-60 and b = 1 + 2^-59 +- 2^-60 touch at 1 + 2^-60, where their exact values may be
// equal: no sign is certain. With either radius dropped (or halved) they no longer touch, and the
// filter answers -1 for values that may be equal.
TEST(FilterBounds, DifferenceOfTouchingEnclosuresDecidesNothing) {
    const Bounded a{{1, 0}, 0x1p-60}, b{{1, 0x1p-59}, 0x1p-60};
    EXPECT_EQ(detail::certain_sign_of_difference(a, b), 0);
    EXPECT_EQ(detail::certain_sign_of_difference(b, a), 0);
    EXPECT_EQ(detail::certain_sign_of_difference<Halved>(a, b), -1);
    EXPECT_EQ(detail::certain_sign_of_difference<Without<DifferenceTerm::first>>(a, b), -1);
    EXPECT_EQ(detail::certain_sign_of_difference<Without<DifferenceTerm::second>>(a, b), -1);
    // A hair apart, they decide: the comparison itself is exact, with no rounding slack of its own.
    const Bounded c{{1, 0x1p-59 + 0x1p-111}, 0x1p-60};
    EXPECT_EQ(detail::certain_sign_of_difference(a, c), -1);
    EXPECT_EQ(detail::certain_sign_of_difference(c, a), 1);
}

// --- the rounding test ----------------------------------------------------------------------------

// 1 + 2^-52 has an odd significand: the midpoint 1 + 3 2^-53 above it rounds to the even 1 + 2^-51.
// An enclosure that reaches the midpoint exactly cannot be rounded; one that stops short of it can.
TEST(FilterBounds, RoundingTestAtTheMidpoint) {
    const double odd = 1 + 0x1p-52;
    EXPECT_FALSE(detail::nearest(Bounded{{odd, 0}, 0x1p-53}));
    EXPECT_EQ(detail::nearest_double(Rational(odd) + Rational(0x1p-53)), 1 + 0x1p-51);
    EXPECT_EQ(detail::nearest(Bounded{{odd, 0x1p-80}, 0x1p-53 - 0x1p-80}), std::nullopt);
    EXPECT_EQ(detail::nearest(Bounded{{odd, 0x1p-80}, 0x1p-53 - 0x1p-79}), odd);
}

// Below a power of two the doubles are twice as dense: the midpoint under 1 is 1 - 2^-54, not 1 - 2^-53.
// An enclosure reaching past it may round to 1 - 2^-53.
TEST(FilterBounds, RoundingTestBelowAPowerOfTwo) {
    EXPECT_EQ(detail::nearest(Bounded{{1, 0}, 0x1p-55}), 1.0);
    EXPECT_FALSE(detail::nearest(Bounded{{1, 0}, 0x1p-54 + 0x1p-70}));
    EXPECT_EQ(detail::nearest_double(Rational(1) - Rational(0x1p-54) - Rational(0x1p-70)), 1 - 0x1p-53);
    EXPECT_FALSE(detail::nearest(Bounded{{1, -0x1p-60}, 0x1p-54}));
}

}  // namespace
}  // namespace rast::reference
