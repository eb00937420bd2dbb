// The covered run of each sample row of a triangle, walked from row to row in exact integer arithmetic:
// two divisions per edge at the start, additions after (an exact digital differential analyzer). One
// template for every integer type the paths need: 64 bits for the fixed path's blocks, 128 bits and big
// integers for the wide path (exact.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <cstddef>
#include <span>
#include <type_traits>

namespace rast::fast::detail {

// A run of covered pixels [lo, hi] in one sample row; empty when lo > hi.
struct Span {
    int lo, hi;
};

// floor(a / b) for b > 0. (No ++ or -- on Int anywhere: Boost 1.74's cpp_int ++ turns -(2^64 k + 1)
// into +(2^64 k), for k >= 1; += 1 and -= 1 are right.)
template <class Int>
Int floor_div(const Int& a, const Int& b) {
    Int q = a / b;
    if (a < 0 && q * b != a) q -= 1;
    return q;
}

// v clamped to [lo - 1, hi + 1]: one past either end already means "no pixel on this side".
template <class Int>
int clamp_to(const Int& v, int lo, int hi) {
    if (v < lo) return lo - 1;
    if (v > hi) return hi + 1;
    return static_cast<int>(v);
}

// floor(Q / d) from row to row while Q grows by `step` per row (d > 0).
template <class Int>
class RowQuotient {
public:
    RowQuotient(const Int& q, const Int& step, const Int& d)
        : d_(d), quotient_(floor_div(q, d)), remainder_(q - quotient_ * d), step_quotient_(floor_div(step, d)),
          step_remainder_(step - step_quotient_ * d) {}
    const Int& value() const { return quotient_; }
    const Int& remainder() const { return remainder_; }  // Q - value() d, in [0, d)
    void next_row() {
        quotient_ += step_quotient_;
        remainder_ += step_remainder_;
        if constexpr (std::is_arithmetic_v<Int>) {
            // No branch on the carry (a flag and a conditional move): carries come as irregularly as the
            // edge's slope makes them, and a branch would mispredict.
            const Int excess = remainder_ - d_;
            const int carry = excess >= 0;
            remainder_ = carry ? excess : remainder_;
            quotient_ += carry;
        } else if (remainder_ >= d_) {  // big integers: no temporary per row
            remainder_ -= d_;
            quotient_ += 1;  // not ++: see floor_div
        }
    }

private:
    Int d_, quotient_, remainder_;  // remainder = Q - quotient d, in [0, d)
    Int step_quotient_, step_remainder_;
};

// -1, 0 or 1 as p is negative, zero or positive.
template <class Int>
int sign_of(const Int& p) {
    return p > 0 ? 1 : p < 0 ? -1 : 0;
}

// What an edge's column bound divides by: floor(q / |p|) for p != 0; q itself (d = 1) for p = 0.
template <class Int>
Int column_divisor(const Int& p) {
    return p > 0 ? p : p < 0 ? Int(-p) : Int(1);
}

// The columns of a sample row one edge leaves covered, from f = floor(Q / d) (column_divisor): from -f on
// for p > 0, up to f for p < 0, all or none (f < 0) for p = 0; the ends clamped to [lo - 1, hi + 1], where
// one past either end already means "no pixel on this side".
struct EdgeLimit {
    int from, to;
    bool none;
};

template <class Int>
EdgeLimit edge_limit(int sign, const Int& f, int lo, int hi) {
    if (sign > 0) return {clamp_to(Int(-f), lo, hi), hi, false};
    if (sign < 0) return {lo, clamp_to(f, lo, hi), false};
    return {lo, hi, f < 0};
}

// Three edge functions along sample rows, E_k = p[k] i + q[k] at pixel column i, q[k] growing by
// step[k] from row to row; a sample is covered where all three are >= 0 (the tie rule is in q). Each
// edge covers a half-line of columns: i >= -floor(q / p) for p > 0, i <= floor(q / -p) for p < 0, all
// or none (q >= 0) for p = 0. Intermediate values stay within a few times |q|, |p| and |step|.
template <class Int>
class RowSpans {
public:
    // Columns are clamped to [lo, hi].
    RowSpans(const Int* p, const Int* q, const Int* step, int lo, int hi)
        : lo_(lo), hi_(hi), rows_{row(p[0], q[0], step[0]), row(p[1], q[1], step[1]), row(p[2], q[2], step[2])} {
        for (int k = 0; k < 3; ++k) sign_[k] = sign_of(p[k]);
    }
    // The current row's covered columns (empty: lo > hi); the next call gives the next row's.
    Span next() {
        int lo = lo_, hi = hi_;
        bool none = false;
        for (int k = 0; k < 3; ++k) {
            const EdgeLimit limit = edge_limit(sign_[k], rows_[k].value(), lo_, hi_);
            lo = std::max(lo, limit.from);
            hi = std::min(hi, limit.to);
            none = none || limit.none;
            rows_[k].next_row();
        }
        return {lo, none ? lo - 1 : hi};
    }

private:
    static RowQuotient<Int> row(const Int& p, const Int& q, const Int& step) {
        return RowQuotient<Int>(q, step, column_divisor(p));
    }
    int lo_, hi_;
    std::array<RowQuotient<Int>, 3> rows_;
    std::array<int, 3> sign_{};
};

// What a band of sample rows' spans are known to lie within: lo_max and hi_min bound the spans' lo
// from above and hi from below over all of them, lo_min and hi_max their lo from below and hi from
// above over the non-empty ones. Columns [i0, i1] are then inside every span when lo_max <= i0 and
// hi_min >= i1 (an empty span, lo > hi, cannot meet that), and outside every one when hi_max < i0 or
// lo_min > i1 (or when all are empty); anything else is left to the spans.
struct SpanBand {
    int lo_min = INT_MAX, hi_max = INT_MIN, lo_max = INT_MIN, hi_min = INT_MAX;
};

}  // namespace rast::fast::detail
