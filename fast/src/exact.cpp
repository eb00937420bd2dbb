// Exact arithmetic on doubles: every finite double is a dyadic rational m · 2^e, so cpp_int mantissas
// hold any coordinate, product and sum here without rounding (and without the gcds of cpp_rational).
#include "exact.h"

#include <rast/filters/orientation.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace rast::fast::detail {
namespace {

using boost::multiprecision::cpp_int;

// A dyadic rational m · 2^e. Every double is one, and sums and products of them stay exact in integer
// arithmetic alone: no gcd per operation, unlike cpp_rational.
struct Dyadic {
    cpp_int m;
    int e = 0;
};

Dyadic dyadic(double x) {
    if (x == 0) return {};
    int exponent = 0;
    const double fraction = std::frexp(x, &exponent);
    return {cpp_int(static_cast<long long>(std::ldexp(fraction, 53))), exponent - 53};
}

Dyadic operator*(const Dyadic& a, const Dyadic& b) { return {a.m * b.m, a.e + b.e}; }

Dyadic operator-(const Dyadic& a) { return {-a.m, a.e}; }

Dyadic operator+(const Dyadic& a, const Dyadic& b) {
    if (a.m.is_zero()) return b;
    if (b.m.is_zero()) return a;
    const int e = std::min(a.e, b.e);
    return {(a.m << static_cast<unsigned>(a.e - e)) + (b.m << static_cast<unsigned>(b.e - e)), e};
}

Dyadic operator-(const Dyadic& a, const Dyadic& b) { return a + -b; }

// (b - a) x (c - a), exactly.
Dyadic cross(const Vertex& a, const Vertex& b, const Vertex& c) {
    const Dyadic ax = dyadic(a.x), ay = dyadic(a.y);
    return (dyadic(b.x) - ax) * (dyadic(c.y) - ay) - (dyadic(b.y) - ay) * (dyadic(c.x) - ax);
}

// x a + y b + c.
struct Linear {
    Dyadic a, b, c;

