// The fast path's own filters, held from both sides on adversarial inputs (filters/testing/adversary.h):
// the depth plane's bound (setup.h, and the SIMD planes of planes.cpp) and the float modes' edge bound
// (edge_bound.h). Sound: the exact error never exceeds the bound. Sharp: the bound halved, or with any
// one of its terms dropped, fails on the same inputs. Worst ratios are printed for docs/filters.md.
#include "edge_bound.h"
#include "engine.h"
#include "line_depth.h"
#include "setup.h"
#include "targets.h"

#include <rast/fast_faults.h>
#include <rast/filters/adversary.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace rast::fast::detail {
namespace {

using filters::Sound;
using filters::testing::climb;
using filters::testing::climbs;
using filters::testing::Halved;
using filters::testing::ratio;
using filters::testing::Rational;
using filters::testing::Without;
using filters::testing::worst;
using testing::on_every_target;

// --- The depth plane ------------------------------------------------------------------------------

// bounded.h's div where the quotient underflows: 2^-1074 / 3 rounds to 0, but over a denominator known
// only within 2.9 of 3 the exact quotient reaches 2^-1074 / 0.1 (the double 2.9 a little below 2.9). A
// bound that took |x/y| as |v| alone gave 2^-1074.
TEST(DivBound, CoversAQuotientThatUnderflows) {
    const Bounded x = exact(DBL_TRUE_MIN), y{3, 2.9};
    const Bounded q = div(x, y);
    ASSERT_EQ(q.v, 0.0);
    // The denominators at the ends of y's interval, exactly.
    for (const Rational& denominator : {Rational(3) - Rational(2.9), Rational(3) + Rational(2.9)})
        EXPECT_LE(abs(Rational(DBL_TRUE_MIN) / denominator - Rational(q.v)), Rational(q.e));
}


// A triangle on the fixed8 grid whose depths the climb moves: its corners stay put, so that the
// bounding box, and the samples where the bound's reach is attained, do too.
struct PlaneCase {
    std::array<double, 6> xy;
    std::array<double, 3> z;
};

Triangle triangle_of(const PlaneCase& k) {
    Triangle t;
    for (int v = 0; v < 3; ++v) t.v[v] = {k.xy[2 * v], k.xy[2 * v + 1], k.z[v]};
    return t;
}

// Its depth_small is the kernel of the targets first in force: the tests here do not call it.
const Context& plane_context() {
    static const Context c = make_context<Fault::none>({1024, 1024}, 1, Precision::fixed8);
    return c;
}

// The exact plane through the placed corners at (px, py).
Rational exact_depth(const Corners& v, double px, double py) {
    const Rational dx1 = Rational(v[1].x) - v[0].x, dy1 = Rational(v[1].y) - v[0].y;
    const Rational dx2 = Rational(v[2].x) - v[0].x, dy2 = Rational(v[2].y) - v[0].y;
    const Rational dz1 = Rational(v[1].z) - v[0].z, dz2 = Rational(v[2].z) - v[0].z;
    const Rational det = dx1 * dy2 - dx2 * dy1;
    return v[0].z + ((Rational(px) - v[0].x) * (dz1 * dy2 - dz2 * dy1) +
                     (Rational(py) - v[0].y) * (dx1 * dz2 - dx2 * dz1)) / det;
}

// The largest error of the kernels' evaluation over the bound, at the corners of the samples' box, where
// the bound's reach is attained.
double plane_ratio(const Plane& p, const Placed& s) {
    const Context& c = plane_context();
    if (!(p.err < std::numeric_limits<double>::infinity())) return 0;
    double largest = 0;
    for (const double px : {s.i_lo + c.ox_min, s.i_hi + c.ox_max})
        for (const double py : {s.j_lo + c.oy_min, s.j_hi + c.oy_max}) {
            const double z = p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0));
            largest = std::max(largest, ratio(abs(Rational(z) - exact_depth(s.v, px, py)), p.err));
        }
    return largest;
}

template <class W>
double plane_ratio(const PlaneCase& k) {
    const std::optional<Placed> s = place<Fault::none>(triangle_of(k), plane_context());
    return s ? plane_ratio(make_plane<W>(*s, plane_context()), *s) : 0;
}

