// MakeOptimalLapOptions: the run's options in the commands' units become the solver's (the solves
// themselves are tested in optimal_lap_test.cc and disc_limit_comparison_test.cc).

#include "hotlap/ocp/optimal_run.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/lap_sensitivities.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

// The command line's ranges hold for every caller (the Python package passed step_m = 200,
// coarse_step_m = -5 and max_iterations = -1 straight to the solver).
TEST(MakeOptimalLapOptions, RefusesWhatTheCommandLineRefuses) {
  const auto error_of = [](auto edit) {
    OptimalRunOptions o;
    edit(o);
    return test::InputErrorOf([&] { MakeOptimalLapOptions(o); });
  };
  EXPECT_TRUE(test::Contains(error_of([](auto& o) { o.step_m = 200.0; }),
                             "step_m: 200 m is not 0.5 to 50 m"));
  EXPECT_TRUE(test::Contains(error_of([](auto& o) { o.step_m = 0.1; }), "step_m: 0.1 m"));
  EXPECT_TRUE(test::Contains(error_of([](auto& o) { o.coarse_step_m = -5.0; }),
                             "coarse_step_m: -5 m is not 0 to 100 m"));
  EXPECT_TRUE(test::Contains(error_of([](auto& o) { o.max_iterations = -1; }),
                             "max_iterations: -1 is not 1 or more"));
  EXPECT_NO_THROW(MakeOptimalLapOptions({}));
}

TEST(MakeOptimalLapOptions, TakesTheRunsOptionsInSolverUnits) {
  OptimalRunOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.steer_smoothing = 0.5;
  o.convex_element_hessians = true;
  o.wear_in_programme = true;
  o.disc_limit_C = 500.0;
  o.thermal_start = "periodic";
  o.ambient_C = 20.0;
  o.track_C = 35.0;
  o.max_iterations = 77;
  o.ipopt_output = true;
  o.second_process = false;
  o.ipopt_options = {{"mumps_pivot_order", "5"}};
  o.independent_drive_and_brake = true;
  o.threads = 3;
  const OptimalLapOptions l = MakeOptimalLapOptions(o);
  EXPECT_EQ(l.step_m, 30.0);
  EXPECT_EQ(l.coarse_step_m, 0.0);
  EXPECT_EQ(l.steer_smoothing_weight, 0.5);
  EXPECT_EQ(l.pedal_smoothing_weight, -1.0);
  EXPECT_TRUE(l.convex_element_hessians);
  EXPECT_TRUE(l.wear_in_programme);
  EXPECT_FALSE(MakeOptimalLapOptions({}).wear_in_programme);
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
  EXPECT_TRUE(l.independent_drive_and_brake);
  EXPECT_EQ(l.derivative_threads, 3);
  EXPECT_EQ(MakeOptimalLapOptions({}).ipopt.print_level, 0);
  EXPECT_FALSE(MakeOptimalLapOptions({}).independent_drive_and_brake);
  EXPECT_EQ(MakeOptimalLapOptions({}).derivative_threads, 1);  // the library's default
  o.threads = 0;                                               // one per core, at most 8
  EXPECT_GE(MakeOptimalLapOptions(o).derivative_threads, 1);
  EXPECT_LE(MakeOptimalLapOptions(o).derivative_threads, 8);
}

// The old two controls let the optimiser brake against the engine (a faster lap on paper, with
// much of the brake work done under drive); the one pedal does not (docs/optimal-control.md).
TEST(SolveOptimalRuns, TheOldTwoControlsBrakeAgainstTheEngineAndThePedalDoesNot) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalRunOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  const OptimalRuns pedal = SolveOptimalRuns(car, track, o);
  o.independent_drive_and_brake = true;
  const OptimalRuns two = SolveOptimalRuns(car, track, o);
  ASSERT_TRUE(pedal.laps[0].run.solution.solve.ok());
  ASSERT_TRUE(two.laps[0].run.solution.solve.ok());
  const OptimalLapFigures& p = pedal.laps[0].figures;
  const OptimalLapFigures& t = two.laps[0].figures;
  EXPECT_LT(p.brake_energy_under_drive_J, 0.005 * p.brake_energy_J);
  EXPECT_GT(t.brake_energy_under_drive_J, 0.2 * t.brake_energy_J);
  EXPECT_LT(t.lap_time_s, p.lap_time_s);  // what braking against the engine buys on paper
  for (double pedal_value : two.laps[0].run.solution.pedal) EXPECT_EQ(pedal_value, 0.0);
}

// Saved laps tried in turn (a sweep's nearest solved cases): each within start_max_iterations,
// a slow one counted as failed and reported, then the next, then the default start.
TEST(SolveOptimalRuns, TriesTheSavedLapsInTurnThenTheDefaultStart) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalRunOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.disc_limit_C = 500.0;
  const OptimalRuns base = SolveOptimalRuns(car, track, o);
  const LapSolution& solved = base.laps[0].run.solution;
  ASSERT_TRUE(solved.solve.ok()) << solved.solve.message;
  EXPECT_EQ(base.laps[0].run.started_from, "the QSS guess");
  const LapStart start{track.length_m(), solved.layout, solved.solve};
  // From its own lap: converged near where it starts (a few iterations: the wear is frozen at the
  // start's, kept in the programme from the guess).
  const OptimalRuns again = SolveOptimalRuns(car, track, o, std::vector<LapStart>{start, start});
  EXPECT_TRUE(again.laps[0].run.failed_starts.empty());
  EXPECT_EQ(again.laps[0].run.started_from, "saved lap 1");
  EXPECT_LE(again.laps[0].run.solution.solve.iterations, 10);
  // Another car (the balance moved) from the same lap, with a cap no start meets: both saved laps
  // fail at the cap, then the default start converges.
  OptimalRunOptions capped = o;
  capped.start_max_iterations = 1;
  const vehicle::Car other = CarWithSetup(car, "brake_system.front_share", 0.65);
  const OptimalRuns chain =
      SolveOptimalRuns(other, track, capped, std::vector<LapStart>{start, start});
  const OptimalLapRun& run = chain.laps[0].run;
  ASSERT_TRUE(run.solution.solve.ok()) << run.solution.solve.message;
  ASSERT_GE(run.failed_starts.size(), 2u);
  EXPECT_EQ(run.failed_starts[0].from, "saved lap 1");
  EXPECT_EQ(run.failed_starts[0].iterations, 1);
  EXPECT_EQ(run.failed_starts[1].from, "saved lap 2");
  EXPECT_EQ(run.started_from, "the QSS guess");
}

TEST(MakeOptimalLapOptions, AnUnknownThermalStartIsAnInputError) {
  OptimalRunOptions o;
  o.thermal_start = "hot";
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { MakeOptimalLapOptions(o); }), "hot"));
}

}  // namespace
}  // namespace hotlap::ocp