    Dyadic at(double x, double y) const { return a * dyadic(x) + b * dyadic(y) + c; }
};

Linear operator*(const Linear& l, const Dyadic& k) { return {l.a * k, l.b * k, l.c * k}; }

Linear operator-(const Linear& l, const Linear& m) { return {l.a - m.a, l.b - m.b, l.c - m.c}; }

// A triangle's plane, depth(p) = numerator(p) / area with area > 0: the barycentric combination of the
// corner depths, the sum over corners k of z_k E_k(p) / area, E_k the edge function of the edge
// opposite corner k, collected by monomial.
struct Plane {
    Linear numerator;
    Dyadic area;
};

Plane plane_of(const Corners& t) {
    Linear n;
    for (int k = 0; k < 3; ++k) {
        const Vertex& a = t[(k + 1) % 3];
        const Vertex& b = t[(k + 2) % 3];
        const Dyadic ax = dyadic(a.x), ay = dyadic(a.y), bx = dyadic(b.x), by = dyadic(b.y), z = dyadic(t[k].z);
        // (b - a) x (p - a) = (ay - by) px + (bx - ax) py + (ax by - ay bx)
        n.a = n.a + z * (ay - by);
        n.b = n.b + z * (bx - ax);
        n.c = n.c + z * (ax * by - ay * bx);
    }
    const Dyadic area = cross(t[0], t[1], t[2]);
    if (area.m.sign() < 0) return {{-n.a, -n.b, -n.c}, -area};
    return {n, area};
}

// n / d rounded to the nearest double (ties to even), d > 0, by one integer division: no gcd of the
// thousands of bits a depth plane spans.
double quotient(const Dyadic& n, const Dyadic& d) {
    if (n.m.is_zero()) return 0;
    const cpp_int magnitude = abs(n.m);
    // q = floor(|n.m| 2^k / d.m) has 56 or 57 bits: three or more below a double's 53, for rounding.
    const int k = 56 + static_cast<int>(msb(d.m)) - static_cast<int>(msb(magnitude));
    cpp_int q, r;
    divide_qr(k >= 0 ? cpp_int(magnitude << static_cast<unsigned>(k)) : cpp_int(magnitude >> static_cast<unsigned>(-k)),
              d.m, q, r);
    // Bits shifted out (k < 0) and the remainder are both below q's last bit: only whether any is set matters.
    const bool sticky = !r.is_zero() || (k < 0 && lsb(magnitude) < static_cast<unsigned>(-k));
    auto bits = static_cast<std::uint64_t>(q);
    const int exponent = n.e - d.e - k;  // |n / d| = (q + a fraction) 2^exponent
    double result = 0;
    if (static_cast<int>(msb(q)) + exponent >= -1022) {
        // Normal or overflowing: the conversion rounds once, with sticky as the last bit, and the scaling is
        // exact, or overflows to infinity exactly where the rounded value does.
        result = std::ldexp(static_cast<double>(bits | std::uint64_t{sticky}), exponent);
    } else {
        // Subnormal: round to a multiple of 2^-1074 here; the conversion and scaling are then exact.
        const int drop = std::min(-1074 - exponent, 63);
        const std::uint64_t half = std::uint64_t{1} << (drop - 1), rest = bits & ((half << 1) - 1);
        bits >>= drop;
        if (rest > half || (rest == half && (sticky || (bits & 1)))) ++bits;
        result = std::ldexp(static_cast<double>(bits), -1074);
    }
    return n.m.sign() < 0 ? -result : result;
}

// x · 2^bits as an integer; x is a multiple of 2^-bits.
cpp_int scaled(double x, int bits) {
    const Dyadic d = dyadic(x);
    const int shift = d.e + bits;
    if (shift >= 0) return d.m << static_cast<unsigned>(shift);
    return d.m / (cpp_int(1) << static_cast<unsigned>(-shift));  // exact: the low bits are zero on the grid
}

// Edge a -> b in fixed units: E(X, Y) = A X + B Y + C, A = ay - by, B = bx - ax, the tie rule in C.
template <class Int>
struct Edge {
    Int a, b, c;
};

// The edges of v in integers of type Int; scale(x) is x · 2^bits as an Int.
template <class Int, class Scale>
std::array<Edge<Int>, 3> edges_of(Scale scale, const Corners& v, const std::array<bool, 3>& inclusive) {
    std::array<Edge<Int>, 3> edges;
    for (int k = 0; k < 3; ++k) {
        const Vertex& p = v[k];
        const Vertex& q = v[(k + 1) % 3];
        const Int ax = scale(p.x), ay = scale(p.y);
        Edge<Int>& e = edges[k];
        e.a = ay - scale(q.y);
        e.b = scale(q.x) - ax;
        // The tie rule as an integer bias: a non-inclusive edge needs E >= 1.
        e.c = -(e.a * ax + e.b * ay) - (inclusive[k] ? 0 : 1);
    }
    return edges;
}

// The edges along the sample row of pixel row j and sample offset o: along it X = i·2^bits + SX, so E
// is P·i + Q with P = A·2^bits, and from one sample row to the next Q grows by B·2^bits (RowSpans'
// p, q and step).
template <class Int>
struct RowLines {
    std::array<Int, 3> p, q, step;
};

template <class Int, class Scale>
RowLines<Int> row_lines(const std::array<Edge<Int>, 3>& edges, Scale scale, int bits, SamplePoint o, int j) {
    const Int unit = Int(1) << bits;
    const Int sx = scale(o.x);
    const Int y = Int(j) * unit + scale(o.y);
    RowLines<Int> lines;
    for (int k = 0; k < 3; ++k) {
        const Edge<Int>& e = edges[k];
        lines.p[k] = e.a * unit;
        lines.q[k] = e.a * sx + e.b * y + e.c;
        lines.step[k] = e.b * unit;
    }
    return lines;
}

// The covered spans, walked row by row.
template <class Int, class Scale>
void solve_spans(Scale scale, const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                 std::span<const SamplePoint> offsets, int i_lo, int i_hi, int j_lo, int j_hi, std::span<Span> spans) {
    const std::array<Edge<Int>, 3> edges = edges_of<Int>(scale, v, inclusive);
    const std::size_t samples = offsets.size();
    for (std::size_t s = 0; s < samples; ++s) {
        const RowLines<Int> lines = row_lines(edges, scale, bits, offsets[s], j_lo);
        RowSpans<Int> walk(lines.p.data(), lines.q.data(), lines.step.data(), i_lo, i_hi);
        for (int j = j_lo; j <= j_hi; ++j) spans[static_cast<std::size_t>(j - j_lo) * samples + s] = walk.next();
    }
}

// The bands, from each band's first and last rows alone: along the rows an edge's column bound,
// floor(Q / d) with Q linear in the row, is monotone, so its extremes over the band are at its ends
// (edge_limit says what each bound means).
template <class Int, class Scale>
std::vector<SpanBand> solve_bands(Scale scale, const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                                  std::span<const SamplePoint> offsets, int i_lo, int i_hi, int j_lo, int j_hi,
                                  int rows) {
    const std::array<Edge<Int>, 3> edges = edges_of<Int>(scale, v, inclusive);
    std::vector<SpanBand> bands;
    for (int first = j_lo; first <= j_hi;) {
        const int last = std::min(j_hi, (first / rows + 1) * rows - 1);
        SpanBand band;
        for (const SamplePoint& o : offsets) {
            const RowLines<Int> top = row_lines(edges, scale, bits, o, first);
            const RowLines<Int> bottom = row_lines(edges, scale, bits, o, last);
            // Over the band's rows: lo(j) between lo_least and lo_most, hi(j) between hi_least and
            // hi_most; some rows, or all, may be empty by an edge along the rows.
            int lo_least = i_lo, lo_most = i_lo, hi_least = i_hi, hi_most = i_hi;
            bool some_empty = false, all_empty = false;
            for (int k = 0; k < 3; ++k) {
                const Int& p = top.p[k];
                const Int d = column_divisor(p);
                const EdgeLimit a = edge_limit(sign_of(p), floor_div(top.q[k], d), i_lo, i_hi);
                const EdgeLimit b = edge_limit(sign_of(p), floor_div(bottom.q[k], d), i_lo, i_hi);
                lo_least = std::max(lo_least, std::min(a.from, b.from));
                lo_most = std::max(lo_most, std::max(a.from, b.from));
                hi_least = std::min(hi_least, std::min(a.to, b.to));
                hi_most = std::min(hi_most, std::max(a.to, b.to));
                some_empty = some_empty || a.none || b.none;
                all_empty = all_empty || (a.none && b.none);
            }
            // Each row's lo is at least lo_least and its hi at most hi_most: beyond each other, no row
            // has a sample.
            all_empty = all_empty || lo_least > hi_most;
            band.lo_max = std::max(band.lo_max, lo_most);
            band.hi_min = std::min(band.hi_min, some_empty ? INT_MIN : hi_least);
            if (!all_empty) {
                band.lo_min = std::min(band.lo_min, lo_least);
                band.hi_max = std::max(band.hi_max, hi_most);
            }
        }
        bands.push_back(band);
        first = last + 1;
    }
    return bands;
}

// Calls solve(scale) with the narrowest integers that hold every edge function of v exactly: fixed
// coordinates within 2^60 (sample positions, below 2^(24 + bits), are) keep A and B below 2^61, C below
// 2^122 and Q below 2^124, so 128-bit integers do, at a small fraction of big-integer cost.
bool fits_128(const Corners& v, int bits) {
    const double limit = std::ldexp(1.0, 60 - bits);
    return std::all_of(v.begin(), v.end(), [limit](const Vertex& p) {
        return std::abs(p.x) <= limit && std::abs(p.y) <= limit;
    });
}

// x · 2^bits as an Int128, for x within 2^(60 - bits): a double within 2^60 holding an integer converts
// exactly.
auto scale_128(int bits) {
    return [bits](double x) { return Int128(static_cast<std::int64_t>(std::ldexp(x, bits))); };
}

template <class Solve>
void with_integers(const Corners& v, int bits, Solve solve) {
    if (fits_128(v, bits)) solve(scale_128(bits));
    else solve([bits](double x) { return scaled(x, bits); });
}

}  // namespace

