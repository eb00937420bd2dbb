// rast filters, for tests — adversarial inputs: a hill climb over the last bits of a filter's inputs
// toward the largest error its bound must cover, and exact arithmetic to measure that error. Random
// inputs stay orders of magnitude below the bounds; a bound is only shown sharp by inputs that approach
// it, and only shown needed, term by term, by inputs on which dropping the term breaks it.
#pragma once

#include <boost/multiprecision/gmp.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <random>
#include <type_traits>

namespace rast::filters::testing {

using Rational = boost::multiprecision::mpq_rational;

// Weights policies (filters/weights.h) that weaken a bound: every term halved, or one term dropped.
struct Halved {
    template <class Term>
    static constexpr double weight(Term) {
        return 0.5;
    }
};
template <auto Dropped>
struct Without {
    template <class Term>
    static constexpr double weight(Term t) {
        if constexpr (std::is_same_v<Term, decltype(Dropped)>) return t == Dropped ? 0 : 1;
        return 1;
    }
};

// How many climbs a generator makes: ci_default in CI, more in a campaign (RAST_FILTER_CLIMBS,
// scripts/filter-campaign).
inline int climbs(int ci_default) {
    const char* env = std::getenv("RAST_FILTER_CLIMBS");
    return env ? std::max(1, std::atoi(env)) : ci_default;
}

// The largest ratio(case) over the cases.
template <class Cases, class Ratio>
double worst(const Cases& cases, Ratio ratio) {
    double largest = 0;
    for (const auto& c : cases) largest = std::max(largest, ratio(c));
    return largest;
}

// error / bound, with error exact; +infinity when a non-zero error meets a zero bound.
inline double ratio(const Rational& error, double bound) {
    if (error == 0) return 0;
    if (!(bound > 0)) return std::numeric_limits<double>::infinity();
    return static_cast<double>(Rational(error / Rational(bound)));
}

// Moves x by k units in the last place (k may be negative), staying finite.
inline double nudge(double x, int k) {
    const double toward = k > 0 ? std::numeric_limits<double>::max() : -std::numeric_limits<double>::max();
    for (int n = 0; n < std::abs(k); ++n) x = std::nextafter(x, toward);
    return x;
}

// Climbs from `inputs` toward a larger score(inputs): each step moves one input by 1 to 8 units either
// way, move(x, k) (ulps of a double unless the filter's inputs are rounded to a coarser type first), and
// keeps the move unless the score drops. Returns the best score; `inputs` holds its inputs.
template <std::size_t N, class Score, class Move = double (*)(double, int)>
double climb(std::array<double, N>& inputs, Score score, std::mt19937_64& rng, int steps, Move move = nudge) {
    std::uniform_int_distribution<std::size_t> which(0, N - 1);
    std::uniform_int_distribution<int> ulps(1, 8), sign(0, 1);
    double best = score(inputs);
    for (int step = 0; step < steps; ++step) {
        const std::size_t k = which(rng);
        const double before = inputs[k];
        inputs[k] = move(before, sign(rng) ? ulps(rng) : -ulps(rng));
        const double s = score(inputs);
        if (s >= best)
            best = s;
        else
            inputs[k] = before;
    }
    return best;
}

}  // namespace rast::filters::testing
