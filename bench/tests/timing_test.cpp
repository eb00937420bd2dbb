#include "timing.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace rast::bench {
namespace {

TEST(Spread, MedianMinMaxOfAnOddCount) {
    const Spread s = spread({3, 1, 2});
    EXPECT_EQ(s.median, 2);
    EXPECT_EQ(s.min, 1);
    EXPECT_EQ(s.max, 3);
    EXPECT_EQ(s.runs, 3u);
}

TEST(Spread, MedianOfAnEvenCountIsTheMiddlePairsMean) { EXPECT_EQ(spread({4, 1, 3, 2}).median, 2.5); }

TEST(Spread, RejectsNoRuns) { EXPECT_THROW(spread({}), std::invalid_argument); }

}  // namespace
}  // namespace rast::bench
