// SummarizeStint on a hand-made stint of two laps: each lap's figures, the braking zones of both
// laps, per corner the peaks over the stint and the mean wear, and the tyres' shortfalls summed.

#include "hotlap/sim/lap_summary.h"

#include <gtest/gtest.h>

#include "sim/qss_example.h"

namespace hotlap::sim {
namespace {

TEST(SummarizeStint, TakesThePeaksOverTheStintAndTheMeanWear) {
  const StintSummary s = SummarizeStint(testing::MakeExampleQssResult(2));
  ASSERT_EQ(s.laps.size(), 2u);
  EXPECT_DOUBLE_EQ(s.laps[1].lap_time_s, 2.4);
  EXPECT_EQ(s.laps[1].top_speed, 51.0);
  ASSERT_EQ(s.braking_zones.size(), 2u);
  EXPECT_EQ(s.braking_zones[1].lap, 2);
  EXPECT_EQ(s.braking_zones[1].start_m, 25.0);
  EXPECT_EQ(s.braking_zones[1].end_m, 50.0);
  EXPECT_EQ(s.braking_zones[1].peak_decel, 20.0);
  // The second lap is 10 K hotter; the rear right 5 K more.
  EXPECT_DOUBLE_EQ(s.corners[0].peak_tread_temp, CelsiusToKelvin(80.0) + 12.0);
  EXPECT_DOUBLE_EQ(s.corners[3].peak_disc_temp, CelsiusToKelvin(80.0) + 415.0);
  EXPECT_DOUBLE_EQ(s.corners[3].peak_calliper_temp, CelsiusToKelvin(80.0) + 66.0);
  EXPECT_NEAR(s.corners[2].wear_per_lap_mm, 0.01, 1e-12);
  EXPECT_NEAR(s.corners[2].wear_total_mm, 0.02, 1e-12);
  EXPECT_EQ(s.slip_points_not_reached, 1);
  EXPECT_EQ(s.max_force_deficit, 100.0);
}

}  // namespace
}  // namespace hotlap::sim