int orientation(const Corners& v) {
    const int sign = filters::orientation(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y).certain_sign();
    return sign != 0 ? sign : cross(v[0], v[1], v[2]).m.sign();
}

struct ExactPlanes::Cache {
    // Node-based maps: a reference survives later inserts.
    std::unordered_map<std::int64_t, Plane> planes;
    // Per ordered pair (t, u) of ids: depth_t - depth_u times area_t area_u > 0, linear in p, so that
    // a sample costs two small products and two sums.
    std::unordered_map<std::uint64_t, Linear> differences;

    const Plane& plane(std::int64_t id, const Corners& t) {
        const auto [at, inserted] = planes.try_emplace(id);
        if (inserted) at->second = plane_of(t);
        return at->second;
    }
};

ExactPlanes::ExactPlanes() = default;
ExactPlanes::ExactPlanes(ExactPlanes&&) noexcept = default;
ExactPlanes& ExactPlanes::operator=(ExactPlanes&&) noexcept = default;
ExactPlanes::~ExactPlanes() = default;

int ExactPlanes::compare(std::int64_t t_id, const Corners& t, std::int64_t u_id, const Corners& u, double x,
                         double y) {
    // A triangle with three equal depths has that depth everywhere: two such compare as those depths,
    // without planes. A flat 2D scene ties at every overlap, and building the planes of every pair
    // made 2 * 10^5 tiny triangles at z = 0 take 9x the time they take at random depths.
    const auto flat = [](const Corners& c) { return c[0].z == c[1].z && c[1].z == c[2].z; };
    if (flat(t) && flat(u)) return (t[0].z > u[0].z) - (t[0].z < u[0].z);
    if (!cache_) cache_ = std::make_unique<Cache>();
    // Ids are below 2^31 (render checks): the pair packs into one key.
    const std::uint64_t key = static_cast<std::uint64_t>(t_id) << 32 | static_cast<std::uint64_t>(u_id);
    auto found = cache_->differences.find(key);
    if (found == cache_->differences.end()) {
        const Plane& p = cache_->plane(t_id, t);
        const Plane& q = cache_->plane(u_id, u);
        found = cache_->differences.emplace(key, p.numerator * q.area - q.numerator * p.area).first;
    }
    return found->second.at(x, y).m.sign();
}

