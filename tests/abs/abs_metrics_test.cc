// The figures of an ABS run, on hand-made histories: the time-weighted slip fraction, the
// window after the first cycle, cycles per second, lock detection above the exit speed and the
// energy balance.

#include "hotlap/abs/abs_metrics.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace {

using hotlap::sim::AbsRunResult;

TEST(AbsMetricsTest, FractionBelowInterpolatesBetweenSamples) {
  const std::vector<double> t = {0.0, 1.0, 2.0, 3.0};
  const std::vector<double> v = {0.0, 0.2, 0.2, 0.0};
  // Below 0.1 on [0, 0.5] and [2.5, 3]: 1 s of 3.
  EXPECT_NEAR(hotlap::sim::FractionOfTimeBelow(t, v, 0.1, 0.0, 3.0), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(hotlap::sim::FractionOfTimeBelow(t, v, 0.1, 0.25, 0.75), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(hotlap::sim::FractionOfTimeBelow(t, v, 0.3, 0.0, 3.0), 1.0);
  EXPECT_DOUBLE_EQ(hotlap::sim::FractionOfTimeBelow(t, v, 0.1, 1.0, 1.0), 1.0);  // empty
}

// The window after the first cycle alone (as the FE tyre's ABS stop uses it): from the second
// cycle's start to the exit or the end, its edges interpolated; undefined with fewer than two
// cycles or no time left after the second start.
TEST(AbsMetricsTest, CycleWindowFromTheSecondStartToTheExitOrTheEnd) {
  using hotlap::sim::CalcCycleWindow;
  const std::vector<double> t = {0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> v = {0.0, 0.3, 0.1, 0.1, 0.2};
  // Starts at 0.5 and 1.5 s, no exit, end 4 s: window [1.5, 4]. Lambda 0.2 at 1.5 s falling to
  // 0.1 at 2, below 0.135 from 1.825 s to 3.35 s (rising 0.1 -> 0.2 over [3, 4]): 1.525 s of 2.5.
  hotlap::sim::CycleWindow w = CalcCycleWindow(t, v, {0.5, 1.5}, std::nullopt, 4.0);
  EXPECT_EQ(w.cycles, 2);
  EXPECT_NEAR(w.cycles_per_s, 2.0 / 3.5, 1e-12);
  EXPECT_DOUBLE_EQ(*w.first_cycle_start_s, 0.5);
  EXPECT_DOUBLE_EQ(*w.second_cycle_start_s, 1.5);
  EXPECT_DOUBLE_EQ(*w.max_lambda_after_first_cycle,
                   0.1);  // the samples at 2 and 3 s (4 s is the end)
  EXPECT_NEAR(*w.fraction_time_lambda_below_0_135, 1.525 / 2.5, 1e-12);
  // An exit at 3 s closes the window there: [1.5, 3], below from 1.825 s: 1.175 s of 1.5.
  w = CalcCycleWindow(t, v, {0.5, 1.5}, 3.0, 4.0);
  EXPECT_NEAR(w.cycles_per_s, 2.0 / 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(*w.max_lambda_after_first_cycle, 0.1);
  EXPECT_NEAR(*w.fraction_time_lambda_below_0_135, 1.175 / 1.5, 1e-12);
  // One cycle: no window. A second start at the very end: no time and no sample in it.
  w = CalcCycleWindow(t, v, {0.5}, std::nullopt, 4.0);
  EXPECT_FALSE(w.second_cycle_start_s || w.max_lambda_after_first_cycle ||
               w.fraction_time_lambda_below_0_135);
  w = CalcCycleWindow(t, v, {0.5, 4.0}, std::nullopt, 4.0);
  EXPECT_TRUE(w.second_cycle_start_s.has_value());
  EXPECT_FALSE(w.max_lambda_after_first_cycle || w.fraction_time_lambda_below_0_135);
  w = CalcCycleWindow(t, v, {}, std::nullopt, 4.0);
  EXPECT_EQ(w.cycles, 0);
  EXPECT_EQ(w.cycles_per_s, 0.0);
}

// A made-up run: lambda 0.2 on [1, 1.5), 0.05 elsewhere; cycles at 0.5, 1.0 and 1.5 s; the ABS
// exits at 2 s below the exit speed, where the wheel locks.
AbsRunResult MadeUpRun(const hotlap::sim::AbsConfig& c) {
  AbsRunResult r;
  auto& h = r.history;
  for (int i = 0; i <= 300; ++i) {
    const double t = i / 100.0;
    h.time.push_back(t);
    h.speed.push_back(t < 2.0 ? 10.0 - 3.0 * t : 1.0);
    h.lambda.push_back(t >= 2.0 ? 1.0 : (t >= 1.0 && t < 1.5 ? 0.2 : 0.05));
    h.locked.push_back(t >= 2.0 ? 1 : 0);
    h.disc_temp.push_back(300.0 + t);
    h.calliper_temp.push_back(295.0);
  }
  r.cycle_starts_s = {0.5, 1.0, 1.5};
  r.abs_exit_s = 2.0;
  r.end_time_s = 3.0;
  r.initial.speed = 10.0;
  r.final.speed = 1.0;
  r.final.distance = 20.0;
  r.final.brake_energy = 0.6 * (hotlap::sim::CalcAbsKineticEnergy(c.plant.wheel, r.initial) -
                                hotlap::sim::CalcAbsKineticEnergy(c.plant.wheel, r.final));
  r.final.slip_energy = 0.4 * (hotlap::sim::CalcAbsKineticEnergy(c.plant.wheel, r.initial) -
                               hotlap::sim::CalcAbsKineticEnergy(c.plant.wheel, r.final));
  r.final_brake = {303.0, 295.0};
  return r;
}

TEST(AbsMetricsTest, WindowsCyclesLockAndEnergy) {
  const auto c = hotlap::sim::LoadAbsConfig(hotlap::test::SourcePath("data/abs/paper.yaml"));
  const auto m = hotlap::sim::CalcAbsMetrics(c, MadeUpRun(c));
  EXPECT_FALSE(m.stopped);
  EXPECT_FALSE(m.stopping_distance_m.has_value());
  EXPECT_EQ(m.cycles, 3);
  EXPECT_DOUBLE_EQ(m.cycles_per_s, 3 / 1.5);  // first cycle (0.5 s) to the exit (2 s)
  EXPECT_DOUBLE_EQ(*m.second_cycle_start_s, 1.0);
  EXPECT_DOUBLE_EQ(*m.max_lambda_after_first_cycle, 0.2);
  // From 1 s to 2 s: 0.2 until 1.49 s, the ramp to 0.05 at 1.5 s, 0.05 until 1.99 s, the ramp
  // to 1.0 at 2 s (linear between samples).
  const double below = 0.01 * (1.0 - (0.2 - 0.135) / 0.15) + 0.49 + 0.01 * (0.085 / 0.95);
  EXPECT_NEAR(*m.fraction_time_lambda_below_0_135, below, 1e-9);
  EXPECT_FALSE(m.wheel_locked);  // the lock comes below the exit speed
  EXPECT_DOUBLE_EQ(m.max_lambda, 0.2);
  EXPECT_DOUBLE_EQ(m.peak_disc_temp_K, 303.0);
  EXPECT_NEAR(m.energy.closure_error, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.mean_deceleration_mps2, 3.0);
}

}  // namespace
