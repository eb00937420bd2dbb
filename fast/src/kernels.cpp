// Highway compiles this file once per SIMD target (foreach_target) and dispatches to the best one the
// CPU supports at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/cache_control.h>
#include <hwy/highway.h>

#include "kernels.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace rast::fast::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Double lanes carry the depth test; every coverage evaluator answers in them.
using D = hn::ScalableTag<double>;
using DI = hn::RebindToSigned<D>;
using MD = hn::Mask<D>;
using VD = hn::Vec<D>;

template <class Tag>
HWY_INLINE std::uint64_t mask_bits(Tag d, hn::Mask<Tag> m) {
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(d, m, bytes);
    std::uint64_t bits = 0;
    std::memcpy(&bits, bytes, (hn::Lanes(d) + 7) / 8);
    return bits;
}

HWY_INLINE MD lanes_of(D d, std::uint64_t bits) {
    std::uint8_t bytes[8];
    std::memcpy(bytes, &bits, sizeof bytes);
    return hn::LoadMaskBits(d, bytes);
}

// The ids of the depth lanes, 32 bits each.
using DId = hn::Rebind<std::int32_t, D>;

// The lanes of m as DId's (RebindMask needs lanes of one size): AVX-512's masks are a bit per lane
// whatever its size; the others' are vectors, whose 64-bit lanes are narrowed (on a fixed-size vector:
// a scalable target's narrowed mask would also cover the lanes past DId's); the scalar target's go
// through their bits.
HWY_INLINE hn::Mask<DId> id_lanes(MD m) {
#if HWY_TARGET <= HWY_AVX3
    return hn::Mask<DId>{m.raw};
#elif HWY_TARGET != HWY_SCALAR
    const hn::RebindToUnsigned<D> du;
    const hn::Rebind<std::uint32_t, D> du32;
    return hn::RebindMask(DId(), hn::MaskFromVec(hn::TruncateTo(du32, hn::BitCast(du, hn::VecFromMask(D(), m)))));
#else
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(D(), m, bytes);
    return hn::LoadMaskBits(DId(), bytes);
#endif
}

// min(closest, |v|) in the lanes of `mask`, closest elsewhere; closest >= 0. AVX-512's range operation
// takes the absolute value in the same instruction.
HWY_INLINE VD masked_min_abs(MD mask, VD closest, VD v) {
#if HWY_TARGET <= HWY_AVX3
    return VD{_mm512_mask_range_pd(closest.raw, mask.raw, closest.raw, v.raw, 0xA)};  // min |.|, sign cleared
#else
    return hn::IfThenElse(mask, hn::Min(closest, hn::Abs(v)), closest);
#endif
}

// The edges' lanes, 32 bits each.
using DI32 = hn::ScalableTag<std::int32_t>;

// The lanes of `mask` where a > b. On AVX-512 one compare under the mask, not a compare and a mask
// operation: the depth test's loops are bound by mask operations there.
HWY_INLINE MD masked_gt(MD mask, VD a, VD b) {
#if HWY_TARGET <= HWY_AVX3
    return MD{_mm512_mask_cmp_pd_mask(mask.raw, a.raw, b.raw, _CMP_GT_OQ)};
#else
    return hn::And(mask, hn::Gt(a, b));
#endif
}
HWY_INLINE hn::Mask<DI32> masked_gt(hn::Mask<DI32> mask, hn::Vec<DI32> a, hn::Vec<DI32> b) {
#if HWY_TARGET <= HWY_AVX3
    return hn::Mask<DI32>{_mm512_mask_cmpgt_epi32_mask(mask.raw, a.raw, b.raw)};
#else
    return hn::And(mask, hn::Gt(a, b));
#endif
}

// Each evaluator is told the row (start_row, rows in order from 0), then asked for the lanes from k = 0
// upwards in steps of Lanes(D) (chunk), px being the lanes' sample x, i + sx.
struct All {
    void start_row(int) {}
    MD chunk(int, VD) { return hn::FirstN(D(), hn::Lanes(D())); }
};

struct Masks {
    const std::uint64_t* masks;
    std::uint64_t bits = 0;
    void start_row(int r) { bits = masks[r]; }
    MD chunk(int k, VD) { return lanes_of(D(), bits >> k); }
};

struct FixedEdges {
    explicit FixedEdges(const Coverage& c) {
        const DI di;
        const int lanes = static_cast<int>(hn::Lanes(di));
        HWY_ALIGN std::int64_t ramp[HWY_MAX_BYTES / sizeof(std::int64_t)];
        for (int e = 0; e < 3; ++e) {
            for (int k = 0; k < lanes; ++k) ramp[k] = k * c.dx[e];
            row[e] = hn::Add(hn::Set(di, c.e[e]), hn::Load(di, ramp));
            step[e] = hn::Set(di, c.dx[e] * lanes);
            down[e] = hn::Set(di, c.dy[e]);
        }
    }
    // Rows come in order from 0: each starts where the previous one started, one row down.
    void start_row(int) {
        for (int e = 0; e < 3; ++e) {
            value[e] = row[e];
            row[e] = hn::Add(row[e], down[e]);
        }
    }
    MD chunk(int, VD) {
        // All three are >= 0 exactly when their bitwise or is > -1.
        const auto inside = hn::Gt(hn::Or(hn::Or(value[0], value[1]), value[2]), hn::Set(DI(), -1));
        for (int e = 0; e < 3; ++e) value[e] = hn::Add(value[e], step[e]);
        return hn::RebindMask(D(), inside);
    }
    hn::Vec<DI> row[3], step[3], down[3], value[3];
};