// Corners within 40 pixels of each other (narrow: the SIMD planes take them too), depths from three
// families: near 1 with small slopes (the evaluation's last rounding is the whole error); steep slopes
// whose numerators nearly cancel (the gradient's roundings, carried across the box, are); and
// independent magnitudes.
std::vector<PlaneCase> plane_cases(int count) {
    std::mt19937_64 rng(20261126);
    std::uniform_int_distribution<int> grid(0, 40 * 256), base(0, 900 * 256), ulps(-64, 64);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<PlaneCase> cases;
    for (int n = 0; n < count; ++n) {
        PlaneCase k;
        const double x = base(rng) / 256.0, y = base(rng) / 256.0;
        for (int v = 0; v < 3; ++v) k.xy[2 * v] = x + grid(rng) / 256.0, k.xy[2 * v + 1] = y + grid(rng) / 256.0;
        switch (n % 3) {
            case 0:
                for (double& z : k.z) z = 1 + ulps(rng) * 0x1p-52;
                break;
            case 1: {
                // z1 - z0 and z2 - z0 in the ratio of the y differences, so that dz1 dy2 - dz2 dy1 cancels.
                const double dz = std::ldexp(unit(rng), 10);
                const double dy1 = k.xy[3] - k.xy[1], dy2 = k.xy[5] - k.xy[1];
                k.z = {0, dz, dy1 != 0 ? dz * dy2 / dy1 : dz};
                break;
            }
            default:
                for (double& z : k.z) z = std::ldexp(unit(rng), ulps(rng) % 20);
        }
        climb(k.z, [&](const std::array<double, 3>& z) { return plane_ratio<Sound>(PlaneCase{k.xy, z}); }, rng, 200);
        cases.push_back(k);
    }
    return cases;
}

const std::vector<PlaneCase>& plane_cases() {
    static const std::vector<PlaneCase> cases = plane_cases(climbs(60));
    return cases;
}

TEST(PlaneBound, IsSoundAndEveryTermBites) {
    const double sound = worst(plane_cases(), plane_ratio<Sound>);
    std::printf("plane: worst error / bound %.3f\n", sound);
    EXPECT_LE(sound, 1.0);
    EXPECT_GT(worst(plane_cases(), plane_ratio<Halved>), 1.0);
    EXPECT_GT(worst(plane_cases(), plane_ratio<Without<PlaneTerm::gradient>>), 1.0);
    EXPECT_GT(worst(plane_cases(), plane_ratio<Without<PlaneTerm::evaluation>>), 1.0);
}

// The SIMD planes of narrow triangles (planes.cpp) leave out only terms that are zero there: on every
// target they hold on the same adversarial cases, and come as near the bound (so that halving theirs
// fails too).
TEST(PlaneBound, SmallPlanesAreSoundOnEveryTarget) {
    const Context& c = plane_context();
    std::vector<SmallFixed> records;
    for (const PlaneCase& k : plane_cases()) {
        SmallFixed record;
        if (place_small_fixed<Fault::none>(triangle_of(k), 0, c, record) == Lane::small_fixed &&
            narrow_edges(record, std::int64_t{1} << c.bits))
            records.push_back(record);
    }
    ASSERT_GT(records.size(), plane_cases().size() / 2);
    on_every_target([&] {
        double largest = 0;
        for (const SmallFixed& record : records) {
            Plane plane;
            PlaneBatch batch;
            small_planes({&record, 1}, c, &plane, batch);
            largest = std::max(largest, plane_ratio(plane, placed_of(record, c)));
        }
        EXPECT_LE(largest, 1.0);
        EXPECT_GT(largest, 0.5);
    });
}

