// StintJson on a hand-made stint of two laps: the run's keys, each lap, the last lap's figures at
// the top level, the braking zones and per corner the peaks in degC and the wear.

#include "hotlap/sim/lap_json.h"

#include <gtest/gtest.h>

#include "hotlap/track/track_io.h"
#include "sim/qss_example.h"

namespace hotlap::sim {
namespace {

TEST(StintJson, HoldsTheLapsZonesAndCorners) {
  const track::Track track = track::LoadTrack("darlington");
  const StintSummary stint = SummarizeStint(testing::MakeExampleQssResult(2));
  vehicle::Car car;
  car.name = "gen7";
  car.overrides = {{"chassis.mass_kg", 1600.0}, {"brakes.fl.duct_factor", 0.5}};
  const nlohmann::json j = StintJson(stint, track, car, "out/lap.csv", "out/lap.html");
  EXPECT_EQ(j["command"], "lap");
  EXPECT_EQ(j["method"], "qss");
  EXPECT_EQ(j["track"], "darlington");
  EXPECT_NEAR(j["track_length_m"].get<double>(), track.length_m(), 1e-6);
  EXPECT_EQ(j["car"], "gen7");
  EXPECT_EQ(j["overrides"],
            nlohmann::json({{"chassis.mass_kg", 1600.0}, {"brakes.fl.duct_factor", 0.5}}));
  ASSERT_EQ(j["laps"].size(), 2u);
  EXPECT_EQ(j["laps"][0]["lap_time_s"], 2.3);
  EXPECT_EQ(j["lap_time_s"], 2.4);
  EXPECT_EQ(j["top_speed_mps"], 51.0);
  EXPECT_EQ(j["min_speed_mps"], 30.0);
  ASSERT_EQ(j["braking_zones"].size(), 2u);
  EXPECT_EQ(j["braking_zones"][1]["lap"], 2);
  EXPECT_EQ(j["braking_zones"][1]["entry_speed_mps"], 48.0);
  EXPECT_EQ(j["corners"]["rr"]["peak_disc_temp_C"], 495.0);
  EXPECT_EQ(j["corners"]["fl"]["peak_tread_temp_C"], 92.0);
  EXPECT_EQ(j["corners"]["fl"]["wear_per_lap_mm"], 0.01);
  EXPECT_EQ(j["corners"]["fl"]["wear_total_mm"], 0.02);
  EXPECT_EQ(j["slip_points_not_reached"], 1);
  EXPECT_EQ(j["out_csv"], "out/lap.csv");
  EXPECT_EQ(j["out_report"], "out/lap.html");
}

}  // namespace
}  // namespace hotlap::sim