// The loops take the evaluator and the block by value: a local whose address never escapes
// stays in registers, where one behind a reference is reloaded and stored around every vector store (an
// integer vector store may alias anything).
template <class Evaluator>
void CoverageLoop(const Block b, Evaluator ev, std::uint64_t* covered) {
    const D d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto ramp = hn::Iota(d, 0.0), advance = hn::Set(d, static_cast<double>(lanes));
    // px = i + sx: sums of integers below 2^25 and multiples of 1/16, exact; lanes at px_end or beyond
    // are past the block.
    const auto px_end = hn::Set(d, double(b.i0 + b.width) + b.sx);
    for (int r = 0; r < b.rows; ++r) {
        ev.start_row(r);
        std::uint64_t bits = 0;
        auto px = hn::Add(hn::Set(d, double(b.i0) + b.sx), ramp);
        for (int k = 0; k < b.width; k += lanes, px = hn::Add(px, advance)) {
            const auto m = hn::And(ev.chunk(k, px), hn::Lt(px, px_end));
            bits |= mask_bits(d, m) << k;
        }
        covered[r] = bits;
    }
}

// The z-buffer test of DepthPlane on a vector of samples of one row. kPerSample: the stored depths'
// error bounds are DepthRows::err's, read and written with them; otherwise DepthPlane::stored_err.
template <bool kPerSample>
struct DepthLanes {
    explicit DepthLanes(const DepthPlane& p)
        : z0(hn::Set(D(), p.z0)), a(hn::Set(D(), p.a)), x0(hn::Set(D(), p.x0)), b(hn::Set(D(), p.b)),
          y0(hn::Set(D(), p.y0)), e(hn::Set(D(), p.err)), margin(hn::Set(D(), p.err + p.stored_err)),
          id(hn::Set(DId(), p.id)) {}
    // a (px - x0) and b (py - y0), the scalar definition's, lane by lane: a column's and a row's terms of
    // the plane. The methods below take the lanes' column terms (a_dx) and their row's (b_dy).
    HWY_INLINE VD a_dx(VD px) const { return hn::Mul(a, hn::Sub(px, x0)); }
    HWY_INLINE VD b_dy(VD py) const { return hn::Mul(b, hn::Sub(py, y0)); }
    // The row at offset `row` of the rows: z, its bounds (read only when kPerSample) and ids.
    struct Row {
        double *z, *err;
        std::int32_t* ids;
    };
    static Row row_of(DepthRows rows, std::ptrdiff_t row) {
        double* z = rows.z + row;
        return {z, kPerSample ? rows.err + row : z, rows.ids + row};  // err: any valid pointer when unused
    }
    HWY_INLINE VD depth(VD a_dx, VD b_dy) const { return hn::Add(z0, hn::Add(a_dx, b_dy)); }
    // The margin of the lanes from column k of the row: err + the stored depths' bounds.
    HWY_INLINE VD margin_at(Row row, int k) const {
        if constexpr (kPerSample) return hn::Add(e, hn::LoadU(D(), row.err + k));
        return margin;
    }
    // The lanes whose gap is beyond the margin m on either side: decided, nearer or farther (not where the
    // gap is NaN).
    static HWY_INLINE MD decided(VD gap, VD m) { return hn::Gt(hn::Abs(gap), m); }
    // Writes the lanes `mask` of `depth` decided nearer than the stored samples from column k of the row
    // (the gap z' - z beyond the margin m), answers the gap.
    HWY_INLINE VD write_nearer(VD depth, VD m, MD mask, Row row, int k) const {
        const D d;
        const auto gap = hn::Sub(hn::LoadU(d, row.z + k), depth);
        const auto nearer = masked_gt(mask, gap, m);
        hn::BlendedStore(depth, nearer, d, row.z + k);
        if constexpr (kPerSample) hn::BlendedStore(e, nearer, d, row.err + k);
        hn::BlendedStore(id, id_lanes(nearer), DId(), row.ids + k);
        return gap;
    }
    // The lanes `mask` against the stored samples from column k of the row: writes the ones decided nearer,
    // answers the ones left undecided.
    HWY_INLINE MD test(VD a_dx, VD b_dy, MD mask, Row row, int k) const {
        const VD m = margin_at(row, k), gap = write_nearer(depth(a_dx, b_dy), m, mask, row, k);
        return hn::AndNot(decided(gap, m), mask);
    }
    // test() without finding the undecided lanes, for a plane whose err is finite: `closest` keeps, lane by
    // lane, what tells whether a covered sample was left undecided (any_undecided()), for undecided_after()
    // to find. With the tile's margin, the least |gap|: the plane's depths are finite (DepthPlane) and the
    // stored ones finite or +infinity, so a gap is never NaN (it may overflow to an infinity). With a bound
    // per sample, 0 where one was left undecided: |gap| - margin would be NaN where both overflow. Finding
    // the undecided lanes vector by vector had taken a tenth to a sixth of a small-triangle scene's time.
    HWY_INLINE void write_decided(VD a_dx, VD b_dy, MD mask, Row row, int k, VD& closest) const {
        const VD m = margin_at(row, k), gap = write_nearer(depth(a_dx, b_dy), m, mask, row, k);
        if constexpr (kPerSample)
            closest = hn::IfThenZeroElse(hn::AndNot(decided(gap, m), mask), closest);
        else
            closest = masked_min_abs(mask, closest, gap);
    }
    // Whether write_decided() left any covered sample undecided, `closest` starting at +infinity.
    HWY_INLINE bool any_undecided(VD closest) const {
        return !hn::AllFalse(D(), hn::Le(closest, kPerSample ? hn::Zero(D()) : margin));
    }
    // After write_decided(), the lanes `mask` it left undecided: neither decided farther (the gap within
    // the margin, or NaN) nor written, which the plane's id tells (rows held none of its samples before).
    HWY_INLINE MD undecided_after(VD a_dx, VD b_dy, MD mask, Row row, int k) const {
        const auto gap = hn::Sub(hn::LoadU(D(), row.z + k), depth(a_dx, b_dy));
        const auto written = hn::RebindMask(D(), hn::Eq(hn::PromoteTo(DI(), hn::LoadU(DId(), row.ids + k)),
                                                        hn::PromoteTo(DI(), id)));
        return hn::AndNot(hn::Or(written, decided(gap, margin_at(row, k))), mask);
    }
    VD z0, a, x0, b, y0, e, margin;  // margin: err + stored_err
    hn::Vec<DId> id;
};

