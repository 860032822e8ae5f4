// Median: odd and even counts (unsorted, with ties), one value, and NaN for an empty sample.

#include "hotlap/common/median.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hotlap {
namespace {

TEST(Median, MiddleValueOfAnOddCount) {
  EXPECT_EQ(Median({5.0, -1.0, 3.0, 9.0, 3.5}), 3.5);
  EXPECT_EQ(Median({2.0, 2.0, 7.0}), 2.0);
  EXPECT_EQ(Median({4.25}), 4.25);
}

TEST(Median, MeanOfTheTwoMiddleValuesOfAnEvenCount) {
  EXPECT_EQ(Median({10.0, 1.0, 4.0, 3.0}), 3.5);
  EXPECT_EQ(Median({6.0, 6.0, 1.0, 8.0, 6.0, 0.0}), 6.0);
  EXPECT_EQ(Median({-2.0, 1.0}), -0.5);
}

TEST(Median, EmptySampleIsNaN) { EXPECT_TRUE(std::isnan(Median({}))); }

}  // namespace
}  // namespace hotlap
