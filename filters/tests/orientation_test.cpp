// The orientation filter's bound, held from both sides on adversarial inputs: sound (the exact error
// never exceeds it) and sharp (halved, or with either term dropped, it fails on them).
#include <rast/filters/adversary.h>
#include <rast/filters/orientation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace rast::filters {
namespace {

using testing::climbs;
using testing::Halved;
using testing::Rational;
using testing::Without;
using testing::worst;
using Points = std::array<double, 6>;  // px py qx qy rx ry

Rational exact_det(const Points& c) {
    const Rational px(c[0]), py(c[1]);
    return (Rational(c[2]) - px) * (Rational(c[5]) - py) - (Rational(c[3]) - py) * (Rational(c[4]) - px);
}

template <class Weights = Sound>
Orientation evaluate(const Points& c) {
    return orientation<Weights>(c[0], c[1], c[2], c[3], c[4], c[5]);
}

// |computed - exact| / bound under the given weights.
template <class Weights = Sound>
double error_ratio(const Points& c) {
    const Orientation o = evaluate<Weights>(c);
    return testing::ratio(abs(Rational(o.det) - exact_det(c)), o.bound);
}

// Nearly collinear points whose differences round: p some binades below q (so q - p and r - p drop p's
// low bits), r about t times as far along p -> q; then a climb toward the largest error over the bound.
// Every rounding of the evaluation (two per product in the differences, one per product, the
// subtraction) then errs, and the climb aligns them.
std::vector<Points> rounding_cases(int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), scale(1, 2), along(1.5, 3);
    std::uniform_int_distribution<int> binades(1, 30);
    std::vector<Points> cases;
    for (int n = 0; n < count; ++n) {
        const double px = std::ldexp(unit(rng), -binades(rng)), py = std::ldexp(unit(rng), -binades(rng));
        const double qx = scale(rng), qy = scale(rng), t = along(rng);
        Points c{px, py, qx, qy, px + t * (qx - px), py + t * (qy - py)};
        testing::climb(c, error_ratio<Sound>, rng, 300);
        cases.push_back(c);
    }
    return cases;
}

// The same cases scaled by 2^-537: exactly, differences and all, but the products now land among the
// subnormals, where their rounding is absolute and the relative term underflows with them.
std::vector<Points> underflow_cases(const std::vector<Points>& rounding) {
    std::vector<Points> cases;
    for (Points c : rounding) {
        for (double& x : c) x = std::ldexp(x, -537);
        cases.push_back(c);
    }
    return cases;
}

// Made once, shared by the tests below.
const std::vector<Points>& rounding() {
    static const std::vector<Points> cases = rounding_cases(climbs(200), 2026);
    return cases;
}
const std::vector<Points>& underflow() {
    static const std::vector<Points> cases = underflow_cases(rounding());
    return cases;
}

TEST(OrientationBound, IsSoundOnAdversarialInputs) {
    for (const auto* cases : {&rounding(), &underflow()})
        for (const Points& c : *cases) {
            const Orientation o = evaluate(c);
            EXPECT_LE(error_ratio(c), 1.0);
            const Rational exact = exact_det(c);
            if (const int sign = o.certain_sign()) {
                EXPECT_EQ(sign, exact.sign());
            }
        }
    const double sound = worst(rounding(), error_ratio<Sound>);
    std::printf("orientation: worst error / bound %.3f (relative term, %zu climbs)\n", sound, rounding().size());
    ::testing::Test::RecordProperty("worst_ratio", std::to_string(sound));
}

TEST(OrientationBound, HalvedFails) { EXPECT_GT(worst(rounding(), error_ratio<Halved>), 1.0); }

TEST(OrientationBound, WithoutTheRelativeTermFails) {
    EXPECT_GT(worst(rounding(), error_ratio<Without<OrientationTerm::relative>>), 1.0);
}

TEST(OrientationBound, WithoutTheUnderflowTermFails) {
    EXPECT_GT(worst(underflow(), error_ratio<Without<OrientationTerm::underflow>>), 1.0);
}

// Hand-computed: p = (2^-53, 0), q = (1, 1), r = (2, 2). Exactly, det = (1 - 2^-53) 2 - 1 (2 - 2^-53) =
// -2^-53. In double, rx - px = 2 - 2^-53 is a tie and rounds to even, 2, so det = (2 - 2^-52) - 2 = -2^-52:
// twice the exact value, an error of u = 2^-53 against a bound of about 3u (2 + 2) = 12u, which keeps
// the filter from deciding. Plain cases it decides; overflow it leaves.
TEST(Orientation, DecidesPlainCasesAndLeavesCollinearOnes) {
    EXPECT_EQ(orientation(0, 0, 1, 0, 0, 1).certain_sign(), 1);   // r left of p -> q
    EXPECT_EQ(orientation(0, 0, 1, 0, 0, -1).certain_sign(), -1);  // right
    EXPECT_EQ(orientation(0, 0, 1, 1, 2, 2).certain_sign(), 0);    // collinear: det 0, bound 2^-1000
    const Orientation rounded = orientation(0x1p-53, 0, 1, 1, 2, 2);
    EXPECT_EQ(rounded.det, -0x1p-52);
    EXPECT_EQ(exact_det({0x1p-53, 0, 1, 1, 2, 2}), -Rational(0x1p-53));
    EXPECT_EQ(rounded.certain_sign(), 0);
    EXPECT_GE(rounded.bound, 0x1p-53);
    // Overflowing products decide nothing.
    EXPECT_EQ(orientation(-1e300, -1e300, 1e300, 1e300, 1e300, -1e300).certain_sign(), 0);
}

}  // namespace
}  // namespace rast::filters