// The depth test for the evaluators (All, Masks: every sample, or the wide path's spans), a row's covered
// samples one run (a span), so the row ends at the first uncovered vector past it.
template <bool kPerSample, class Evaluator>
bool DepthLoop(const Block b, Evaluator ev, const DepthPlane& p, DepthRows rows, std::uint64_t* undecided) {
    const D d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const DepthLanes<kPerSample> lanes_test(p);
    const auto ramp = hn::Iota(d, 0.0), advance = hn::Set(d, static_cast<double>(lanes));
    const auto px_end = hn::Set(d, double(b.i0 + b.width) + b.sx);  // as in CoverageLoop
    // py = j + sy, exact as px is.
    const auto down = hn::Set(d, 1.0);
    auto py = hn::Set(d, double(b.j0) + b.sy);
    std::uint64_t any = 0;
    for (int r = 0; r < b.rows; ++r, py = hn::Add(py, down)) {
        ev.start_row(r);
        const auto b_dy = lanes_test.b_dy(py);
        const auto row = DepthLanes<kPerSample>::row_of(rows, r * rows.stride);
        std::uint64_t open_bits = 0;
        bool seen = false;
        auto px = hn::Add(hn::Set(d, double(b.i0) + b.sx), ramp);
        for (int k = 0; k < b.width; k += lanes, px = hn::Add(px, advance)) {
            const auto mask = hn::And(ev.chunk(k, px), hn::Lt(px, px_end));
            if (hn::AllFalse(d, mask)) {
                if (seen) break;  // past the row's one run of covered samples
                continue;
            }
            seen = true;
            const auto open = lanes_test.test(lanes_test.a_dx(px), b_dy, mask, row, k);
            if (!hn::AllFalse(d, open)) open_bits |= mask_bits(d, open) << k;
        }
        undecided[r] = open_bits;
        any |= open_bits;
    }
    return any != 0;
}

// The integer edges of a block that fit in 32 bits, in 32-bit lanes (twice as many per vector as the
// depth test's), with all three edges in the registers: row_lanes(inside, r, k) is called for the rows r
// in order and the vectors k = 0 .. count - 1 across each, `inside` the mask of the vector's lanes (columns
// k * Lanes + l) inside the block and all three edges. A count the compiler knows unrolls the loop (a
// small triangle's rows take one or two vectors, and the loop's own instructions were as many as the
// evaluation's).
template <class Row>
HWY_INLINE void SmallEdgeLanes(const SmallEdges& edges, const Block b, int count, Row row_lanes) {
    const DI32 di;
    const int lanes32 = static_cast<int>(hn::Lanes(di));
    hn::Vec<DI32> row[3], step[3], down[3];
    for (int e = 0; e < 3; ++e) {
        row[e] = hn::Add(hn::Set(di, edges.e[e]), hn::Mul(hn::Iota(di, 0), hn::Set(di, edges.dx[e])));
        step[e] = hn::Mul(hn::Set(di, edges.dx[e]), hn::Set(di, static_cast<std::int32_t>(lanes32)));
        down[e] = hn::Set(di, edges.dy[e]);
    }
    const auto width = hn::Set(di, b.width), outside = hn::Set(di, -1);
    for (int r = 0; r < b.rows; ++r) {
        auto v0 = row[0], v1 = row[1], v2 = row[2];
        for (int k = 0; k < count; ++k) {
            // All three are >= 0 exactly when their bitwise or is > -1. Vector integer arithmetic wraps
            // around: a lane inside the block ends at its true value, which fits (SmallEdges); the lanes
            // past the block's width, which may not, are masked off.
            const auto in_block = hn::Lt(hn::Iota(di, k * lanes32), width);
            row_lanes(masked_gt(in_block, hn::Or(hn::Or(v0, v1), v2), outside), r, k);
            v0 = hn::Add(v0, step[0]);
            v1 = hn::Add(v1, step[1]);
            v2 = hn::Add(v2, step[2]);
        }
        for (int e = 0; e < 3; ++e) row[e] = hn::Add(row[e], down[e]);
    }
}

