// The JSON summary of `hotlap abs` on hand-made figures: rounding, null for a missing window,
// degC, the event's settings and the scenarios.

#include "hotlap/abs/abs_json.h"

#include <gtest/gtest.h>

#include "abs/abs_example.h"

namespace hotlap::sim {
namespace {

TEST(AbsMetricsJson, RoundsAndUsesNullAndCelsius) {
  const nlohmann::json j = AbsMetricsJson(testing::MakeExampleAbsMetrics());
  EXPECT_EQ(j["stopped"], true);
  EXPECT_EQ(j["stopping_distance_m"], 15.1234568);
  EXPECT_EQ(j["cycles"], 3);
  EXPECT_EQ(j["first_cycle_start_s"], 0.1);
  EXPECT_TRUE(j["second_cycle_start_s"].is_null());
  EXPECT_TRUE(j["abs_exit_s"].is_null());
  EXPECT_EQ(j["peak_disc_temp_C"], 103.0);
  EXPECT_EQ(j["energy"]["brake_J"], 900.0);
  EXPECT_EQ(j["energy"]["closure_error"], 1.23e-5);
}

TEST(AbsRunJson, HoldsTheEventAndTheScenarios) {
  const AbsConfig config = testing::MakeExampleAbsConfig();
  AbsEvent event = testing::MakeExampleAbsEvent();
  event.vehicle = AbsVehicleMode::kDrum;
  const AbsMetrics m = testing::MakeExampleAbsMetrics();
  nlohmann::json j = AbsRunJson(config, event, m, "out/abs.csv", "out/abs_report.html");
  EXPECT_EQ(j["command"], "abs");
  EXPECT_EQ(j["config"], "abs/example.yaml");
  EXPECT_EQ(j["surface"], "dry");
  EXPECT_EQ(j["abs"], true);
  EXPECT_EQ(j["vehicle"], "drum");
  EXPECT_EQ(j["initial_speed_mps"], 20.0);
  EXPECT_EQ(j["outputs"]["report"], "out/abs_report.html");
  EXPECT_EQ(j["stop_time_s"], 1.5);
  EXPECT_FALSE(j.contains("scenarios"));

  std::vector<AbsComparisonRun> comparison(2);
  comparison[0].surface = comparison[1].surface = "wet";
  comparison[0].metrics = m;
  comparison[1].metrics.stopping_distance_m = 20.0;
  AbsStopSeries series;
  series.stops = {m, m};
  j = AbsRunJson(config, event, m, "a.csv", "a.html", &comparison, &series);
  EXPECT_EQ(j["scenarios"]["comparison"][0]["surface"], "wet");
  EXPECT_EQ(j["scenarios"]["comparison"][0]["locked"]["stopping_distance_m"], 20.0);
  EXPECT_EQ(j["scenarios"]["stop_series"]["stops"], 2);
  EXPECT_EQ(j["scenarios"]["stop_series"]["interval_s"], 30.0);
  EXPECT_EQ(j["scenarios"]["stop_series"]["peak_disc_temp_C"], nlohmann::json({103.0, 103.0}));
}

}  // namespace
}  // namespace hotlap::sim
