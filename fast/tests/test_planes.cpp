// The depth planes of setup.h. Their error bound against exact rational arithmetic (GMP): at every sample
// of the bounding box, the double evaluation the kernels make is within err of the exact plane through the
// corners (test_filter_bounds.cpp shows on adversarial depths that no term of it can be spared). And
// small_planes, the small lane's planes set up several at once, on every SIMD target: on a narrow triangle,
// the bits of the narrow plane in scalar code; its gradient make_plane's (the same rounded operations), and
// its bound no larger (it leaves out only error terms that are zero there). Triangles from the small lane's
// own records in every fixed mode, and placed ones of every path, with depths of every magnitude and sign,
// flat planes and near-degenerate corners. placed_planes, the other small triangles' planes in lanes:
// make_plane's bits.
#include "setup.h"
#include "targets.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

// The three depths of a triangle, from one of the families where rounding is hardest on the bound:
// independent magnitudes from subnormal to huge, one value (a flat plane), values a few units in the last
// place apart (cancellation in the differences), small multiples of the least subnormal (products that
// underflow), and a huge corner beside tiny ones.
std::array<double, 3> random_depths(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> exponent(-1074, 1000), ulps(-4, 4), multiple(-40, 40);
    std::array<double, 3> z;
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0:
            for (double& d : z) d = std::ldexp(unit(rng), exponent(rng));
            break;
        case 1:
            z.fill(unit(rng));
            break;
        case 2:
            for (double& d : z) d = 1 + ulps(rng) * 0x1p-52;
            break;
        case 3:
            for (double& d : z) d = multiple(rng) * DBL_TRUE_MIN;
            break;
        default:
            z = {std::ldexp(unit(rng), 900), std::ldexp(unit(rng), -900), unit(rng)};
            break;
    }
    return z;
}

// Corners within `side` pixels of a random point of the viewport, the third sometimes almost on the line
// through the first two.
Triangle random_small_triangle(std::mt19937_64& rng, double side) {
    std::uniform_real_distribution<double> where(0, 1000), offset(0, side);
    const double x = where(rng), y = where(rng);
    const std::array<double, 3> z = random_depths(rng);
    Triangle t;
    for (int k = 0; k < 3; ++k) t.v[k] = {x + offset(rng), y + offset(rng), z[k]};
    if (rng() % 4 == 0) {
        const double s = std::uniform_real_distribution<double>(0, 1)(rng);
        t.v[2].x = t.v[0].x + s * (t.v[1].x - t.v[0].x) + 0x1p-7;
        t.v[2].y = t.v[0].y + s * (t.v[1].y - t.v[0].y);
    }
    return t;
}

// The plane's double depth at (px, py), as the kernels compute it, is within err of the exact plane
// through the corners.
void expect_bounded(const Plane& p, const Corners& v, double px, double py) {
    const mpq_class dx1 = mpq_class(v[1].x) - v[0].x, dy1 = mpq_class(v[1].y) - v[0].y;
    const mpq_class dx2 = mpq_class(v[2].x) - v[0].x, dy2 = mpq_class(v[2].y) - v[0].y;
    const mpq_class dz1 = mpq_class(v[1].z) - v[0].z, dz2 = mpq_class(v[2].z) - v[0].z;
    const mpq_class det = dx1 * dy2 - dx2 * dy1;
    const mpq_class exact =
        v[0].z + ((mpq_class(px) - v[0].x) * (dz1 * dy2 - dz2 * dy1) + (mpq_class(py) - v[0].y) * (dx1 * dz2 - dx2 * dz1)) / det;
    const double z = p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0));
    ASSERT_TRUE(std::isfinite(z));
    const mpq_class distance = abs(mpq_class(z) - exact);
    EXPECT_LE(distance, mpq_class(p.err)) << "at (" << px << ", " << py << "): z " << z << ", err " << p.err;
}