// The covered samples of each row of a block as bits (SmallEdgeLanes).
HWY_INLINE void SmallEdgeRuns(const SmallEdges& edges, const Block b, std::uint64_t* covered) {
    const DI32 di;
    const int lanes32 = static_cast<int>(hn::Lanes(di));
    for (int r = 0; r < b.rows; ++r) covered[r] = 0;
    SmallEdgeLanes(edges, b, (b.width + lanes32 - 1) / lanes32, [&](auto inside, int r, int k) {
        covered[r] |= mask_bits(di, inside) << (k * lanes32);
    });
}

// The depth test of a block in two passes, each_vector(visit) calling visit(r, k, mask, a_dx, row, b_dy)
// for its vectors (row r, from column k, the covered lanes `mask` and the plane's column terms there):
// the samples are written where decided nearer, and only a block that left some undecided (rarely one)
// is visited again to find them; a plane whose bound is infinite decides none.
template <bool kPerSample, class EachVector>
HWY_INLINE bool TwoPasses(const DepthLanes<kPerSample>& lanes_test, const DepthPlane& p, int rows,
                          EachVector each_vector, std::uint64_t* undecided) {
    const D d;
    if (p.err < std::numeric_limits<double>::infinity()) {
        auto closest = hn::Set(d, std::numeric_limits<double>::infinity());
        each_vector([&](int, int k, MD mask, VD a_dx, auto row, VD b_dy) {
            lanes_test.write_decided(a_dx, b_dy, mask, row, k, closest);
        });
        if (!lanes_test.any_undecided(closest)) return false;
    }
    std::fill_n(undecided, rows, std::uint64_t{0});
    std::uint64_t any = 0;
    each_vector([&](int r, int k, MD mask, VD a_dx, auto row, VD b_dy) {
        const std::uint64_t bits = mask_bits(d, lanes_test.undecided_after(a_dx, b_dy, mask, row, k));
        undecided[r] |= bits << k;
        any |= bits;
    });
    return any != 0;
}

// The depth test on the covered samples of each row (covered[r]), one run per row (its columns
// [first, last]), in vectors from the run's first sample. py = j + sy, stepped, and px = i + sx are exact
// (sums of integers below 2^25 and multiples of 1/16), so they are the values DepthLoop computes.
template <bool kPerSample>
HWY_INLINE bool DepthOnRuns(const Block b, const std::uint64_t* covered, const DepthPlane& p, DepthRows rows,
                            std::uint64_t* undecided) {
    const D d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const DepthLanes<kPerSample> lanes_test(p);
    // The plane's column terms a (px - x0), px = i + sx, for every column a vector from a run's sample
    // reaches: found once for all the rows.
    HWY_ALIGN double a_dx[kRowLanes + 2 * hn::MaxLanes(D())];
    const auto ramp = hn::Iota(d, 0.0);
    for (int k = 0; k < b.width + lanes; k += lanes)
        hn::Store(lanes_test.a_dx(hn::Add(hn::Set(d, double(b.i0 + k) + b.sx), ramp)), d, a_dx + k);
    const MD all = hn::FirstN(d, static_cast<std::size_t>(lanes));
    // visit(r, k, mask, a_dx, row, b_dy) for the vectors from column k of each row r's run.
    const auto each_vector = [&](auto visit) {
        double py = double(b.j0) + b.sy;
        for (int r = 0; r < b.rows; ++r, py += 1) {
            const std::uint64_t bits = covered[r];
            if (bits == 0) continue;
            const int first = std::countr_zero(bits), last = 63 - std::countl_zero(bits);
            const auto b_dy = lanes_test.b_dy(hn::Set(d, py));
            const auto row = DepthLanes<kPerSample>::row_of(rows, r * rows.stride);
            // The whole vectors first, the run's last part apart: a mask known to be full costs nothing.
            int k = first;
            for (; k + lanes <= last + 1; k += lanes) visit(r, k, all, hn::LoadU(d, a_dx + k), row, b_dy);
            if (k <= last)
                visit(r, k, hn::FirstN(d, static_cast<std::size_t>(last - k + 1)), hn::LoadU(d, a_dx + k), row, b_dy);
        }
    };
    return TwoPasses(lanes_test, p, b.rows, each_vector, undecided);
}

