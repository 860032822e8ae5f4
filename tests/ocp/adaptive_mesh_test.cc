// The adaptive mesh's loop (ocp/adaptive_mesh.h) through RunOptimalLap: the coarse solve is its
// first round, a mesh whose every interval is within its share of the tolerance is kept, and the
// set-up sensitivities of a refined lap are those of its own mesh's programme.

#include "hotlap/ocp/adaptive_mesh.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/lap_sensitivities.h"
#include "hotlap/ocp/mesh_resample.h"
#include "hotlap/track/track_io.h"
#include "short_track.h"
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

// One refinement of the short stadium's 24 m lap: the run keeps the refined solve's programme as
// posed (its mesh and start point), and the mass's sensitivity from it matches the central
// difference of two solves on that mesh from the refined lap (the wear in the programme, as the
// sensitivities' own test has it: no frozen wear that differs between the solves).
TEST(RefineLapMeshTest, TheSensitivitiesAreTheRefinedMeshs) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = test::ShortStadium();
  OptimalLapOptions o;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  o.thermal_start = ThermalStart::kWarm;
  o.coarse_step_m = 24.0;
  o.tolerance_s = 1e-4;
  o.max_refinements = 1;
  o.wear_in_programme = true;
  o.ipopt.max_iterations = 300;
  const LapWarmUp warm_up = RunLapWarmUp(car, track, o);
  const OptimalLapRun base = RunOptimalLap(car, track, o, &warm_up);
  ASSERT_TRUE(base.solution.solve.ok()) << base.solution.solve.message;
  ASSERT_EQ(base.mesh_rounds.size(), 2u);  // the 24 m solve and one refined
  ASSERT_TRUE(base.mesh_rounds[1].converged);
  const std::vector<double>& mesh = base.solution.layout.mesh_m;
  ASSERT_GT(mesh.size(), static_cast<size_t>(LapNodeCount(track, 24.0)));
  ASSERT_TRUE(base.posed);
  EXPECT_EQ(base.posed->problem.mesh_m, mesh);
  EXPECT_EQ(base.posed->problem.start_point.size(), base.solution.solve.x.size());

  SensitivityOptions so;
  so.keys = {"chassis.mass_kg"};
  const std::vector<LapSensitivity> analytic = ComputeLapSensitivities(car, track, o, base, so);
  ASSERT_EQ(analytic.size(), 1u);
  const double step = analytic[0].parameter.typical_step;
  const auto solve = [&](double mass) {
    OptimalLapOptions r = o;
    r.tolerance_s = 0.0;
    r.coarse_step_m = 0.0;
    r.mesh_m = mesh;
    StartFromSolutionOnMesh(base.solution.solve, base.solution.layout, track.length_m(), mesh, true,
                            r.start_point, r.ipopt);
    r.ipopt.tolerance = 1e-9;
    return RunOptimalLap(CarWithSetup(car, "chassis.mass_kg", mass), track, r, &warm_up);
  };
  const OptimalLapRun plus = solve(analytic[0].value + step);
  const OptimalLapRun minus = solve(analytic[0].value - step);
  ASSERT_TRUE(plus.solution.solve.ok()) << plus.solution.solve.message;
  ASSERT_TRUE(minus.solution.solve.ok()) << minus.solution.solve.message;
  EXPECT_EQ(plus.solution.layout.nodes, base.solution.layout.nodes);
  const double fd_effect = 0.5 * (plus.solution.lap_time - minus.solution.lap_time);
  const double effect = analytic[0].typical_effect_s();
  RecordProperty("mass_effect_ms",
                 fmt::format("{:.4f} against {:.4f}", 1e3 * effect, 1e3 * fd_effect));
  EXPECT_GT(effect, 0.0);
  EXPECT_NEAR(effect, fd_effect, std::max(0.05 * std::abs(fd_effect), 2e-4));
}

}  // namespace
}  // namespace hotlap::ocp
