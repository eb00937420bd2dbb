// wide_bands, what the wide path classifies whole tiles by, against the spans it stands for (wide_spans,
// walked row by row): every span of a band lies within its band, and the bounds that decide trivial
// accept (lo_max, and hi_min where every row has samples) are the spans' own extremes. And BandSpans,
// where the tiles of a row of tiles find the spans they need.
#include "engine.h"
#include "setup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <random>
#include <span>
#include <utility>
#include <vector>

namespace rast::fast::detail {
namespace {

// A corner on the 2^-bits grid: near the viewport, or up to 2^far pixels away (beyond 2^(60 - bits)
// the wide path takes big integers), sometimes on the row or column of the corner before it, so that
// edges along the rows and columns come up.
double coordinate(std::mt19937_64& rng, int bits, double near_size, int far, const double* previous) {
    const int shape = std::uniform_int_distribution<int>(0, 9)(rng);
    if (shape == 0 && previous) return *previous;
    if (shape <= 3) {
        const double magnitude = std::ldexp(1.0, std::uniform_int_distribution<int>(20, far)(rng));
        return std::round(std::uniform_real_distribution<double>(-magnitude, magnitude)(rng));
    }
    const double x = std::uniform_real_distribution<double>(-8, near_size + 8)(rng);
    return std::ldexp(std::round(std::ldexp(x, bits)), -bits);
}

TEST(WideBands, HoldEverySpanOfTheirRowsAndTheAcceptBoundsExactly) {
    std::mt19937_64 rng(20261124);
    const Viewport vp{150, 200};
    int bands_checked = 0, exact_hi_min = 0;
    for (const Precision precision : {Precision::fixed4, Precision::fixed8, Precision::fixed16})
        for (const int samples : {1, 4, 16}) {
            const Context c = make_context<Fault::none>(vp, samples, precision);
            for (int n = 0; n < 150; ++n) {
                Corners v;
                for (int k = 0; k < 3; ++k) {
                    v[k].x = coordinate(rng, c.bits, vp.width, 70, k > 0 ? &v[k - 1].x : nullptr);
                    v[k].y = coordinate(rng, c.bits, vp.height, 70, k > 0 ? &v[k - 1].y : nullptr);
                }
                const std::optional<Placed> placed = place<Fault::none>(Triangle{v}, c);
                if (!placed) continue;
                const Placed& p = *placed;
                const std::array<bool, 3> owns = owning_edges<Fault::none>(p.v);
                const std::vector<SpanBand> bands =
                    wide_bands(p.v, c.bits, owns, c.offsets, p.i_lo, p.i_hi, p.j_lo, p.j_hi, kTile);
                ASSERT_EQ(bands.size(), static_cast<std::size_t>(p.j_hi / kTile - p.j_lo / kTile + 1));
                for (std::size_t k = 0; k < bands.size(); ++k) {
                    const int first = std::max(p.j_lo, (p.j_lo / kTile + static_cast<int>(k)) * kTile);
                    const int last = std::min(p.j_hi, first / kTile * kTile + kTile - 1);
                    std::vector<Span> spans(static_cast<std::size_t>(last - first + 1) * samples);
                    wide_spans(p.v, c.bits, owns, c.offsets, p.i_lo, p.i_hi, first, last, spans);
                    SCOPED_TRACE(::testing::Message() << "precision " << static_cast<int>(precision) << ", samples "
                                                      << samples << ", triangle " << n << ", band " << k);
                    const SpanBand& band = bands[k];
                    int lo_max = INT_MIN, hi_min = INT_MAX;
                    bool every_row_covered = true;
                    for (const Span& s : spans) {
                        lo_max = std::max(lo_max, s.lo);
                        hi_min = std::min(hi_min, s.hi);
                        if (s.lo > s.hi) {
                            every_row_covered = false;
                            continue;
                        }
                        EXPECT_GE(s.lo, band.lo_min);
                        EXPECT_LE(s.hi, band.hi_max);
                    }
                    EXPECT_EQ(band.lo_max, lo_max);
                    EXPECT_LE(band.hi_min, hi_min);
                    if (every_row_covered) {
                        EXPECT_EQ(band.hi_min, hi_min);
                        ++exact_hi_min;
                    }
                    if (::testing::Test::HasFailure()) return;
                    ++bands_checked;
                }
            }
        }
    // The generator does reach the viewport, and rows of tiles every one of whose rows has samples.
    EXPECT_GT(bands_checked, 1000);
    EXPECT_GT(exact_hi_min, 200);
}

// BandSpans gives a triangle's spans as spans_of finds them, whether it kept them from an earlier tile,
// dropped them for room (it keeps three triangles' here), moved to another row of tiles in between, or
// was asked for other rows of the same row of tiles (band -1: rows 10 to 20 of the first); and having
// given them, keeps them.
TEST(BandSpans, GiveEachTrianglesSpansWhateverTheyKept) {
    const Context c = make_context<Fault::none>({200, 150}, 4, Precision::fixed8);
    const double r = 0x1p30;  // beyond the 64-bit path's range: the wide path
    std::vector<detail::Setup> setups;  // qualified: a test body sees testing::Test::Setup
    for (int k = 0; k < 5; ++k) {
        const double x = 20.5 + 30 * k;
        const std::optional<Placed> p = place<Fault::none>(Triangle{{{{x, -1, 0}, {2 * r, 70, 0}, {x + 30, 151, 0}}}}, c);
        ASSERT_TRUE(p && p->path == Path::wide);
        setups.push_back(setup_triangle<Fault::none>(*p, c, true));
    }
    BandSpans band_spans(3 * kTile * c.offsets.size());
    const std::pair<int, int> visits[] = {{0, 0}, {1, 0}, {2, 0}, {0, 0}, {3, 0}, {4, 0}, {0, 0}, {1, 0},  {2, 1},
                                          {1, 1}, {2, 0}, {4, 2}, {4, 2}, {0, 1}, {0, 0}, {0, -1}, {0, 0}};
    for (const auto& [k, band] : visits) {
        const detail::Setup& t = setups[static_cast<std::size_t>(k)];
        const int j0 = band < 0 ? 10 : std::max(t.p.j_lo, band * kTile);
        const int j1 = band < 0 ? 20 : std::min(t.p.j_hi, band * kTile + kTile - 1);
        std::vector<Span> expected(static_cast<std::size_t>(j1 - j0 + 1) * c.offsets.size());
        spans_of(t, c, j0, j1, expected);
        const std::span<const Span> given = band_spans.of(t, c, j0, j1);
        ASSERT_EQ(given.size(), expected.size());
        for (std::size_t n = 0; n < expected.size(); ++n) {
            EXPECT_EQ(given[n].lo, expected[n].lo) << "triangle " << k << ", band " << band << ", span " << n;
            EXPECT_EQ(given[n].hi, expected[n].hi) << "triangle " << k << ", band " << band << ", span " << n;
        }
        // Kept: asked again, the same spans, not walked again.
        EXPECT_EQ(band_spans.of(t, c, j0, j1).data(), given.data()) << "triangle " << k << ", band " << band;
    }
}

}  // namespace
}  // namespace rast::fast::detail
