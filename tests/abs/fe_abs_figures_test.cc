// The figures an FE ABS stop ensemble judges (abs/fe_abs_figures.h), on a made-up history: the
// window after the first cycle is CalcCycleWindow's (the largest slip in it is its
// max_lambda_after_first_cycle), the quantile and mean are of its rows, times are from the
// braking's start, and a stop with one cycle has no window figures.

#include "hotlap/abs/fe_abs_figures.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hotlap::sim {
namespace {

// 1 s of braking from t0 = 0.24 s on the histories' clock, rows every 1 ms; the slip a sawtooth.
FeAbsStopResult MadeUpStop(std::vector<double> cycle_starts_from_brake) {
  FeAbsStopResult r;
  const double t0 = 0.24;
  for (int k = 0; k <= 1000; ++k) {
    fe::HistoryRow row;
    row.time_s = t0 + 1e-3 * k;
    row.slip = 0.02 + 0.15 * std::fmod(1e-3 * k, 0.1) / 0.1;  // 0.02 .. 0.17 every 0.1 s
    row.rim_vx_mps = 11.0 - 5.0 * 1e-3 * k;
    r.brake.history.push_back(row);
  }
  r.brake.initial_speed_mps = 11.0;
  r.brake.final_speed_mps = 6.0;
  r.brake.distance_m = 8.5;
  for (double& c : cycle_starts_from_brake) r.cycle_starts_s.push_back(t0 + c);
  std::vector<double> time, slip;
  for (const fe::HistoryRow& row : r.brake.history) {
    time.push_back(row.time_s);
    slip.push_back(row.slip);
  }
  r.cycles = CalcCycleWindow(time, slip, r.cycle_starts_s, std::nullopt, time.back());
  return r;
}

TEST(FeAbsFiguresTest, WindowFiguresAreThoseOfTheRowsAfterTheFirstCycle) {
  const FeAbsStopResult r = MadeUpStop({0.125, 0.300, 0.500});
  const FeAbsFigures f = CalcFeAbsFigures(r, 1.0);
  EXPECT_EQ(f.cycles, 3);
  ASSERT_TRUE(f.first_release_s);
  EXPECT_NEAR(*f.first_release_s, 0.125, 1e-12);
  ASSERT_TRUE(f.slip_max && f.slip_p99 && f.slip_mean && f.fraction_below_0_135);
  EXPECT_EQ(*f.slip_max, *r.cycles.max_lambda_after_first_cycle);
  EXPECT_EQ(*f.fraction_below_0_135, *r.cycles.fraction_time_lambda_below_0_135);
  // The sawtooth spends (0.135 - 0.02) / 0.15 of each period below 0.135.
  EXPECT_NEAR(*f.fraction_below_0_135, 0.115 / 0.15, 0.01);
  EXPECT_NEAR(*f.slip_mean, 0.02 + 0.075, 0.002);
  EXPECT_GT(*f.slip_p99, 0.165);
  EXPECT_LE(*f.slip_p99, *f.slip_max);
  EXPECT_NEAR(f.mean_deceleration_mps2, 5.0, 1e-12);
  EXPECT_EQ(f.distance_m, 8.5);
  EXPECT_NEAR(f.cycles_per_s, 3.0 / (1.0 - 0.125), 1e-9);
  EXPECT_EQ(ListFeAbsFigures(f).size(), 8u);
}

TEST(FeAbsFiguresTest, OneCycleHasNoWindow) {
  const FeAbsFigures f = CalcFeAbsFigures(MadeUpStop({0.2}), 1.0);
  EXPECT_EQ(f.cycles, 1);
  EXPECT_TRUE(f.first_release_s);
  EXPECT_FALSE(f.fraction_below_0_135);
  EXPECT_FALSE(f.slip_p99);
  EXPECT_FALSE(f.slip_mean);
  const FeAbsFigures none = CalcFeAbsFigures(MadeUpStop({}), 1.0);
  EXPECT_FALSE(none.first_release_s);
  EXPECT_EQ(none.cycles_per_s, 0.0);
}

}  // namespace
}  // namespace hotlap::sim