// The depth test compares two planes' depths against the sum of their bounds: for a halved bound to change
// a framebuffer, two computed depths must be wrong by more than half of both bounds together. Coplanar
// twins (one triangle, another first corner) make every exact gap 0; with depths just above 1 and gentle
// slopes, each bound is close to u, and now and then the twins' values straddle a rounding midpoint: a
// gap of one ulp, 2u, at a covered sample. The generator of corpus/filters/depth-halved-orders-coplanar-
// twins.tri: such twins turn up within a few thousand triangles, and their gap exceeds the halved bounds.
TEST(PlaneBound, CoplanarTwinsStraddleAMidpoint) {
    const Context& c = plane_context();
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int> grid(0, 40 * 256);
    std::uniform_int_distribution<std::int64_t> base(0, 1 << 20), rise(0, std::int64_t{1} << 34);
    const auto depth_at = [](const Plane& p, double px, double py) {
        return p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0));
    };
    double largest = 0, halved = 0;
    for (int n = 0; n < 20000 && halved <= 1; ++n) {
        Triangle t;
        const double z0 = 1 + base(rng) * 0x1p-52;
        for (int v = 0; v < 3; ++v)
            t.v[v] = {grid(rng) / 256.0, grid(rng) / 256.0, z0 + (v == 0 ? 0 : rise(rng) * 0x1p-52)};
        const Triangle twin{{t.v[1], t.v[2], t.v[0]}};
        const std::optional<Placed> s = place<Fault::none>(t, c), w = place<Fault::none>(twin, c);
        if (!s || !w) continue;
        const Plane p = make_plane(*s, c), q = make_plane(*w, c);
        const double margin = make_plane<Halved>(*s, c).err + make_plane<Halved>(*w, c).err;
        for (const std::size_t at : covered_samples(t, c.vp, 1, Precision::fixed8)) {
            const double px = double(at % c.vp.width) + 0.5, py = double(at / c.vp.width) + 0.5;
            const double gap = std::abs(depth_at(p, px, py) - depth_at(q, px, py));
            largest = std::max(largest, gap / (p.err + q.err));
            halved = std::max(halved, gap / margin);
        }
    }
    std::printf("coplanar twins: largest gap / summed bounds %.3f\n", largest);
    EXPECT_LE(largest, 1.0);
    EXPECT_GT(halved, 1.0);
}

// A tile for hierarchical z: every depth it holds at most 0.25, within 3e-13 of its exact value.
TileBuffer tile_with_far_depth(const Context& c) {
    TileBuffer tile;
    tile.fit(1, 1, c.vp);
    tile.stored_err = 3e-13;
    tile.far = 0.25;
    return tile;
}

// Hierarchical z uses the bound as the depth test does (kernels.h): a triangle is behind a tile only when
// its nearest computed depth is beyond the tile's far depth by more than the two bounds together. By
// hand, nearest - far = f (err + stored_err): a margin scaled either way fails.
TEST(PlaneBound, HierarchicalZDecidesExactlyBeyondTheMargin) {
    const Context& c = plane_context();
    const TileBuffer tile = tile_with_far_depth(c);
    for (const double f : {-1.0, 0.5, 0.9, 0.99, 1.01, 1.1, 2.0}) {
        // A flat plane: its nearest depth over any box is z0.
        const Plane p{0, 0, tile.far + f * (1e-13 + tile.stored_err), 0, 0, 1e-13};
        EXPECT_EQ(behind_tile(p, c, tile, 0, 3, 0, 3), f > 1) << "f = " << f;
    }
}

// Per subtile as for the whole tile: the margin is the plane's bound and the tile's together
// (in_front_subtiles). A flat plane f (err + stored_err) beyond every subtile's far depth hides them all
// only for f > 1; a subtile with an empty sample (+infinity) stays open whatever f.
TEST(PlaneBound, SubtilesDecideExactlyBeyondTheMargin) {
    const Context& c = plane_context();
    TileBuffer tile = tile_with_far_depth(c);
    std::fill(std::begin(tile.subtile_far), std::end(tile.subtile_far), tile.far);
    constexpr std::uint64_t kAll = ~std::uint64_t{0}, kEmpty = std::uint64_t{1} << 9;  // subtile (1, 1)
    for (const double f : {-1.0, 0.5, 0.9, 0.99, 1.01, 1.1, 2.0}) {
        const Plane p{0, 0, tile.far + f * (1e-13 + tile.stored_err), 0, 0, 1e-13};
        tile.subtile_far[9] = tile.far;
        EXPECT_EQ(in_front_subtiles(p, c, tile, 0, 0, 0, 63, 0, 63), f > 1 ? 0 : kAll) << "f = " << f;
        tile.subtile_far[9] = std::numeric_limits<double>::infinity();
        EXPECT_EQ(in_front_subtiles(p, c, tile, 0, 0, 0, 63, 0, 63), f > 1 ? kEmpty : kAll) << "f = " << f;
    }
}

