// The mesh check as a library call (ocp/mesh_check.h): a 30 m lap solved again on 15 m from its
// own point and multipliers lands on the 15 m lap in fewer iterations than from its point alone.

#include "hotlap/ocp/mesh_check.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/lap_problem.h"
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

  // From the 30 m lap's point alone (no multipliers: Ipopt's own barrier start) the same 15 m
  // problem lands on the same lap in more iterations: the multipliers are what the mesh check
  // adds. (From the QSS guess it is a lottery of the 15 m problem's local optima, 5-10 ms apart:
  // 63 iterations to a lap 10 ms slower, 2026-11-29.)
  OptimalLapOptions point_only = o;
  point_only.step_m = 15.0;
  StartFromSolution(coarse.run.solution.solve, coarse.run.solution.layout,
                    LapNodeCount(track, point_only.step_m), point_only.collocation, false,
                    point_only.start_point, point_only.ipopt);
  const SolvedLap from_point = SolveLap(car, track, point_only, "15 m from the 30 m point");
  ASSERT_TRUE(from_point.run.solution.solve.ok()) << from_point.run.solution.solve.message;
  EXPECT_NEAR(half.figures.lap_time_s, from_point.figures.lap_time_s, 1e-3);  // 2e-6 s seen
  EXPECT_LT(half.run.solution.solve.iterations, from_point.run.solution.solve.iterations);
  RecordProperty("half_mesh_iterations", half.run.solution.solve.iterations);
  RecordProperty("point_only_iterations", from_point.run.solution.solve.iterations);
}

}  // namespace
}  // namespace hotlap::ocp