// DepthOnRuns for a block of at most kVectors vectors across, the covered samples straight from
// SmallEdgeLanes: every row takes all kVectors from the block's first column, its covered samples as the
// lanes' mask, whatever its run. A small triangle's rows took one vector or two by their runs, which the
// loop's branch mispredicted (8% of a small-scene render); the lanes outside the run cost less. Except on
// AVX-512, whose masks are bits, the coverage is kept as lanes, not bits: turning each vector's mask into
// bits and back took a third of the loop. px = i + sx is exact, as in DepthOnRuns.
template <int kVectors, bool kPerSample>
HWY_INLINE bool DepthOnColumns(const Block b, const SmallEdges& edges, const DepthPlane& p, DepthRows rows,
                               std::uint64_t* undecided) {
    const D d;
    const DI32 di32;
    const int lanes = static_cast<int>(hn::Lanes(d)), lanes32 = static_cast<int>(hn::Lanes(di32));
    // The edges take whole vectors of 32-bit lanes, twice a depth vector's (or as many, on one lane): at
    // most kVectors + 1 depth vectors' columns. Past the block's width a column is not covered.
    const int vectors32 = (kVectors * lanes + lanes32 - 1) / lanes32;
    const DepthLanes<kPerSample> lanes_test(p);
    VD a_dx[kVectors];  // the plane's column terms (DepthLanes)
    for (int v = 0; v < kVectors; ++v)
        a_dx[v] = lanes_test.a_dx(hn::Add(hn::Set(d, double(b.i0 + v * lanes) + b.sx), hn::Iota(d, 0.0)));
    // visit(r, k, covered, a_dx, row, b_dy) for each row r and vector from column k, in order (TwoPasses).
#if HWY_TARGET <= HWY_AVX3
    // AVX-512's masks are bits: a row's coverage goes from the edges' mask to the depth vectors' by a
    // shift of the mask register, 8 lanes (through a general register it cost 2% of a small triangle's
    // time; on AVX2 the bits' way took 8% more instructions than the lanes').
    static_assert(hn::MaxLanes(D()) == 8 && hn::MaxLanes(DI32()) == 16, "a 16-lane mask shifted by 8");
    const int per32 = lanes32 / lanes;
    const auto each_vector = [&](auto visit) {
        // py = j + sy, stepped at each row's first edge vector: exact, as in DepthOnRuns.
        auto py = hn::Set(d, double(b.j0) + b.sy);
        VD b_dy;
        SmallEdgeLanes(edges, b, vectors32, [&](auto in, int r, int k) {
            if (k == 0) {
                b_dy = lanes_test.b_dy(py);
                py = hn::Add(py, hn::Set(d, 1.0));
            }
            const auto row = DepthLanes<kPerSample>::row_of(rows, r * rows.stride);
            for (int h = 0, v = k * per32; h < per32 && v < kVectors; ++h, ++v)
                visit(r, v * lanes, MD{static_cast<__mmask8>(h == 0 ? in.raw : _kshiftri_mask16(in.raw, 8))}, a_dx[v],
                      row, b_dy);
        });
    };
#else
    // Row r's coverage from column k at inside[r * columns + k], as 0 or -1.
    const DI di;
    const hn::Rebind<std::int32_t, D> d32;  // a depth vector's lanes, 32 bits each
    const int columns = vectors32 * lanes32;
    HWY_ALIGN std::int32_t inside[kRowLanes * (kVectors + 1) * hn::MaxLanes(D())];
    SmallEdgeLanes(edges, b, vectors32, [&](auto in, int r, int k) {
        hn::Store(hn::VecFromMask(di32, in), di32, inside + r * columns + k * lanes32);
    });
    const auto each_vector = [&](auto visit) {
        auto py = hn::Set(d, double(b.j0) + b.sy);
        for (int r = 0; r < b.rows; ++r, py = hn::Add(py, hn::Set(d, 1.0))) {
            const auto b_dy = lanes_test.b_dy(py);
            const auto row = DepthLanes<kPerSample>::row_of(rows, r * rows.stride);
            for (int v = 0; v < kVectors; ++v) {
                const auto lanes32_at = hn::LoadU(d32, inside + r * columns + v * lanes);
                const auto covered = hn::RebindMask(d, hn::MaskFromVec(hn::PromoteTo(di, lanes32_at)));
                visit(r, v * lanes, covered, a_dx[v], row, b_dy);
            }
        }
    };
#endif
    return TwoPasses(lanes_test, p, b.rows, each_vector, undecided);
}

bool DepthRuns(const Block& b, const std::uint64_t* covered, const DepthPlane& p, const DepthRows& rows,
               std::uint64_t* undecided) {
    return with_stored_bounds(rows, [&](auto per_sample) {
        return DepthOnRuns<per_sample>(b, covered, p, rows, undecided);
    });
}

// The runs first, then the depth test on them: in one loop the edges' nine vectors and the depth test's
// did not fit the 16 registers of AVX2 together, and the spills cost 5-10% of the time on small triangles.
// Blocks up to four vectors across are tested by columns (DepthOnColumns), wider ones by runs.
template <bool kPerSample>
HWY_INLINE bool DepthSmallOf(const Block& b, const SmallEdges& edges, const DepthPlane& p, const DepthRows& rows,
                             std::uint64_t* undecided) {
    const int lanes = static_cast<int>(hn::Lanes(D()));
    if (b.width <= lanes) return DepthOnColumns<1, kPerSample>(b, edges, p, rows, undecided);
    if (b.width <= 2 * lanes) return DepthOnColumns<2, kPerSample>(b, edges, p, rows, undecided);
    if (b.width <= 3 * lanes) return DepthOnColumns<3, kPerSample>(b, edges, p, rows, undecided);
    if (b.width <= 4 * lanes) return DepthOnColumns<4, kPerSample>(b, edges, p, rows, undecided);
    std::uint64_t covered[kRowLanes];
    SmallEdgeRuns(edges, b, covered);
    return DepthOnRuns<kPerSample>(b, covered, p, rows, undecided);
}

bool DepthSmall(const Block& b, const SmallEdges& edges, const DepthPlane& p, const DepthRows& rows,
                std::uint64_t* undecided) {
    return with_stored_bounds(
        rows, [&](auto per_sample) { return DepthSmallOf<per_sample>(b, edges, p, rows, undecided); });
}