// Hierarchical z takes the plane at the box's corner nearest the viewer, whatever its slopes' signs: over pixels
// [0, 3] x [0, 3] (samples 0.5 to 3.5 each way), a slope of +1/64 in x is nearest at x = 0.5 (+1/128 from
// x0 = 0), -1/64 at x = 3.5 (-7/128); in y, +-1/128 give +1/256 and -7/256. z0 puts that corner at
// f (err + stored_err) beyond the far depth; any other corner is at least 3/128 farther.
TEST(PlaneBound, HierarchicalZTakesTheNearestCornerForEverySlope) {
    const Context& c = plane_context();
    const TileBuffer tile = tile_with_far_depth(c);
    for (const double a : {1.0 / 64, -1.0 / 64})
        for (const double b : {1.0 / 128, -1.0 / 128})
            for (const double f : {0.9, 1.1}) {
                const double nearest_terms = (a > 0 ? 1.0 / 128 : -7.0 / 128) + (b > 0 ? 1.0 / 256 : -7.0 / 256);
                const double err = 1e-13, z0 = tile.far + f * (err + tile.stored_err) - nearest_terms;
                const Plane p{0, 0, z0, a, b, err};
                EXPECT_EQ(behind_tile(p, c, tile, 0, 3, 0, 3), f > 1) << "a " << a << ", b " << b << ", f " << f;
            }
}

// A depth the exact arithmetic rounded to nearest (stored where a plane's bound overflows), by hand: just
// short of the midpoint above 1, whose nearest double is 1, the error is all but u; just short of half the
// least subnormal, whose nearest double is 0, all but half of it.
TEST(NearestBound, IsSoundAndEveryTermBites) {
    struct Case {
        double nearest;
        Rational exact;
    };
    const Case cases[] = {{1, Rational(1) + Rational(0x1p-53) - Rational(0x1p-80)},
                          {0, Rational(DBL_TRUE_MIN) / 2 - Rational(DBL_TRUE_MIN) / 1024}};
    const auto worst_ratio = [&](auto bound) {
        double largest = 0;
        for (const Case& k : cases) largest = std::max(largest, ratio(abs(k.exact - k.nearest), bound(k.nearest)));
        return largest;
    };
    EXPECT_LE(worst_ratio(nearest_error<Sound>), 1.0);
    EXPECT_GT(worst_ratio(nearest_error<Halved>), 1.0);
    EXPECT_GT(worst_ratio(nearest_error<Without<NearestTerm::rounding>>), 1.0);
    EXPECT_GT(worst_ratio(nearest_error<Without<NearestTerm::underflow>>), 1.0);
}

// --- A line's depth at a pixel (line_depth.h) ------------------------------------------------------

// A segment's ends (x0, y0, z0, x1, y1, z1) and the pixel whose centre it is evaluated at.
struct LineCase {
    std::array<double, 6> ends;
    int i, j;
};

Segment segment_of(const std::array<double, 6>& e) { return {{Vertex{e[0], e[1], e[2]}, Vertex{e[3], e[4], e[5]}}}; }

// z at the segment's point nearest the centre, in rationals (docs/design.md).
Rational exact_line_depth(const Segment& s, double cx, double cy) {
    const Rational x0(s.v[0].x), y0(s.v[0].y), z0(s.v[0].z);
    const Rational dx = Rational(s.v[1].x) - x0, dy = Rational(s.v[1].y) - y0;
    const Rational d = dx * dx + dy * dy;
    const Rational n = (Rational(cx) - x0) * dx + (Rational(cy) - y0) * dy;
    if (d == 0 || n <= 0) return z0;
    if (n >= d) return Rational(s.v[1].z);
    return z0 + n / d * (Rational(s.v[1].z) - z0);
}

