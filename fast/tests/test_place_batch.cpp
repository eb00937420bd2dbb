// place_small_batch (place_batch.h) against place_small_fixed (setup.h), the one-triangle definition, lane
// by lane on every SIMD target: the same verdict (small, culled or general; general for a depth that is
// not finite) and, for a small triangle, the same record, for every fixed mode and sample count, on
// triangles chosen where the steps can go wrong: corners on and off the grid's ties, clockwise and
// counter-clockwise, zero area, boxes of 31, 32 and 33 pixels, boxes clipped by the viewport and outside
// it, coordinates at and past the fixed range, NaN and infinity, corners so far apart that the cross
// product's terms pass 2^53 (undecided lanes: test_binning.cpp checks what becomes of them), slivers
// whose cross product is +-1 between terms near 2^56, and extents either side of narrow_edges' limit.
#include "binning.h"
#include "targets.h"

#include <rast/filters/orientation.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace rast::fast::detail {
namespace {

using testing::on_every_target;

Vertex random_vertex(std::mt19937_64& rng, const Context& c, double cx, double cy, double reach) {
    std::uniform_real_distribution<double> offset(-reach, reach), depth(-1, 1);
    std::uniform_int_distribution<int> kind(0, 19);
    const auto coordinate = [&](double centre) {
        const double v = centre + offset(rng);
        switch (kind(rng)) {
            case 0: return std::round(v / c.unit) * c.unit + c.unit / 2;  // a tie of the grid's rounding
            case 1: return std::round(v);                                // on a pixel corner
            case 2: return c.coordinate_limit * (offset(rng) < 0 ? -1 : 1);  // the range's end
            case 3: return std::nextafter(c.coordinate_limit, 1e300) * (offset(rng) < 0 ? -1 : 1);  // just past it
            case 4: return offset(rng) < 0 ? -0.0 : 0.0;
            default: return v;
        }
    };
    return {coordinate(cx), coordinate(cy), depth(rng)};
}

// A triangle with one corner near the viewport's far corner (a small box there) and two far out, chosen
// so that its cross product is +-1 in grid units while its two products are near 2^56: doubles round
// those products, and only their exactness bound sends such a lane to place_small_fixed.
Triangle sliver(std::mt19937_64& rng, const Context& c) {
    std::uniform_int_distribution<std::int64_t> big(std::int64_t{1} << 27, std::int64_t{1} << 28);
    std::int64_t a = big(rng), b = big(rng);
    // Extended Euclid: u a + v b = gcd(a, b); made coprime by dividing it out.
    std::int64_t r0 = a, r1 = b, u0 = 1, u1 = 0, v0 = 0, v1 = 1;
    while (r1 != 0) {
        const std::int64_t q = r0 / r1;
        std::tie(r0, r1) = std::make_tuple(r1, r0 - q * r1);
        std::tie(u0, u1) = std::make_tuple(u1, u0 - q * u1);
        std::tie(v0, v1) = std::make_tuple(v1, v0 - q * v1);
    }
    a /= r0;
    b /= r0;
    // a u0 + b v0 = 1: the corners (a, b) and (a - v0, b + u0) have a (b + u0) - b (a - v0) = 1.
    const double x0 = 1020, y0 = 1020, scale = 1 / c.unit;
    const auto at = [&](std::int64_t dx, std::int64_t dy) {
        return Vertex{x0 + static_cast<double>(dx) / scale, y0 + static_cast<double>(dy) / scale, 0.25};
    };
    Triangle t{{at(0, 0), at(a, b), at(a - v0, b + u0)}};
    if (rng() % 2) std::swap(t.v[1], t.v[2]);
    return t;
}

// A triangle whose larger extent w is the last or the first past narrow_edges' limit
// (2 w (w + scale) + 1 < 2^31), its box clipped small at the viewport's far corner.
Triangle at_the_narrow_limit(std::mt19937_64& rng, const Context& c) {
    const double scale = 1 / c.unit;
    std::int64_t w = 1;
    while (2 * (w + 1) * (w + 1 + static_cast<std::int64_t>(scale)) + 1 < (std::int64_t{1} << 31)) ++w;
    w += static_cast<std::int64_t>(rng() % 4) - 1;  // w* - 1 to w* + 2
    const double x0 = c.vp.width - 1.5, y0 = c.vp.height - 1.5, far = static_cast<double>(w) * c.unit;
    Triangle t{{Vertex{x0, y0, 0.5}, Vertex{x0 + far, y0 + 3 * c.unit, 0.25}, Vertex{x0 + 5 * c.unit, y0 + far, 0.75}}};
    if (rng() % 2) std::swap(t.v[1], t.v[2]);
    return t;
}

Triangle random_triangle(std::mt19937_64& rng, const Context& c) {
    std::uniform_real_distribution<double> where(-40, 1064);
    std::uniform_int_distribution<int> shape(0, 10);
    const double cx = where(rng), cy = where(rng);
    Triangle t;
    switch (shape(rng)) {
        case 0:  // far apart: products past 2^53 in the coarse modes too
            for (Vertex& v : t.v) v = random_vertex(rng, c, cx, cy, c.coordinate_limit);
            break;
        case 1:  // zero area: a point repeated, or three on a line
            t.v[0] = random_vertex(rng, c, cx, cy, 8);
            t.v[1] = random_vertex(rng, c, cx, cy, 8);
            t.v[2] = shape(rng) < 5 ? t.v[0] : Vertex{2 * t.v[1].x - t.v[0].x, 2 * t.v[1].y - t.v[0].y, 0.5};
            break;
        case 2:  // boxes about 32 pixels across, either side of the small lane's limit
            for (Vertex& v : t.v) v = random_vertex(rng, c, cx, cy, 16.5);
            break;
        case 3: {  // not finite
            for (Vertex& v : t.v) v = random_vertex(rng, c, cx, cy, 4);
            const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity()};
            double* field = &t.v[shape(rng) % 3].x + shape(rng) % 3;
            *field = bad[shape(rng) % 3];
            break;
        }
        case 4:
            return sliver(rng, c);
        case 5:
            return at_the_narrow_limit(rng, c);
        default:  // tiny to small
            for (Vertex& v : t.v) v = random_vertex(rng, c, cx, cy, shape(rng) < 7 ? 3 : 12);
            break;
    }
    return t;
}