// At the corners of the samples' box, where the bound's reach is largest, and at some samples inside.
void expect_bounded_over_box(std::mt19937_64& rng, const Plane& p, const Placed& s, const Context& c) {
    const double xs[] = {s.i_lo + c.ox_min, s.i_hi + c.ox_max}, ys[] = {s.j_lo + c.oy_min, s.j_hi + c.oy_max};
    for (const double x : xs)
        for (const double y : ys) expect_bounded(p, s.v, x, y);
    std::uniform_int_distribution<int> column(s.i_lo, s.i_hi), row(s.j_lo, s.j_hi);
    std::uniform_int_distribution<std::size_t> sample(0, c.offsets.size() - 1);
    for (int k = 0; k < 4; ++k) {
        const SamplePoint o = c.offsets[sample(rng)];
        expect_bounded(p, s.v, column(rng) + o.x, row(rng) + o.y);
    }
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

// The narrow plane in scalar code (planes.h says why it holds): make_plane's operations with the errors of
// the corners' differences, exact there, left out. The lanes of narrow_planes must give its bits.
Plane narrow_plane(const Placed& s, const Context& c) {
    const Corners& v = s.v;
    const double u = kUnitDouble;
    const double dx1 = v[1].x - v[0].x, dy1 = v[1].y - v[0].y, dx2 = v[2].x - v[0].x, dy2 = v[2].y - v[0].y;
    const double det = dx1 * dy2 - dx2 * dy1;
    const double dz1 = v[1].z - v[0].z, dz2 = v[2].z - v[0].z;
    const Bounded z1 = {dz1, u * std::abs(dz1)}, z2 = {dz2, u * std::abs(dz2)};  // sub's bounds
    // (z p - w q) / det: make_plane's a = (dz1 dy2 - dz2 dy1) / det and b = (dx1 dz2 - dx2 dz1) / det.
    const auto slope = [&](Bounded z, double p, Bounded w, double q) {
        const double m1 = z.v * p, m2 = w.v * q, n = m1 - m2;
        const double en = std::abs(p) * z.e + std::abs(q) * w.e + u * (std::abs(m1) + std::abs(m2) + std::abs(n)) +
                          2 * DBL_TRUE_MIN;
        const double g = n / det;
        return Bounded{g, en / std::abs(det) + u * std::abs(g) + DBL_TRUE_MIN};
    };
    return plane_over_box(s, c, slope(z1, dy2, z2, dy1), slope(z2, dx1, z1, dx2));
}

// In runs of 1 to kPlaneBatch records, as a tile hands them over, on every SIMD target: a narrow record's
// plane has narrow_plane's bits, its gradient make_plane's, and a bound no larger than make_plane's that
// holds; fixed16 mixes narrow triangles (below a quarter of a pixel there) with others, which must get
// make_plane's plane itself.
TEST(SmallPlanes, AreTheScalarNarrowPlanesOnEveryTarget) {
    std::mt19937_64 rng(20261124);
    for (const Precision precision : {Precision::fixed4, Precision::fixed8, Precision::fixed16}) {
        SCOPED_TRACE(::testing::Message() << "precision " << static_cast<int>(precision));
        const Context c = make_context<Fault::none>({1024, 1024}, 4, precision);
        std::vector<SmallFixed> records;
        for (int n = 0; n < 4000; ++n) {
            const double side = precision == Precision::fixed16 ? (n % 2 == 0 ? 0.2 : 4) : n % 2 == 0 ? 4 : 31;
            SmallFixed record;
            if (place_small_fixed<Fault::none>(random_small_triangle(rng, side), 0, c, record) == Lane::small_fixed)
                records.push_back(record);
        }
        on_every_target([&] {
            int narrow_count = 0, wide_count = 0;
            for (std::size_t first = 0, n = 1; first < records.size(); first += n, n = n % kPlaneBatch + 1) {
                n = std::min(n, records.size() - first);
                Plane planes[kPlaneBatch];
                PlaneBatch batch;
                const std::uint32_t narrow_bits = small_planes({records.data() + first, n}, c, planes, batch);
                ASSERT_EQ(narrow_bits >> n, 0u);
                bool narrow[kPlaneBatch];
                for (std::size_t k = 0; k < n; ++k) {
                    narrow[k] = narrow_bits >> k & 1;
                    const SmallFixed& record = records[first + k];
                    ASSERT_EQ(narrow[k], narrow_edges(record, std::int64_t{1} << c.bits));
                    const Placed p = placed_of(record, c);
                    const Plane& got = planes[k];
                    const Plane general = make_plane(p, c), want = narrow[k] ? narrow_plane(p, c) : general;
                    SCOPED_TRACE(::testing::Message() << "record " << first + k);
                    EXPECT_EQ(bits(got.x0), bits(want.x0));
                    EXPECT_EQ(bits(got.y0), bits(want.y0));
                    EXPECT_EQ(bits(got.z0), bits(want.z0));
                    EXPECT_EQ(bits(got.a), bits(general.a));
                    EXPECT_EQ(bits(got.b), bits(general.b));
                    EXPECT_EQ(bits(got.err), bits(want.err));
                    EXPECT_LE(got.err, general.err);
                    if (got.err < std::numeric_limits<double>::infinity()) expect_bounded_over_box(rng, got, p, c);
                    if (::testing::Test::HasFailure()) return;
                    narrow_count += narrow[k];
                    wide_count += !narrow[k];
                }
            }
            // The generator does make narrow small triangles in every mode, and others in fixed16.
            EXPECT_GT(narrow_count, 1000);
            if (precision == Precision::fixed16) {
                EXPECT_GT(wide_count, 1000);
            }
        });
    }
}

// placed_planes, the small lane's planes in lanes, in runs of 1 to kPlaneBatch: make_plane's bits, on every
// SIMD target, for placed triangles of every path, with corners from a pixel apart to 10^300 (overflowing
// products, unbounded planes) and depths of every magnitude.
TEST(PlacedPlanes, AreMakePlanesBitsOnEveryTarget) {
    std::mt19937_64 rng(20261129);
    for (const Precision precision : {Precision::fixed8, Precision::float32, Precision::float64}) {
        SCOPED_TRACE(::testing::Message() << "precision " << static_cast<int>(precision));
        const Context c = make_context<Fault::none>({1024, 1024}, 4, precision);
        std::vector<Placed> placed;
        int unbounded = 0, undecided_det = 0;
        for (int n = 0; n < 4000; ++n) {
            // Corners up to `reach` pixels either way of a point of the viewport.
            const double reach = std::array{1.0, 8.0, 1500.0, 1e9, 1e300}[n % 5];
            std::uniform_real_distribution<double> where(0, 1000), offset(-reach, reach);
            const double x = where(rng), y = where(rng);
            const std::array<double, 3> z = random_depths(rng);
            Triangle t;
            for (int k = 0; k < 3; ++k) t.v[k] = {x + offset(rng), y + offset(rng), z[k]};
            if (n % 3 == 0) {  // the third corner a few units in the last place off the line of the others
                const double along = std::uniform_real_distribution<double>(0, 1)(rng);
                t.v[2].x = t.v[0].x + along * (t.v[1].x - t.v[0].x);
                t.v[2].y = t.v[0].y + along * (t.v[1].y - t.v[0].y);
                for (int ulp = 0; ulp < n % 4; ++ulp) t.v[2].y = std::nextafter(t.v[2].y, INFINITY);
            }
            const std::optional<Placed> p = place<Fault::none>(t, c);
            if (!p) continue;
            placed.push_back(*p);
            unbounded += !(make_plane(*p, c).err < std::numeric_limits<double>::infinity());
            const Corners& v = p->v;
            const Bounded dx1 = sub(exact(v[1].x), exact(v[0].x)), dy1 = sub(exact(v[1].y), exact(v[0].y));
            const Bounded dx2 = sub(exact(v[2].x), exact(v[0].x)), dy2 = sub(exact(v[2].y), exact(v[0].y));
            const Bounded det = sub(mul(dx1, dy2), mul(dx2, dy1));
            undecided_det += !(std::abs(det.v) > det.e);
        }
        ASSERT_GT(placed.size(), 2500u);
        EXPECT_GT(unbounded, 100);  // the generator reaches make_plane's infinite bounds
        EXPECT_GT(undecided_det, 10);  // and determinants whose sign the doubles leave open
        on_every_target([&] {
            for (std::size_t first = 0, n = 1; first < placed.size(); first += n, n = n % kPlaneBatch + 1) {
                n = std::min(n, placed.size() - first);
                Plane planes[kPlaneBatch];
                placed_planes(n, [&](std::size_t k) -> const Placed& { return placed[first + k]; }, c, planes);
                for (std::size_t k = 0; k < n; ++k) {
                    const Plane want = make_plane(placed[first + k], c), &got = planes[k];
                    SCOPED_TRACE(::testing::Message() << "triangle " << first + k);
                    for (const auto field : {&Plane::x0, &Plane::y0, &Plane::z0, &Plane::a, &Plane::b, &Plane::err})
                        ASSERT_EQ(bits(got.*field), bits(want.*field));
                }
            }
        });
    }
}

TEST(Plane, BoundHoldsOnEveryPath) {
    std::mt19937_64 rng(20261125);
    for (const Precision precision : {Precision::fixed8, Precision::float32, Precision::float64}) {
        const Context c = make_context<Fault::none>({1024, 1024}, 4, precision);
        int checked = 0;
        for (int n = 0; n < 3000; ++n) {
            // Small and near-degenerate, across the screen, and reaching far past it (the wide path).
            const double side = n % 3 == 0 ? 8 : n % 3 == 1 ? 1500 : 1e9;
            Triangle t = random_small_triangle(rng, side);
            const std::optional<Placed> p = place<Fault::none>(t, c);
            if (!p) continue;
            SCOPED_TRACE(::testing::Message() << "precision " << static_cast<int>(precision) << ", triangle " << n);
            const Plane plane = make_plane(*p, c);
            if (plane.err < std::numeric_limits<double>::infinity()) expect_bounded_over_box(rng, plane, *p, c);
            if (::testing::Test::HasFailure()) return;
            ++checked;
        }
        EXPECT_GT(checked, 1000);
    }
}

}  // namespace
}  // namespace rast::fast::detail
