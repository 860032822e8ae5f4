// The JSON summary of an optimal-lap run on hand-made laps: one lap's keys (solve, limit, corners,
// turns, thermal start), the single run's and the comparison's top levels.

#include "hotlap/ocp/optimal_run_json.h"

#include <gtest/gtest.h>

#include "ocp/solved_lap_example.h"

namespace hotlap::ocp {
namespace {

TEST(SolvedLapJson, HoldsTheSolveFiguresTurnsAndStart) {
  const nlohmann::json j =
      SolvedLapJson(testing::MakeExampleSolvedLap("optimal lap", 30.0), "racing");
  EXPECT_EQ(j["lap_time_s"], 30.0);
  EXPECT_EQ(j["qss_lap_time_s"], 30.5);
  EXPECT_EQ(j["solve_time_s"], 1.23456789);
  EXPECT_EQ(j["ipopt_iterations"], 42);
  EXPECT_EQ(j["regularized_iterations"], 3);
  EXPECT_TRUE(j["coarse_solve"].is_null());
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["message"], "Optimal Solution Found");
  EXPECT_TRUE(j["front_disc_limit_C"].is_null());
  EXPECT_EQ(j["corners"]["fr"]["peak_disc_temp_C"], 481.0);
  EXPECT_EQ(j["corners"]["rr"]["wear_mm"], 0.013);
  EXPECT_EQ(j["turns"][0]["turn"], "turn 1");
  EXPECT_EQ(j["turns"][0]["lift_m"], 120.0);
  EXPECT_TRUE(j["turns"][0]["brake_m"].is_null());
  EXPECT_EQ(j["thermal_start"]["mode"], "racing");
  EXPECT_EQ(j["thermal_start"]["qss_laps"], 4);
  EXPECT_EQ(j["thermal_start"]["carcass_rise_K"], 12.5);
  EXPECT_EQ(j["thermal_start"]["corners"]["fl"]["disc_temp_C"], 400.0);  // the lap's first node
  EXPECT_EQ(j["brake_energy_J"], 2.5e6);
  EXPECT_EQ(j["variables"], 300);
  const nlohmann::json car = SolvedLapJson(testing::MakeExampleSolvedLap("x", 30.0, 500.0), "car");
  EXPECT_EQ(car["front_disc_limit_C"], 500.0);
  EXPECT_FALSE(car["thermal_start"].contains("carcass_rise_K"));
  EXPECT_TRUE(j["sensitivities"].is_null());  // not asked
}

TEST(SolvedLapJson, HoldsTheSensitivities) {
  SolvedLap lap = testing::MakeExampleSolvedLap("optimal lap", 30.0);
  lap.sensitivities = {{CrewChiefParameters()[3], 303.4, 0.3034, -5.255e-5}};
  const nlohmann::json j = SolvedLapJson(lap, "racing")["sensitivities"];
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["key"], "tyre_forces.rr.pressure_kPa");
  EXPECT_EQ(j[0]["label"], "right-rear cold pressure");
  EXPECT_EQ(j[0]["unit"], "kPa");
  EXPECT_EQ(j[0]["value"], 303.4);
  EXPECT_EQ(j[0]["step"], 0.3034);
  EXPECT_EQ(j[0]["d_lap_time_s_per_unit"], -5.255e-5);
  EXPECT_EQ(j[0]["typical_step_text"], "+1 psi");
  EXPECT_NEAR(j[0]["typical_step"].get<double>(), 6.894757, 1e-6);
  EXPECT_NEAR(j[0]["typical_step_effect_ms"].get<double>(), -0.36232, 1e-5);
}

TEST(OptimalRunsJson, HoldsTheLimitsCostSensitivities) {
  SolvedLap free = testing::MakeExampleSolvedLap("no limit", 30.0);
  SolvedLap limited = testing::MakeExampleSolvedLap("discs <= 500 degC", 30.25, 500.0);
  EXPECT_TRUE(LimitCostSensitivitiesJson(free, limited).is_null());
  const SetupParameter& mass = CrewChiefParameters().back();
  free.sensitivities = {{mass, 1542.0, 1.542, 4.0e-3}};
  limited.sensitivities = {{mass, 1542.0, 1.542, 4.25e-3}};
  const nlohmann::json j = LimitCostSensitivitiesJson(free, limited);
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["key"], mass.key);
  EXPECT_NEAR(j[0]["d_delta_s_per_unit"].get<double>(), 2.5e-4, 1e-12);
  EXPECT_NEAR(j[0]["typical_step_effect_ms"].get<double>(), 2.5e-4 * mass.typical_step * 1e3, 1e-9);
}

TEST(OptimalRunsJson, OneSolveAndTheComparison) {
  OptimalRunOptions o;
  o.step_m = 30.0;
  vehicle::Car car;
  car.name = "gen7";
  OptimalRuns one;
  one.laps = {testing::MakeExampleSolvedLap("optimal lap", 30.0)};
  nlohmann::json j = OptimalRunsJson(one, o, "darlington", car, 12.3456789012, 0.0123);
  EXPECT_EQ(j["command"], "optimise");
  EXPECT_EQ(j["track"], "darlington");
  EXPECT_EQ(j["car"], "gen7");
  EXPECT_EQ(j["overrides"], nlohmann::json::object());
  EXPECT_EQ(j["mesh_step_m"], 30.0);
  EXPECT_EQ(j["collocation"], "trapezoid");
  EXPECT_EQ(j["coarse_mesh_step_m"], 15.0);
  EXPECT_EQ(j["coarse_collocation"], "trapezoid");
  EXPECT_EQ(j["wear_in_programme"], false);
  EXPECT_EQ(j["wall_time_s"], 12.3456789);
  EXPECT_EQ(j["mesh_check_delta_s"], 0.0123);
  EXPECT_EQ(j["lap_time_s"], 30.0);
  EXPECT_EQ(j["controls"], "pedal");
  o.independent_drive_and_brake = true;
  EXPECT_EQ(OptimalRunsJson(one, o, "darlington", car, 1.0)["controls"], "independent");
  o.coarse_collocation = "hermite-simpson";
  o.wear_in_programme = true;
  EXPECT_EQ(OptimalRunsJson(one, o, "darlington", car, 1.0)["coarse_collocation"],
            "hermite-simpson");
  EXPECT_EQ(OptimalRunsJson(one, o, "darlington", car, 1.0)["wear_in_programme"], true);

  OptimalRuns two;
  two.laps = {testing::MakeExampleSolvedLap("no limit", 30.0),
              testing::MakeExampleSolvedLap("discs <= 500 degC", 30.25, 500.0)};
  two.limited_in_second_process = true;
  car.overrides = {{"brake_system.front_share", 0.55}};
  j = OptimalRunsJson(two, o, "darlington", car, 1.0);
  EXPECT_EQ(j["command"], "lap --method ocp");
  EXPECT_EQ(j["delta_s"], 0.25);
  EXPECT_EQ(j["lap_time_s"], 30.0);
  EXPECT_EQ(j["constrained"]["front_disc_limit_C"], 500.0);
  EXPECT_EQ(j["limited_in_second_process"], true);
  EXPECT_EQ(j["overrides"], nlohmann::json({{"brake_system.front_share", 0.55}}));
  EXPECT_FALSE(j.contains("mesh_check_delta_s"));
}

}  // namespace
}  // namespace hotlap::ocp
