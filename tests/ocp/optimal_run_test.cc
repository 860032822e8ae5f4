// MakeOptimalLapOptions: the run's options in the commands' units become the solver's (the solves
// themselves are tested in optimal_lap_test.cc and disc_limit_comparison_test.cc).

#include "hotlap/ocp/optimal_run.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

TEST(MakeOptimalLapOptions, TakesTheRunsOptionsInSolverUnits) {
  OptimalRunOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.steer_smoothing = 0.5;
  o.convex_element_hessians = true;
  o.disc_limit_C = 500.0;
  o.thermal_start = "periodic";
  o.ambient_C = 20.0;
  o.track_C = 35.0;
  o.max_iterations = 77;
  o.ipopt_output = true;
  o.second_process = false;
  o.ipopt_options = {{"mumps_pivot_order", "5"}};
  const OptimalLapOptions l = MakeOptimalLapOptions(o);
  EXPECT_EQ(l.step_m, 30.0);
  EXPECT_EQ(l.coarse_step_m, 0.0);
  EXPECT_EQ(l.steer_smoothing_weight, 0.5);
  EXPECT_EQ(l.pedal_smoothing_weight, -1.0);
  EXPECT_TRUE(l.convex_element_hessians);
  EXPECT_FALSE(l.front_disc_limit);  // SolveOptimalRuns sets the limit
  EXPECT_EQ(l.thermal_start, ThermalStart::kPeriodic);
  EXPECT_EQ(l.ambient_temp, CelsiusToKelvin(20.0));
  EXPECT_EQ(l.track_temp, CelsiusToKelvin(35.0));
  EXPECT_EQ(l.ipopt.max_iterations, 77);
  EXPECT_EQ(l.ipopt.print_level, 5);
  EXPECT_EQ(l.ipopt.alpha_for_y, "min-dual-infeas");  // LapIpoptOptions' own
  ASSERT_EQ(l.ipopt.extra.size(), 1u);
  EXPECT_EQ(l.ipopt.extra[0].second, "5");
  EXPECT_FALSE(l.second_process);
  EXPECT_EQ(MakeOptimalLapOptions({}).ipopt.print_level, 0);
}

TEST(MakeOptimalLapOptions, AnUnknownThermalStartIsAnInputError) {
  OptimalRunOptions o;
  o.thermal_start = "hot";
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { MakeOptimalLapOptions(o); }), "hot"));
}

}  // namespace
}  // namespace hotlap::ocp