std::size_t DepthSmallRun(const SmallRunEntry* entries, std::size_t first, std::size_t count,
                          const DepthRows& tile, double stored_err, std::uint64_t* undecided) {
    return with_stored_bounds(tile, [&](auto per_sample) {
        for (std::size_t k = first; k < count; ++k) {
            const SmallRunEntry& t = entries[k];
            const DepthRows rows{tile.z + t.at, per_sample ? tile.err + t.at : nullptr, tile.ids + t.at, tile.stride};
            const DepthPlane p{t.z0, t.a, t.x0, t.b, t.y0, t.err, stored_err, t.id};
            if (DepthSmallOf<per_sample>(t.block, t.edges, p, rows, undecided)) return k;
        }
        return count;
    });
}

// Instantiates `loop` with the evaluator for the coverage's kind.
template <class Loop>
auto with_evaluator(const Coverage& c, Loop loop) {
    switch (c.kind) {
        case Coverage::Kind::masks: {
            Masks ev{c.masks};
            return loop(ev);
        }
        case Coverage::Kind::fixed: {
            FixedEdges ev(c);
            return loop(ev);
        }
        case Coverage::Kind::float32:  // by float_row_masks
        case Coverage::Kind::float64:
        case Coverage::Kind::all: break;
    }
    All ev;
    return loop(ev);
}

bool FloatKind(const Coverage& c) {
    return c.kind == Coverage::Kind::float32 || c.kind == Coverage::Kind::float64;
}

void CoverageBlock(const Block& b, const Coverage& c, std::uint64_t* covered) {
    if (FloatKind(c)) return float_row_masks(c, b, covered);
    with_evaluator(c, [&](auto& ev) { CoverageLoop(b, ev, covered); });
}

// Edges go through their row masks and DepthRuns, as the fixed path's own calls (depth_runs,
// depth_small) do, rather than a fused loop of their own: the integer ones walked, the float ones found by
// bisection (float_row_masks), which tests a fraction of the samples the float evaluation did (a float32
// edge took about 30 operations a vector, the depth test about 10).
bool DepthBlock(const Block& b, const Coverage& c, const DepthPlane& p, const DepthRows& rows,
                std::uint64_t* undecided) {
    if (c.kind == Coverage::Kind::fixed || FloatKind(c)) {
        std::uint64_t covered[kRowLanes];
        CoverageBlock(b, c, covered);
        return DepthRuns(b, covered, p, rows, undecided);
    }
    return with_evaluator(c, [&](auto& ev) {
        return with_stored_bounds(
            rows, [&](auto per_sample) { return DepthLoop<per_sample>(b, ev, p, rows, undecided); });
    });
}

DepthSmallKernel DepthSmallKernelOf() { return &DepthSmall; }
DepthSmallRunKernel DepthSmallRunKernelOf() { return &DepthSmallRun; }

double Farthest(const double* z, std::size_t n) {
    const D d;
    const std::size_t lanes = hn::Lanes(d);
    auto largest = hn::Set(d, -std::numeric_limits<double>::infinity());
    std::size_t k = 0;
    for (; k + lanes <= n; k += lanes) largest = hn::Max(largest, hn::LoadU(d, z + k));
    double result = hn::GetLane(hn::MaxOfLanes(d, largest));
    for (; k < n; ++k) result = std::max(result, z[k]);
    return result;
}

void FarthestSubtiles(const double* z, std::ptrdiff_t stride, int width, int rows, double* far) {
    const hn::CappedTag<double, kSubtile> d;  // a subtile's row in one vector, or in a few
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto lowest = hn::Set(d, -std::numeric_limits<double>::infinity());
    for (int x = 0; x < width; x += kSubtile) {
        const int n = std::min(kSubtile, width - x);
        auto largest = lowest;
        // A whole subtile's rows, the common case, without masking the lanes (a tenth of the refresh).
        if (n == kSubtile) {
            for (int r = 0; r < rows; ++r)
                for (int l = 0; l < n; l += lanes) largest = hn::Max(largest, hn::LoadU(d, z + r * stride + x + l));
        } else {
            for (int r = 0; r < rows; ++r)
                for (int l = 0; l < n; l += lanes)
                    largest = hn::Max(largest, hn::IfThenElse(hn::FirstN(d, static_cast<std::size_t>(n - l)),
                                                              hn::LoadU(d, z + r * stride + x + l), lowest));
        }
        far[x / kSubtile] = hn::GetLane(hn::MaxOfLanes(d, largest));
    }
}

// The first pixel column of each lane's subtile, the lanes from subtile column k of the tile whose first
// column is ti (exact: small integers).
template <class DF>
HWY_INLINE hn::Vec<DF> SubtileColumns(DF d, int k, int ti) {
    return hn::Add(hn::Mul(hn::Iota(d, double(k)), hn::Set(d, double(kSubtile))), hn::Set(d, double(ti)));
}

