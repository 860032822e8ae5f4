// Min/max decimation keeps the ends, every peak and trough, and gaps.

#include "hotlap/report/decimate.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap::report {
namespace {

// A seeded random walk, like a logged temperature.
std::vector<double> RandomWalk(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> step(0.0, 0.1);
  std::vector<double> v(n);
  double x = 80.0;
  for (double& value : v) value = x += step(rng);
  return v;
}

void ExpectStrictlyIncreasingWithin(const std::vector<size_t>& kept, size_t n) {
  for (size_t i = 1; i < kept.size(); ++i) ASSERT_LT(kept[i - 1], kept[i]) << i;
  ASSERT_LT(kept.back(), n);
}

TEST(MinMaxDecimationTest, ShortSeriesAreKeptWhole) {
  const std::vector<double> v = RandomWalk(1451, 1);
  const std::vector<size_t> kept = MinMaxDecimationIndices(v, 2000);
  ASSERT_EQ(kept.size(), v.size());
  for (size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(kept[i], i);
  EXPECT_TRUE(MinMaxDecimationIndices(std::vector<double>{}, 2000).empty());
}

TEST(MinMaxDecimationTest, KeepsEndpointsExtremesAndSpikes) {
  std::vector<double> v = RandomWalk(90001, 2);  // 30 laps at 100 Hz of a 30 s lap
  v[12345] = 500.0;                              // a one-sample spike up ...
  v[67890] = -500.0;                             // ... and one down
  const std::vector<size_t> kept = MinMaxDecimationIndices(v, 2000);
  EXPECT_LE(kept.size(), 2000u);
  EXPECT_GE(kept.size(), 1990u);  // the budget is used
  ExpectStrictlyIncreasingWithin(kept, v.size());
  EXPECT_EQ(kept.front(), 0u);
  EXPECT_EQ(kept.back(), v.size() - 1);
  EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), size_t{12345}));
  EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), size_t{67890}));

  // Every bucket's extremes survive: the kept values reach the same min and max as the original
  // over any stretch of 1000 samples (about 11 buckets), give or take one bucket (90 samples) at
  // the edges.
  const std::vector<double> picked = PickIndices(v, kept);
  for (size_t start = 1000; start + 2000 < v.size(); start += 7919) {
    const auto begin = v.begin() + start, end = begin + 1000;
    const double hi = *std::max_element(begin, end), lo = *std::min_element(begin, end);
    double kept_hi = -INFINITY, kept_lo = INFINITY;
    for (size_t k = 0; k < kept.size(); ++k) {
      if (kept[k] + 100 >= start && kept[k] < start + 1100) {
        kept_hi = std::max(kept_hi, picked[k]);
        kept_lo = std::min(kept_lo, picked[k]);
      }
    }
    EXPECT_GE(kept_hi, hi) << start;
    EXPECT_LE(kept_lo, lo) << start;
  }
}

TEST(MinMaxDecimationTest, KeepsGapsAsGaps) {
  std::vector<double> v = RandomWalk(50000, 3);
  for (size_t i = 20000; i < 20100; ++i) v[i] = NAN;
  const std::vector<size_t> kept = MinMaxDecimationIndices(v, 1000);
  EXPECT_LE(kept.size(), 1000u);
  EXPECT_GE(kept.size(), 990u);  // only the buckets with part of the gap keep a third point
  ExpectStrictlyIncreasingWithin(kept, v.size());
  const auto gaps =
      std::count_if(kept.begin(), kept.end(), [&](size_t i) { return std::isnan(v[i]); });
  EXPECT_GE(gaps, 1);
  EXPECT_LE(gaps, 5);  // one per bucket that holds part of the gap
}

TEST(MinMaxDecimationTest, AllGapsStayWithinBudget) {
  const std::vector<double> v(10000, NAN);
  const std::vector<size_t> kept = MinMaxDecimationIndices(v, 100);
  EXPECT_LE(kept.size(), 100u);
  EXPECT_GE(kept.size(), 20u);
  ExpectStrictlyIncreasingWithin(kept, v.size());
}

TEST(MinMaxDecimationTest, RejectsTinyBudgets) {
  EXPECT_THROW(MinMaxDecimationIndices(RandomWalk(10, 4), 4), std::invalid_argument);
  EXPECT_EQ(MinMaxDecimationIndices(RandomWalk(100, 4), 5).size(), 4u);  // ends + one bucket
}

}  // namespace
}  // namespace hotlap::report
