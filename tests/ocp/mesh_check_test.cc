// The mesh check as a library call (ocp/mesh_check.h): a 30 m lap solved again on 15 m from its
// own point and multipliers lands on the 15 m lap in fewer iterations than from the QSS guess.

#include "hotlap/ocp/mesh_check.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

TEST(SolveOnHalfMeshTest, WarmStartsFromTheSolutionAndHalvesTheSpacing) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalLapOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  const SolvedLap coarse = SolveLap(car, track, o, "30 m");
  ASSERT_TRUE(coarse.run.solution.solve.ok()) << coarse.run.solution.solve.message;

  const SolvedLap half = SolveOnHalfMesh(car, track, o, coarse);
  ASSERT_TRUE(half.run.solution.solve.ok()) << half.run.solution.solve.message;
  EXPECT_EQ(half.label, "half mesh");
  EXPECT_FALSE(half.front_disc_limit.has_value());
  EXPECT_EQ(half.run.solution.layout.nodes, LapNodeCount(track, 15.0));
  EXPECT_EQ(half.run.coarse.iterations, 0);  // started from the solution, not coarse to fine
  // The same lap to within what a doubled mesh changes (the 3 m and 1.5 m laps agree to 0.1 ms).
  EXPECT_NEAR(half.figures.lap_time_s, coarse.figures.lap_time_s, 0.02);

  // From the QSS guess the same 15 m problem takes more iterations to the same lap.
  OptimalLapOptions cold = o;
  cold.step_m = 15.0;
  const SolvedLap direct = SolveLap(car, track, cold, "15 m");
  ASSERT_TRUE(direct.run.solution.solve.ok());
  // (Two local optima of the 15 m problem: under 2 ms apart with the paper's models; 4.9 ms has
  // been seen with the gas-and-rim tyres and bulk discs, 2026-11-29.)
  EXPECT_NEAR(half.figures.lap_time_s, direct.figures.lap_time_s, 6e-3);
  EXPECT_LT(half.run.solution.solve.iterations, direct.run.solution.solve.iterations);
  RecordProperty("half_mesh_iterations", half.run.solution.solve.iterations);
  RecordProperty("direct_iterations", direct.run.solution.solve.iterations);
}

}  // namespace
}  // namespace hotlap::ocp