std::uint64_t OpenSubtiles(const SubtileTest& t, const double* far) {
    const hn::CappedTag<double, kSubtiles> d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const bool low_x = t.a >= 0, low_y = t.b >= 0;
    const auto z0 = hn::Set(d, t.z0), a = hn::Set(d, t.a), x0 = hn::Set(d, t.x0), margin = hn::Set(d, t.margin);
    const auto i0 = hn::Set(d, double(t.i0)), i1 = hn::Set(d, double(t.i1));
    const int by0 = (t.j0 - t.tj) / kSubtile, by1 = (t.j1 - t.tj) / kSubtile;
    const std::uint64_t columns = first_bits((t.i1 - t.ti) / kSubtile + 1) & ~first_bits((t.i0 - t.ti) / kSubtile);
    const std::uint64_t lane_bits = first_bits(lanes);
    std::uint64_t open = 0;
    for (int k = 0; k < kSubtiles; k += lanes) {
        // The nearest corner's x in each subtile column, within the box (exact: integers and sixteenths).
        const auto first = SubtileColumns(d, k, t.ti);
        const auto px = low_x ? hn::Add(hn::Max(first, i0), hn::Set(d, t.ox_min))
                              : hn::Add(hn::Min(hn::Add(first, hn::Set(d, double(kSubtile - 1))), i1),
                                        hn::Set(d, t.ox_max));
        const auto a_dx = hn::Mul(a, hn::Sub(px, x0));
        for (int by = by0; by <= by1; ++by) {
            const int row = t.tj + by * kSubtile;  // the band's first
            const double py = low_y ? double(std::max(t.j0, row)) + t.oy_min
                                    : double(std::min(t.j1, row + kSubtile - 1)) + t.oy_max;
            const auto nearest = hn::Add(z0, hn::Add(a_dx, hn::Set(d, t.b * (py - t.y0))));
            const auto behind = hn::Gt(hn::Sub(nearest, hn::LoadU(d, far + by * kSubtiles + k)), margin);
            open |= (~mask_bits(d, behind) & lane_bits) << (by * kSubtiles + k);
        }
    }
    std::uint64_t box = 0;
    for (int by = by0; by <= by1; ++by) box |= columns << (by * kSubtiles);
    return open & box;
}

void LowerCoveredSubtiles(const SubtileCover& t, double* far) {
    const hn::CappedTag<double, kSubtiles> d;
    const hn::RebindToSigned<decltype(d)> di;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const bool high_x = t.a >= 0, high_y = t.b >= 0;  // the farthest corner
    const auto z0 = hn::Set(d, t.z0), a = hn::Set(d, t.a), x0 = hn::Set(d, t.x0);
    const auto bx0 = hn::Set(di, t.bx0), bx1 = hn::Set(di, t.bx1);
    for (int k = t.bx0 / lanes * lanes; k <= t.bx1; k += lanes) {
        const auto bx = hn::Add(hn::Iota(di, 0), hn::Set(di, k));  // each lane's subtile column
        const auto in_box = hn::RebindMask(d, hn::Not(hn::Or(hn::Gt(bx0, bx), hn::Gt(bx, bx1))));
        // The x range of each lane's subtile's samples (exact: integers and sixteenths).
        const auto column = SubtileColumns(d, k, t.ti);
        const auto x_lo = hn::Add(column, hn::Set(d, t.ox_min));
        const auto x_hi = hn::Add(hn::Add(column, hn::Set(d, kSubtile - 1.0)), hn::Set(d, t.ox_max));
        const auto a_dx = hn::Mul(a, hn::Sub(high_x ? x_hi : x_lo, x0));
        // Integer edges: each edge's least value in each lane's subtile of the first band; integer vectors
        // wrap around, and the lanes outside the box, which may, are masked off. Float edges: the column
        // term d3 (x - ax) of each edge's double value at the corner of the subtile's samples where it is least.
        hn::Vec<decltype(di)> edge[3], down[3];
        hn::Vec<decltype(d)> column_term[3];
        for (int e = 0; e < 3; ++e) {
            column_term[e] = hn::Mul(hn::Set(d, t.d3[e]), hn::Sub(t.d3[e] >= 0 ? x_hi : x_lo, hn::Set(d, t.ax[e])));
            edge[e] = hn::Add(hn::Set(di, t.lowest[e]), hn::Mul(hn::Sub(bx, bx0), hn::Set(di, t.across[e])));
            down[e] = hn::Set(di, t.down[e]);
        }
        for (int by = t.by0; by <= t.by1; ++by) {
            const double row = t.tj + by * kSubtile;
            const double y_lo = row + t.oy_min, y_hi = (row + (kSubtile - 1)) + t.oy_max;  // exact, as x
            const auto farthest = hn::Add(z0, hn::Add(a_dx, hn::Set(d, t.b * ((high_y ? y_hi : y_lo) - t.y0))));
            auto inside = hn::FirstN(d, hn::Lanes(d));
            if (t.floating) {
                // The whole-tile test's (classify, coverage.h) on the subtile: its operations, its margin.
                for (int e = 0; e < 3; ++e) {
                    const double row_term = t.d1[e] * ((t.d1[e] >= 0 ? y_lo : y_hi) - t.ay[e]);
                    const auto lowest = hn::Sub(hn::Set(d, row_term), column_term[e]);
                    inside = hn::And(inside, hn::Gt(lowest, hn::Set(d, t.margin)));
                }
            } else {
                // All three are >= 0 exactly when their bitwise or is > -1.
                inside = hn::RebindMask(d, hn::Gt(hn::Or(hn::Or(edge[0], edge[1]), edge[2]), hn::Set(di, -1)));
                for (int e = 0; e < 3; ++e) edge[e] = hn::Add(edge[e], down[e]);
            }
            double* at = far + by * kSubtiles + k;
            const auto old = hn::LoadU(d, at);
            hn::StoreU(hn::IfThenElse(hn::And(inside, in_box), hn::Min(old, farthest), old), d, at);
        }
    }
}