namespace {

// A depth as a fraction num / den, den > 0.
struct Fraction {
    Dyadic num, den;
};

// The segment's nearest point to c has the parameter n / d along it, clamped to [0, 1], where
// n = (c - a) . (b - a) and d = |b - a|^2; its depth is z_a + (n / d)(z_b - z_a) = (z_a d + n (z_b - z_a)) / d.
Fraction segment_depth(const Segment& s, double cx, double cy) {
    const Vertex &a = s.v[0], &b = s.v[1];
    const Dyadic one = dyadic(1), ax = dyadic(a.x), ay = dyadic(a.y);
    const Dyadic dx = dyadic(b.x) - ax, dy = dyadic(b.y) - ay;
    const Dyadic d = dx * dx + dy * dy;
    const Dyadic n = (dyadic(cx) - ax) * dx + (dyadic(cy) - ay) * dy;
    if (d.m.is_zero() || n.m.sign() <= 0) return {dyadic(a.z), one};
    if ((n - d).m.sign() >= 0) return {dyadic(b.z), one};
    return {dyadic(a.z) * d + n * (dyadic(b.z) - dyadic(a.z)), d};
}

Fraction depth_of(const DepthAt& a) {
    if (a.segment) return segment_depth(*a.segment, a.x, a.y);
    const Plane p = plane_of(*a.triangle);
    return {p.numerator.at(a.x, a.y), p.area};
}

}  // namespace

int compare(const DepthAt& a, const DepthAt& b) {
    const Fraction p = depth_of(a), q = depth_of(b);
    return (p.num * q.den - q.num * p.den).m.sign();
}

double nearest(const DepthAt& a) {
    const Fraction p = depth_of(a);
    return quotient(p.num, p.den);
}

double ExactPlanes::depth(std::int64_t id, const Corners& t, double x, double y) {
    if (!cache_) cache_ = std::make_unique<Cache>();
    const Plane& p = cache_->plane(id, t);
    return quotient(p.numerator.at(x, y), p.area);
}

void wide_spans(const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                std::span<const SamplePoint> offsets, int i_lo, int i_hi, int j_lo, int j_hi,
                std::span<Span> spans) {
    with_integers(v, bits, [&](auto scale) {
        using Int = decltype(scale(0.0));
        solve_spans<Int>(scale, v, bits, inclusive, offsets, i_lo, i_hi, j_lo, j_hi, spans);
    });
}

std::optional<std::array<WideEdge, 3>> wide_edges(const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                                                  std::span<const std::int64_t> sx, std::span<const std::int64_t> sy) {
    if (!fits_128(v, bits)) return std::nullopt;
    const Int128 limit = kWideStep;
    std::array<WideEdge, 3> out;
    const std::array<Edge<Int128>, 3> edges = edges_of<Int128>(scale_128(bits), v, inclusive);
    for (std::size_t k = 0; k < 3; ++k) {
        const Edge<Int128>& e = edges[k];
        if (!(-limit < e.a && e.a < limit && -limit < e.b && e.b < limit)) return std::nullopt;
        WideEdge& f = out[k];
        f = {static_cast<std::int64_t>(e.a), static_cast<std::int64_t>(e.b), e.c, 0, 0};
        for (std::size_t s = 0; s < sx.size(); ++s) {
            const Int128 term = offset_term(f, bits, sx[s], sy[s]);
            f.least = s == 0 ? term : std::min(f.least, term);
            f.greatest = s == 0 ? term : std::max(f.greatest, term);
        }
    }
    return out;
}

std::vector<SpanBand> wide_bands(const Corners& v, int bits, const std::array<bool, 3>& inclusive,
                                 std::span<const SamplePoint> offsets, int i_lo, int i_hi, int j_lo, int j_hi,
                                 int rows) {
    std::vector<SpanBand> bands;
    with_integers(v, bits, [&](auto scale) {
        using Int = decltype(scale(0.0));
        bands = solve_bands<Int>(scale, v, bits, inclusive, offsets, i_lo, i_hi, j_lo, j_hi, rows);
    });
    return bands;
}

}  // namespace rast::fast::detail
