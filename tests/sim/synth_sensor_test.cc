// The sensor models of synthetic logs: the first-order lag reads a ramp tau late and a step 63%
// after tau, exactly for inputs linear between samples; the noise is seeded and standard normal.

#include "hotlap/sim/synth_sensor.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap::sim {
namespace {

TEST(FirstOrderLagTest, RampIsReadTauLateAndStepReaches63PercentAfterTau) {
  FirstOrderLag<double> ramp(0.2);
  double y = 0.0;
  for (int k = 0; k <= 500; ++k) y = ramp.Next(0.01 * k, 3.0 * 0.01 * k);  // 3 K/s for 5 s
  EXPECT_NEAR(y, 3.0 * (5.0 - 0.2), 1e-9);  // settled: exactly s (t - tau)
  FirstOrderLag<double> step(0.5);
  step.Next(0.0, 0.0);
  step.Next(1e-9, 1.0);  // a (near) step, then hold
  for (int k = 1; k <= 50; ++k) y = step.Next(0.01 * k, 1.0);
  EXPECT_NEAR(y, 1.0 - std::exp(-0.5 / 0.5), 1e-6);
}

TEST(FirstOrderLagTest, ZeroLagReadsTheTruthAndTheFirstReadingIsSettled) {
  FirstOrderLag<double> none(0.0);
  EXPECT_EQ(none.Next(0.0, 5.0), 5.0);
  EXPECT_EQ(none.Next(0.1, 7.0), 7.0);
  FirstOrderLag<double> lag(1.0);
  EXPECT_EQ(lag.Next(3.0, 42.0), 42.0);
}

// Exact for any sample spacing: 100 Hz and 10 Hz readings of a piecewise-linear signal agree at
// the common times.
TEST(FirstOrderLagTest, ExactForAnySpacing) {
  const auto signal = [](double t) { return t < 1.0 ? 10.0 * t : 10.0 - 4.0 * (t - 1.0); };
  FirstOrderLag<double> fine(0.3), coarse(0.3);
  double yf = 0.0, yc = 0.0;
  for (int k = 0; k <= 200; ++k) yf = fine.Next(0.01 * k, signal(0.01 * k));
  for (int k = 0; k <= 20; ++k) yc = coarse.Next(0.1 * k, signal(0.1 * k));
  EXPECT_NEAR(yf, yc, 1e-12);
}

TEST(GaussianNoiseTest, SeededStandardNormal) {
  GaussianNoise a(42), b(42), c(43);
  double sum = 0.0, sum2 = 0.0;
  constexpr int kN = 200000;
  for (int i = 0; i < kN; ++i) {
    const double x = a.Next();
    EXPECT_EQ(x, b.Next());
    sum += x;
    sum2 += x * x;
  }
  EXPECT_NEAR(sum / kN, 0.0, 0.01);
  EXPECT_NEAR(sum2 / kN, 1.0, 0.01);
  EXPECT_NE(GaussianNoise(42).Next(), c.Next());
}

}  // namespace
}  // namespace hotlap::sim
