// Coarse to fine (ocp/lap_problem.h ResampleLapPoint, ocp/optimal_lap.h coarse_step_m): a lap
// solved on a coarse mesh, taken onto a finer one by linear interpolation in distance, starts the
// fine solve, which then lands on the same lap in fewer iterations than from the QSS guess.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/lap_problem.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

TEST(ResampleLapPointTest, InterpolatesEveryNodeVariableInDistance) {
  // Three nodes of two variables (a, b) onto five: the new nodes sit at 0, 1/2, 1, 3/2, 2
  // coarse intervals.
  const std::vector<double> x = {0.0, 10.0, 2.0, 30.0, 6.0, 20.0};
  const std::vector<double> y = ResampleLapPoint(x, 3, 5);
  const std::vector<double> expected = {0.0, 10.0, 1.0, 20.0, 2.0, 30.0, 4.0, 25.0, 6.0, 20.0};
  ASSERT_EQ(y.size(), expected.size());
  for (size_t i = 0; i < y.size(); ++i) EXPECT_DOUBLE_EQ(y[i], expected[i]) << i;
  // Onto the same mesh: unchanged; onto a coarser one: the nodes it shares.
  EXPECT_EQ(ResampleLapPoint(x, 3, 3), x);
  const std::vector<double> ends = ResampleLapPoint(x, 3, 2);
  EXPECT_EQ(ends, (std::vector<double>{0.0, 10.0, 6.0, 20.0}));
}

TEST(ResampleLapPointTest, RefusesAPointThatIsNotWholeNodes) {
  EXPECT_THROW(ResampleLapPoint({1.0, 2.0, 3.0}, 2, 4), InputError);
  EXPECT_THROW(ResampleLapPoint({}, 2, 4), InputError);
  EXPECT_THROW(ResampleLapPoint({1.0, 2.0}, 1, 4), InputError);
}

TEST(LapNodeCountTest, IntervalsOfAboutTheStepAndTheClosingNode) {
  const track::Track track = track::LoadTrack("darlington");  // 2198 m
  EXPECT_EQ(LapNodeCount(track, 3.0), 734);                   // round(732.7) + 1
  EXPECT_EQ(LapNodeCount(track, 20.0), 111);                  // round(109.9) + 1
  EXPECT_EQ(LapNodeCount(track, 1000.0), 17);                 // at least 16 intervals
}

TEST(CoarseToFineTest, ReachesTheSameLapAsTheGuessStartInFewerIterations) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalLapOptions o;
  o.step_m = 15.0;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  const LapWarmUp warm_up = RunLapWarmUp(car, track, o);

  o.coarse_step_m = 0.0;
  const OptimalLapRun direct = RunOptimalLap(car, track, o, &warm_up);
  o.coarse_step_m = 45.0;
  const OptimalLapRun staged = RunOptimalLap(car, track, o, &warm_up);
  ASSERT_TRUE(direct.solution.solve.ok()) << direct.solution.solve.message;
  ASSERT_TRUE(staged.solution.solve.ok()) << staged.solution.solve.message;
  EXPECT_EQ(direct.coarse.iterations, 0);
  ASSERT_TRUE(staged.coarse.ok()) << staged.coarse.message;
  EXPECT_GT(staged.coarse.iterations, 0);
  EXPECT_GT(staged.coarse_lap_time, 0.0);
  // The same problem, the same lap (local optima of this size differ by well under 10 ms).
  EXPECT_EQ(staged.solution.variables, direct.solution.variables);
  EXPECT_NEAR(staged.solution.lap_time, direct.solution.lap_time, 0.01);
  // Started close to its optimum, the fine solve needs fewer iterations than from the guess.
  EXPECT_LT(staged.solution.solve.iterations, direct.solution.solve.iterations)
      << "coarse " << staged.coarse.iterations << " then " << staged.solution.solve.iterations;
  RecordProperty("direct_iterations", direct.solution.solve.iterations);
  RecordProperty("coarse_iterations", staged.coarse.iterations);
  RecordProperty("fine_iterations", staged.solution.solve.iterations);

  // With a small first barrier that keeps the start (IpoptOptions::primal_start_mu): the same lap
  // (the iterations differ either way with the car and the mesh, docs/optimal-control.md).
  o.ipopt.primal_start_mu = 1e-4;
  const OptimalLapRun pushed = RunOptimalLap(car, track, o, &warm_up);
  ASSERT_TRUE(pushed.solution.solve.ok()) << pushed.solution.solve.message;
  EXPECT_NEAR(pushed.solution.lap_time, staged.solution.lap_time, 2e-3);
  RecordProperty("fine_iterations_small_mu", pushed.solution.solve.iterations);
  o.ipopt.primal_start_mu = 0.0;

  // A given start point wins over coarse to fine.
  o.start_point = staged.solution.solve.x;
  const OptimalLapRun again = RunOptimalLap(car, track, o, &warm_up);
  EXPECT_EQ(again.coarse.iterations, 0);
  ASSERT_TRUE(again.solution.solve.ok());
  EXPECT_NEAR(again.solution.lap_time, staged.solution.lap_time, 1e-4);
}

}  // namespace
}  // namespace hotlap::ocp