template <class W>
double line_ends_ratio(const std::array<double, 6>& ends, int i, int j) {
    const Segment s = segment_of(ends);
    const Bounded z = line_depth<W>(s, i + 0.5, j + 0.5);
    if (!(z.e < std::numeric_limits<double>::infinity())) return 0;
    return ratio(abs(Rational(z.v) - exact_line_depth(s, i + 0.5, j + 0.5)), z.e);
}

template <class W>
double line_ratio(const LineCase& k) {
    return line_ends_ratio<W>(k.ends, k.i, k.j);
}

// Centres well inside the segment's span (the clamp is decided), from three families: ends with every
// bit set, whose differences and products round, so the parameter's error leads; depths near 1 with a
// small rise (the evaluation's roundings lead); and ends on the 1/256 grid, where the parameter is a
// quotient of exact integers and depths of every magnitude.
std::vector<LineCase> line_cases(int count) {
    std::mt19937_64 rng(20261127);
    std::uniform_real_distribution<double> unit(0, 1), signed_unit(-1, 1);
    std::uniform_int_distribution<int> grid(0, 64 * 256), ulps(-64, 64);
    std::vector<LineCase> cases;
    for (int n = 0; n < count; ++n) {
        LineCase k{};
        const bool on_grid = n % 3 == 2;
        for (const int e : {0, 1, 3, 4}) k.ends[e] = on_grid ? grid(rng) / 256.0 : 64 * unit(rng);
        switch (n % 3) {
            case 0: k.ends[2] = 0, k.ends[5] = std::ldexp(signed_unit(rng), ulps(rng) % 16); break;
            case 1: k.ends[2] = 1 + ulps(rng) * 0x1p-52, k.ends[5] = 1 + std::ldexp(unit(rng), -20); break;
            default: k.ends[2] = std::ldexp(signed_unit(rng), ulps(rng) % 8), k.ends[5] = std::ldexp(signed_unit(rng), ulps(rng) % 8);
        }
        // A centre near the middle of the segment.
        const double t = 0.25 + unit(rng) / 2;
        k.i = static_cast<int>(std::floor(k.ends[0] + t * (k.ends[3] - k.ends[0])));
        k.j = static_cast<int>(std::floor(k.ends[1] + t * (k.ends[4] - k.ends[1])));
        const auto score = [&](const std::array<double, 6>& ends) { return line_ends_ratio<Sound>(ends, k.i, k.j); };
        climb(k.ends, score, rng, 200);
        cases.push_back(k);
    }
    return cases;
}

const std::vector<LineCase>& line_cases() {
    static const std::vector<LineCase> cases = line_cases(climbs(90));
    return cases;
}

TEST(LineDepthBound, IsSoundAndEveryTermBites) {
    const double sound = worst(line_cases(), line_ratio<Sound>);
    std::printf("line depth: worst error / bound %.3f\n", sound);
    EXPECT_LE(sound, 1.0);
    EXPECT_GT(worst(line_cases(), line_ratio<Halved>), 1.0);
    EXPECT_GT(worst(line_cases(), line_ratio<Without<LineDepthTerm::parameter>>), 1.0);
    EXPECT_GT(worst(line_cases(), line_ratio<Without<LineDepthTerm::evaluation>>), 1.0);
}

// The clamp, by hand: a centre beyond either end takes that end's z exactly, with no error to bound, and
// one exactly abreast of an end (n = 0 or n = d) is left to exact arithmetic.
TEST(LineDepthBound, ClampsExactlyOrNotAtAll) {
    const Segment s{{Vertex{0.5, 0.5, 0.1}, Vertex{4.5, 0.5, 0.7}}};
    EXPECT_EQ(line_depth(s, -1.5, 0.5).v, 0.1);
    EXPECT_EQ(line_depth(s, -1.5, 0.5).e, 0.0);
    EXPECT_EQ(line_depth(s, 6.5, 3.5).v, 0.7);
    EXPECT_EQ(line_depth(s, 6.5, 3.5).e, 0.0);
    EXPECT_EQ(line_depth(s, 0.5, 2.5).e, std::numeric_limits<double>::infinity());
    EXPECT_EQ(line_depth(s, 4.5, 2.5).e, std::numeric_limits<double>::infinity());
    const Bounded middle = line_depth(s, 2.5, 7.5);
    EXPECT_LE(std::abs(middle.v - 0.4), middle.e);
    EXPECT_LT(middle.e, 1e-15);
    // A review's case: n's enclosure overflows to -inf +- inf, which once read as "n <= 0" and gave the
    // start's z exactly, while the exact n is positive.
    const Segment far{{Vertex{0x1.0000000000002p+60, -0x1.f30567547a34cp+60, 0},
                       Vertex{0x1.ffffffffffffcp+963, 0x1.06a881a323e6bp+963, 1}}};
    EXPECT_GT(exact_line_depth(far, 127.5, 0.5), 0);
    EXPECT_EQ(line_depth(far, 127.5, 0.5).e, std::numeric_limits<double>::infinity());
}