void expect_same_record(const SmallFixed& got, const SmallFixed& want, const std::string& what) {
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(got.x[k], want.x[k]) << what;
        EXPECT_EQ(got.y[k], want.y[k]) << what;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(got.z[k]), std::bit_cast<std::uint64_t>(want.z[k])) << what;
    }
    EXPECT_EQ(got.i_lo, want.i_lo) << what;
    EXPECT_EQ(got.i_hi, want.i_hi) << what;
    EXPECT_EQ(got.j_lo, want.j_lo) << what;
    EXPECT_EQ(got.j_hi, want.j_hi) << what;
    EXPECT_EQ(got.id, want.id) << what;
    EXPECT_EQ(got.narrow, want.narrow) << what;
}

TEST(PlaceBatch, EqualsPlaceSmallFixedOnEveryTarget) {
    on_every_target([&] {
        std::mt19937_64 rng(20261127);
        int verdicts[4] = {};  // small, culled, general, undecided
        for (const Precision precision : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
            for (const int samples : {1, 4, 8, 16}) {
                const Context c = make_context<Fault::none>({1024, 1024}, samples, precision);
                const PlaceGrid grid = place_grid(c);
                for (int trial = 0; trial < 3000; ++trial) {
                    std::vector<Triangle> batch(1 + trial % kPlaceBatch);
                    for (Triangle& t : batch) t = random_triangle(rng, c);
                    const int n = static_cast<int>(batch.size());
                    PlacedBatch got;
                    place_small_batch(batch.data(), n, grid, got);
                    EXPECT_EQ(got.small & got.culled, 0u);
                    EXPECT_EQ((got.small | got.culled) & (got.general | got.undecided), 0u);
                    EXPECT_EQ(got.general & got.undecided, 0u);
                    EXPECT_EQ(got.small | got.culled | got.general | got.undecided, (1u << n) - 1);
                    for (int k = 0; k < n; ++k) {
                        const std::uint32_t bit = 1u << k;
                        const std::string what = "trial " + std::to_string(trial) + " lane " + std::to_string(k);
                        SmallFixed want;
                        Lane lane = place_small_fixed<Fault::none>(batch[k], 7, c, want);
                        // place_small_fixed leaves depths to its caller; the batch sends a triangle with
                        // one that is not finite to the general lane, which checks every coordinate.
                        const bool finite_depths = std::isfinite(batch[k].v[0].z) && std::isfinite(batch[k].v[1].z) &&
                                                   std::isfinite(batch[k].v[2].z);
                        if (!finite_depths) lane = Lane::general;
                        if (got.undecided & bit) {
                            ++verdicts[3];
                            continue;  // place_small_fixed's own to decide
                        }
                        EXPECT_EQ(lane == Lane::small_fixed, (got.small & bit) != 0) << what;
                        EXPECT_EQ(lane == Lane::culled, (got.culled & bit) != 0) << what;
                        EXPECT_EQ(lane == Lane::general, (got.general & bit) != 0) << what;
                        ++verdicts[lane == Lane::small_fixed ? 0 : lane == Lane::culled ? 1 : 2];
                        if (lane == Lane::small_fixed) expect_same_record(small_fixed_of(got, k, 7), want, what);
                        if (HasFailure()) return;
                    }
                }
            }
        // Every verdict is met often.
        for (const int count : verdicts)
            EXPECT_GT(count, 1000) << verdicts[0] << " " << verdicts[1] << " " << verdicts[2] << " " << verdicts[3];
    });
}

// A triangle for the float modes' batch: tiny to 33 pixels across, with corners on pixel centres and
// sample rows (the pixel range's ties), just off the viewport, near-collinear (the orientation filter left
// open), of zero area, 10^300 across, subnormal, or not finite.
Triangle random_float_triangle(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> where(-40, 1064), depth(-1, 1);
    std::uniform_int_distribution<int> shape(0, 11);
    const double cx = where(rng), cy = where(rng);
    const auto near = [&](double reach) {
        std::uniform_real_distribution<double> offset(-reach, reach);
        const auto coordinate = [&](double centre) {
            const double v = centre + offset(rng);
            switch (shape(rng)) {
                case 0: return std::round(v) + 0.5;   // a pixel centre
                case 1: return std::round(v) + 0.375;  // a row or column of the 4- and 8-sample patterns
                case 2: return std::round(v);
                default: return v;
            }
        };
        return Vertex{coordinate(cx), coordinate(cy), depth(rng)};
    };
    Triangle t;
    switch (shape(rng)) {
        case 0:  // near-collinear: the third corner a few units in the last place off the others' line
            t.v[0] = near(12);
            t.v[1] = near(12);
            t.v[2] = {(t.v[0].x + t.v[1].x) / 2, std::nextafter((t.v[0].y + t.v[1].y) / 2, shape(rng) < 6 ? 1e9 : -1e9),
                      0.5};
            break;
        case 1:  // zero area
            t.v[0] = near(8);
            t.v[1] = near(8);
            t.v[2] = t.v[shape(rng) % 2];
            break;
        case 2:  // boxes about 32 pixels across, either side of the small lane's limit
            for (Vertex& v : t.v) v = near(16.5);
            break;
        case 3: {  // not finite
            for (Vertex& v : t.v) v = near(4);
            const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity()};
            *(&t.v[shape(rng) % 3].x + shape(rng) % 3) = bad[shape(rng) % 3];
            break;
        }
        case 4:  // far apart: products that overflow
            for (Vertex& v : t.v) v = {std::ldexp(depth(rng), 1000), std::ldexp(depth(rng), 1000), depth(rng)};
            break;
        case 5:  // products in the subnormal range, below the filter's absolute term
            for (Vertex& v : t.v) v = {std::ldexp(depth(rng), -530), std::ldexp(depth(rng), -530), depth(rng)};
            break;
        default:  // tiny to small
            for (Vertex& v : t.v) v = near(shape(rng) < 8 ? 3 : 12);
            break;
    }
    return t;
}

