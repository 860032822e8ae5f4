// Scenario comparisons: every surface with and without ABS, and a series of stops heating the
// disc.

#include "hotlap/abs/abs_scenarios.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace {

using hotlap::sim::AbsConfig;
using hotlap::sim::AbsControl;

const AbsConfig& ScenarioConfig() {
  static const AbsConfig c =
      hotlap::sim::LoadAbsConfig(hotlap::test::SourcePath("data/abs/paper.yaml"));
  return c;
}

TEST(AbsScenariosTest, ComparesEverySurfaceWithAndWithoutAbs) {
  const auto runs = hotlap::sim::RunAbsComparison(ScenarioConfig(), ScenarioConfig().event);
  ASSERT_EQ(runs.size(), 2 * ScenarioConfig().surfaces.size());
  for (size_t i = 0; i < runs.size(); i += 2) {
    EXPECT_EQ(runs[i].surface, ScenarioConfig().surfaces[i / 2].name);
    EXPECT_EQ(runs[i].control, AbsControl::kAbs);
    EXPECT_EQ(runs[i + 1].control, AbsControl::kDriverOnly);
    ASSERT_TRUE(runs[i].metrics.stopped && runs[i + 1].metrics.stopped) << runs[i].surface;
    EXPECT_LT(*runs[i].metrics.stopping_distance_m, *runs[i + 1].metrics.stopping_distance_m)
        << runs[i].surface;
  }
}

TEST(AbsScenariosTest, ASeriesOfStopsHeatsTheDisc) {
  const auto series = hotlap::sim::RunAbsStopSeries(ScenarioConfig(), ScenarioConfig().event);
  ASSERT_EQ(series.stops.size(), static_cast<size_t>(ScenarioConfig().scenarios.stop_series_count));
  // Each stop starts hotter, so each peaks higher, toward a steady cycle.
  for (size_t k = 1; k < series.stops.size(); ++k) {
    EXPECT_GT(series.stops[k].peak_disc_temp_K, series.stops[k - 1].peak_disc_temp_K) << k;
    EXPECT_NEAR(
        series.stop_start_s[k] - series.stop_start_s[k - 1],
        *series.stops[k - 1].stop_time_s + ScenarioConfig().scenarios.stop_series_interval_s, 1e-9);
  }
  const double first_rise = series.stops[1].peak_disc_temp_K - series.stops[0].peak_disc_temp_K;
  const double last_rise =
      series.stops.back().peak_disc_temp_K - series.stops[series.stops.size() - 2].peak_disc_temp_K;
  EXPECT_LT(last_rise, 0.1 * first_rise);
  for (size_t i = 1; i < series.time.size(); ++i) ASSERT_GT(series.time[i], series.time[i - 1]);
  EXPECT_EQ(series.time.size(), series.disc_temp.size());
}

}  // namespace