// --- The float modes' edge function ----------------------------------------------------------------

// Edge a -> b at sample p: ax, ay, bx, by, px, py, in a mode's type T.
using EdgeCase = std::array<double, 6>;

// fl(d1 d2) - fl(d3 d4) as the kernels compute it in T (scalar.h), before the last rounding.
template <class T>
Rational computed_edge(const EdgeCase& e) {
    const T ax = T(e[0]), ay = T(e[1]), bx = T(e[2]), by = T(e[3]), px = T(e[4]), py = T(e[5]);
    const T p1 = T(bx - ax) * T(py - ay), p2 = T(by - ay) * T(px - ax);
    return Rational(double(p1)) - Rational(double(p2));
}

Rational exact_edge(const EdgeCase& e) {
    return (Rational(e[2]) - e[0]) * (Rational(e[5]) - e[1]) - (Rational(e[3]) - e[1]) * (Rational(e[4]) - e[0]);
}

template <class W, class T>
double edge_ratio(const EdgeCase& e) {
    const Vertex a{e[0], e[1], 0}, b{e[2], e[3], 0};
    const EdgeFormat& f = std::is_same_v<T, float> ? kFloat32Edges : kFloat64Edges;
    const double bound = directed_edge_bound<W>(a, b, reach_at(a, e[4], e[5], f), f);
    if (!(bound < std::numeric_limits<double>::infinity())) return 0;
    const Rational computed = computed_edge<T>(e);
    return ratio(abs(computed - exact_edge(e)), bound);
}

// Steps of the climb for float32 inputs: whole float ulps (a float stays a float), or sixteenths of one
// (so that the inputs' own rounding to float moves too).
double float_ulps(double x, int k) {
    float f = float(x);
    for (int n = 0; n < std::abs(k); ++n) f = std::nextafter(f, k > 0 ? FLT_MAX : -FLT_MAX);
    return f;
}

double float_sixteenths(double x, int k) {
    const float f = std::abs(float(x));
    return x + k * double(std::nextafter(f, FLT_MAX) - f) / 16;
}

// Samples near the edge's line (the products cancel), and off it; coordinates of every magnitude, down to
// where the products are subnormal in T; for float32, inputs with more bits than a float holds.
template <class T>
std::vector<EdgeCase> edge_cases(int count) {
    std::mt19937_64 rng(std::is_same_v<T, float> ? 32 : 64);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> magnitude(-4, 30);
    const int tiny = std::is_same_v<T, float> ? -80 : -560;
    std::vector<EdgeCase> cases;
    for (int n = 0; n < count; ++n) {
        const int scale = n % 4 == 3 ? tiny + magnitude(rng) : magnitude(rng);
        const bool floats = std::is_same_v<T, float> && n % 2 == 0;
        const auto coordinate = [&] {
            const double x = std::ldexp(unit(rng), scale);
            return floats ? double(float(x)) : x;
        };
        EdgeCase e{coordinate(), coordinate(), coordinate(), coordinate(), 0, 0};
        const double t = unit(rng), off = n % 3 == 0 ? unit(rng) : 0;
        e[4] = e[0] + t * (e[2] - e[0]) - off * (e[3] - e[1]);
        e[5] = e[1] + t * (e[3] - e[1]) + off * (e[2] - e[0]);
        if (floats) {
            for (double& x : e) x = float(x);
            climb(e, edge_ratio<Sound, T>, rng, 300, float_ulps);
        } else {
            const auto step = std::is_same_v<T, float> ? float_sixteenths : filters::testing::nudge;
            climb(e, edge_ratio<Sound, T>, rng, 300, step);
        }
        cases.push_back(e);
    }
    return cases;
}