void FillFar(double* z, std::size_t n) {
    const D d;
    const std::size_t lanes = hn::Lanes(d);
    const auto far = hn::Set(d, std::numeric_limits<double>::infinity());
    std::size_t k = 0;
    for (; k + lanes <= n; k += lanes) hn::StoreU(far, d, z + k);
    for (; k < n; ++k) z[k] = std::numeric_limits<double>::infinity();
}

// n values from `from` to `to`: the whole cache lines of `to` streamed, a vector of at most a line at a
// time (the vector is then aligned to its size, as Stream needs: `to`, an array's, is aligned to T), the
// rest stored one by one.
template <class T>
HWY_INLINE void StreamRow(const T* from, T* to, std::size_t n) {
    constexpr std::size_t kLine = 64, kPerLine = kLine / sizeof(T);
    const hn::CappedTag<T, kPerLine> d;
    const std::size_t lanes = hn::Lanes(d);
    const std::size_t misaligned = reinterpret_cast<std::uintptr_t>(to) % kLine;
    const std::size_t head = std::min(n, misaligned == 0 ? 0 : (kLine - misaligned) / sizeof(T));
    std::size_t k = 0;
    for (; k < head; ++k) to[k] = from[k];
    for (; k + kPerLine <= n; k += kPerLine)
        for (std::size_t v = 0; v < kPerLine; v += lanes) hn::Stream(hn::LoadU(d, from + k + v), d, to + k + v);
    for (; k < n; ++k) to[k] = from[k];
}

void CopyOut(const double* z, const std::int32_t* ids, std::ptrdiff_t stride, double* to_z, std::int32_t* to_ids,
             std::ptrdiff_t to_stride, int width, int rows) {
    for (int r = 0; r < rows; ++r) {
        StreamRow(z + r * stride, to_z + r * to_stride, static_cast<std::size_t>(width));
        StreamRow(ids + r * stride, to_ids + r * to_stride, static_cast<std::size_t>(width));
    }
    hwy::FlushStream();
}

}  // namespace rast::fast::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rast::fast::detail {

HWY_EXPORT(CoverageBlock);
HWY_EXPORT(DepthBlock);
HWY_EXPORT(DepthRuns);
HWY_EXPORT(DepthSmall);
HWY_EXPORT(DepthSmallKernelOf);
HWY_EXPORT(DepthSmallRunKernelOf);
HWY_EXPORT(Farthest);
HWY_EXPORT(FarthestSubtiles);
HWY_EXPORT(OpenSubtiles);
HWY_EXPORT(LowerCoveredSubtiles);
HWY_EXPORT(FillFar);
HWY_EXPORT(CopyOut);

void coverage_block(const Block& block, const Coverage& coverage, std::uint64_t* covered) {
    HWY_DYNAMIC_DISPATCH(CoverageBlock)(block, coverage, covered);
}

bool depth_block(const Block& block, const Coverage& coverage, const DepthPlane& plane, const DepthRows& rows,
                 std::uint64_t* undecided) {
    return HWY_DYNAMIC_DISPATCH(DepthBlock)(block, coverage, plane, rows, undecided);
}

bool depth_runs(const Block& block, const std::uint64_t* covered, const DepthPlane& plane, const DepthRows& rows,
                std::uint64_t* undecided) {
    return HWY_DYNAMIC_DISPATCH(DepthRuns)(block, covered, plane, rows, undecided);
}

bool depth_small(const Block& block, const SmallEdges& edges, const DepthPlane& plane, const DepthRows& rows,
                 std::uint64_t* undecided) {
    return HWY_DYNAMIC_DISPATCH(DepthSmall)(block, edges, plane, rows, undecided);
}

DepthSmallKernel depth_small_kernel() { return HWY_DYNAMIC_DISPATCH(DepthSmallKernelOf)(); }

DepthSmallRunKernel depth_small_run_kernel() { return HWY_DYNAMIC_DISPATCH(DepthSmallRunKernelOf)(); }

std::uint64_t open_subtiles(const SubtileTest& t, const double* far) {
    return HWY_DYNAMIC_DISPATCH(OpenSubtiles)(t, far);
}

void lower_covered_subtiles(const SubtileCover& t, double* far) {
    HWY_DYNAMIC_DISPATCH(LowerCoveredSubtiles)(t, far);
}

double farthest(const double* z, std::size_t n) {
    return HWY_DYNAMIC_DISPATCH(Farthest)(z, n);
}

void farthest_subtiles(const double* z, std::ptrdiff_t stride, int width, int rows, double* far) {
    HWY_DYNAMIC_DISPATCH(FarthestSubtiles)(z, stride, width, rows, far);
}

void fill_far(double* z, std::size_t n) { HWY_DYNAMIC_DISPATCH(FillFar)(z, n); }

void copy_out(const double* z, const std::int32_t* ids, std::ptrdiff_t stride, double* to_z, std::int32_t* to_ids,
              std::ptrdiff_t to_stride, int width, int rows) {
    HWY_DYNAMIC_DISPATCH(CopyOut)(z, ids, stride, to_z, to_ids, to_stride, width, rows);
}

}  // namespace rast::fast::detail
#endif  // HWY_ONCE