// place_float_batch against place<Fault::none>, lane by lane on every SIMD target: a small lane is the
// triangle place finds small, with its corners and box; a culled one, one place finds covers nothing; and
// a lane in neither is one place must settle: a coordinate not finite, a winding the filter leaves open,
// or a box too big.
TEST(PlaceBatch, FloatEqualsPlaceOnEveryTarget) {
    on_every_target([&] {
        std::mt19937_64 rng(20261129);
        int verdicts[3] = {}, open_windings = 0;  // small, culled, left to place
        for (const Precision precision : {Precision::float32, Precision::float64})
            for (const int samples : {1, 4, 8, 16}) {
                const Context c = make_context<Fault::none>({1024, 1024}, samples, precision);
                const PlaceGrid grid = float_place_grid(c);
                for (int trial = 0; trial < 3000; ++trial) {
                    std::vector<Triangle> batch(1 + trial % kPlaceBatch);
                    for (Triangle& t : batch) t = random_float_triangle(rng);
                    const int n = static_cast<int>(batch.size());
                    FloatPlacedBatch got;
                    place_float_batch(batch.data(), n, grid, got);
                    EXPECT_EQ(got.small & got.culled, 0u);
                    EXPECT_EQ((got.small | got.culled) >> n, 0u);
                    for (int k = 0; k < n; ++k) {
                        const std::uint32_t bit = 1u << k;
                        const std::string what = "trial " + std::to_string(trial) + " lane " + std::to_string(k);
                        const Triangle& t = batch[k];
                        if (!is_finite(t)) {
                            EXPECT_EQ((got.small | got.culled) & bit, 0u) << what;
                            ++verdicts[2];
                            continue;
                        }
                        const std::optional<Placed> want = place<Fault::none>(t, c);
                        const bool open = filters::orientation(t.v[0].x, t.v[0].y, t.v[1].x, t.v[1].y, t.v[2].x,
                                                               t.v[2].y).certain_sign() == 0;
                        EXPECT_EQ((got.culled & bit) != 0, !want && !open) << what;
                        EXPECT_EQ((got.small & bit) != 0, want && !open && is_small(*want)) << what;
                        ++verdicts[got.small & bit ? 0 : got.culled & bit ? 1 : 2];
                        open_windings += open;
                        if (got.small & bit) {
                            for (int corner = 0; corner < 3; ++corner) {
                                EXPECT_EQ(std::bit_cast<std::uint64_t>(got.x[corner][k]),
                                          std::bit_cast<std::uint64_t>(want->v[corner].x)) << what;
                                EXPECT_EQ(std::bit_cast<std::uint64_t>(got.y[corner][k]),
                                          std::bit_cast<std::uint64_t>(want->v[corner].y)) << what;
                                EXPECT_EQ(std::bit_cast<std::uint64_t>(got.z[corner][k]),
                                          std::bit_cast<std::uint64_t>(want->v[corner].z)) << what;
                            }
                            EXPECT_EQ(got.i_lo[k], want->i_lo) << what;
                            EXPECT_EQ(got.i_hi[k], want->i_hi) << what;
                            EXPECT_EQ(got.j_lo[k], want->j_lo) << what;
                            EXPECT_EQ(got.j_hi[k], want->j_hi) << what;
                        }
                        if (HasFailure()) return;
                    }
                }
            }
        // Every verdict is met often.
        for (const int count : verdicts)
            EXPECT_GT(count, 1000) << verdicts[0] << " " << verdicts[1] << " " << verdicts[2];
        EXPECT_GT(open_windings, 300);
    });
}

}  // namespace
}  // namespace rast::fast::detail