template <class T>
void expect_edge_bound_bites(const char* name) {
    const std::vector<EdgeCase> cases = edge_cases<T>(climbs(80));
    const double sound = worst(cases, edge_ratio<Sound, T>);
    std::printf("%s edges: worst error / bound %.3f\n", name, sound);
    EXPECT_LE(sound, 1.0);
    EXPECT_GT(worst(cases, edge_ratio<Halved, T>), 1.0);
    EXPECT_GT(worst(cases, edge_ratio<Without<EdgeTerm::difference>, T>), 1.0);
    EXPECT_GT(worst(cases, edge_ratio<Without<EdgeTerm::product>, T>), 1.0);
    EXPECT_GT(worst(cases, edge_ratio<Without<EdgeTerm::underflow>, T>), 1.0);
    if (std::is_same_v<T, float>) {
        EXPECT_GT(worst(cases, edge_ratio<Without<EdgeTerm::input>, T>), 1.0);
    }
}

TEST(EdgeBound, Float32IsSoundAndEveryTermBites) { expect_edge_bound_bites<float>("float32"); }

TEST(EdgeBound, Float64IsSoundAndEveryTermBites) { expect_edge_bound_bites<double>("float64"); }

// The float modes accept or reject a whole tile where every sample's exact edge function is beyond the
// tile margin, the mode's edge bound plus the double evaluation's, so that the tile's samples get what
// the per-sample float evaluation would give them. corpus/filters/float-margin-halved-accepts-a-sample.tri:
// one edge passes by the corner sample (63.5, 63.5) of the tile [0, 64)^2, exactly inside by 0.643 of
// the margin, while its float32 edge function there is exactly 0 on a right edge, which does not own the
// sample. The tile is partial, and float32 leaves the sample out, as covered_samples (which never
// classifies tiles) does; with the margin halved the tile is accepted whole and the sample drawn.
TEST(TileMargin, HalvedAcceptsASampleTheFloatEvaluationLeavesOut) {
    const Triangle t{{Vertex{0x1.07766411db3e2p+23, -0x1.05a033fb8188cp+23, 0},
                      Vertex{-0x1.077561f1db3e2p+23, 0x1.05a135fb8188cp+23, 0}, Vertex{-136, -136, 0}}};
    const Scene scene{{64, 64}, 1, {t}};
    const std::size_t corner = 63 * 64 + 63;
    const float ax = float(t.v[0].x), ay = float(t.v[0].y), bx = float(t.v[1].x), by = float(t.v[1].y);
    EXPECT_EQ((bx - ax) * (63.5f - ay) - (by - ay) * (63.5f - ax), 0.0f);
    const Rational exact = (Rational(t.v[1].x) - t.v[0].x) * (Rational(63.5) - t.v[0].y) -
                           (Rational(t.v[1].y) - t.v[0].y) * (Rational(63.5) - t.v[0].x);
    const Viewport vp = scene.viewport;
    const double margin = edge_error_bound(t, Precision::float32, vp) + edge_error_bound(t, Precision::float64, vp);
    EXPECT_GT(exact, Rational(margin) / 2);
    EXPECT_LT(exact, Rational(margin));

    const std::vector<std::size_t> per_sample = covered_samples(t, vp, 1, Precision::float32);
    EXPECT_FALSE(std::binary_search(per_sample.begin(), per_sample.end(), corner));
    EXPECT_EQ(per_sample.size(), std::size_t{64 * 64 - 1});
    EXPECT_EQ(render(scene, {Precision::float32, 1}).ids[corner], Framebuffer::kNoTriangle);
    EXPECT_EQ(render_with_fault(scene, {Precision::float32, 1}, Fault::halved_float_margin).ids[corner], 0);
}

}  // namespace
}  // namespace rast::fast::detail
