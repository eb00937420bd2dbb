// rast filters — how a bound is written so that tests can break it.
//
// Every exact verdict in rast starts with a floating-point filter: a value computed in double with a
// rigorous bound on its error, trusted alone when the bound allows. A bound is a sum of terms, one per
// source of error (a rounding, an underflow, an input's own error), each derived beside its code.
// Filters take a Weights policy and multiply each term by Weights::weight(term):
// - Sound, the default and the only policy the engines use, weighs every term 1. The weight is a
//   constant expression, so the multiplication folds away and the filter costs what it did without it.
// - A test's policy weakens one term (weight 0: dropped) or the whole bound (0.5: halved) and shows that
//   the filter's soundness test then fails on adversarial inputs: every term is needed, and no bound is
//   twice what the worst input reaches. docs/filters.md lists each filter, its terms and the test that
//   fails when each is weakened.
#pragma once

namespace rast::filters {

struct Sound {
    template <class Term>
    static constexpr double weight(Term) {
        return 1;
    }
};

}  // namespace rast::filters
