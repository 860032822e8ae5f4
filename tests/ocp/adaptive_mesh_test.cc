// The adaptive mesh's loop (ocp/adaptive_mesh.h) through RunOptimalLap: the coarse solve is its
// first round, and a mesh whose every interval is within its share of the tolerance is kept.

#include "hotlap/ocp/adaptive_mesh.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

TEST(RefineLapMeshTest, KeepsAMeshWithinTheTolerance) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalLapOptions o;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  o.coarse_step_m = 30.0;
  o.tolerance_s = 1.0;  // far above the 30 m lap's estimate
  int meshes = 0;
  o.on_mesh = [&meshes](const MeshRefinement&) { ++meshes; };
  const OptimalLapRun run = RunOptimalLap(car, track, o);
  ASSERT_TRUE(run.solution.solve.ok()) << run.solution.solve.message;
  EXPECT_EQ(meshes, 0);
  ASSERT_EQ(run.mesh_rounds.size(), 1u);  // the coarse solve, and nothing to refine
  EXPECT_EQ(run.solution.layout.nodes, LapNodeCount(track, 30.0));
  EXPECT_EQ(run.mesh_rounds[0].nodes, run.solution.layout.nodes);
  EXPECT_DOUBLE_EQ(run.mesh_rounds[0].lap_time_s, run.solution.lap_time);
  EXPECT_TRUE(run.mesh_rounds[0].converged);
  // The estimate of the lap kept is the last round's, and within the tolerance.
  EXPECT_DOUBLE_EQ(run.mesh_rounds[0].estimated_error_s, run.mesh_error.lap_time_error_s);
  EXPECT_LE(run.mesh_error.abs_error_s, o.tolerance_s);
  EXPECT_GT(run.mesh_error.abs_error_s, 0.0);
  RecordProperty("estimated_abs_error_ms_30m", std::to_string(1e3 * run.mesh_error.abs_error_s));
}

}  // namespace
}  // namespace hotlap::ocp
