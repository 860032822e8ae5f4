// An ensemble's statistics (abs/ensemble_stats.h): the mean, standard error and spread of known
// samples, the equivalence bound with and without its standard-error floor, and the quantile.

#include "hotlap/abs/ensemble_stats.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap::sim {
namespace {

TEST(EnsembleStatsTest, MeanStandardErrorAndSpreadOfKnownSamples) {
  const EnsembleStat s = CalcEnsembleStat({1.0, 2.0, 3.0, 6.0});
  EXPECT_EQ(s.n, 4);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  const double sd = std::sqrt((4.0 + 1.0 + 0.0 + 9.0) / 3.0);
  EXPECT_DOUBLE_EQ(s.sd, sd);
  EXPECT_DOUBLE_EQ(s.standard_error, sd / 2.0);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 6.0);
  const EnsembleStat one = CalcEnsembleStat({0.5});
  EXPECT_EQ(one.n, 1);
  EXPECT_EQ(one.sd, 0.0);
  EXPECT_EQ(CalcEnsembleStat({}).n, 0);
  // Equal members (every one 6.3498 cycles a second): no spread at all, not the mean's rounding.
  const EnsembleStat same = CalcEnsembleStat(std::vector<double>(8, 6.3498));
  EXPECT_EQ(same.sd, 0.0);
  EXPECT_EQ(same.standard_error, 0.0);
}

TEST(EnsembleStatsTest, EquivalenceBoundAddsTwoCombinedStandardErrorsWithTheirFloor) {
  EnsembleStat a, b;
  a.n = b.n = 16;
  a.mean = 0.90;
  b.mean = 0.93;
  a.standard_error = 0.006;
  b.standard_error = 0.008;
  EXPECT_NEAR(EquivalenceBound(a, b), 0.03 + 2.0 * 0.010, 1e-12);
  EXPECT_NEAR(EquivalenceBound(b, a), EquivalenceBound(a, b), 1e-15);
  // Two ensembles whose members all agree: the floor stands in for their standard errors.
  a.standard_error = b.standard_error = 0.0;
  EXPECT_NEAR(EquivalenceBound(a, b), 0.03, 1e-12);
  EXPECT_NEAR(EquivalenceBound(a, b, 0.003), 0.03 + 2.0 * std::sqrt(2.0) * 0.003, 1e-12);
  b.n = 0;
  EXPECT_EQ(EquivalenceBound(a, b), std::numeric_limits<double>::infinity());
}

TEST(EnsembleStatsTest, QuantileIsLinearBetweenOrderStatistics) {
  const std::vector<double> v = {5.0, 1.0, 4.0, 2.0, 3.0};
  EXPECT_EQ(Quantile(v, 0.0), 1.0);
  EXPECT_EQ(Quantile(v, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(Quantile(v, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(Quantile(v, 0.99), 4.96);  // rank 3.96
  EXPECT_EQ(Quantile({}, 0.5), 0.0);
}

}  // namespace
}  // namespace hotlap::sim
