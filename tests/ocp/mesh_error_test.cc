// The mesh error estimate (ocp/mesh_error.h): the embedded rule's defect on polynomials, and the
// estimated lap-time error of a coarse mesh against its difference from a finer solve.

#include "hotlap/ocp/mesh_error.h"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/mesh_resample.h"
#include "hotlap/ocp/optimal_lap.h"
#include "short_track.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

// On a cubic the four-node rule is exact, so the defect is the trapezoid's exact error,
// -h^3 / 12 f'' at the interval's midpoint (f''' is constant), on any nodes.
TEST(TrapezoidDefectTest, IsTheTrapezoidsErrorOnACubic) {
  const std::vector<double> s = {0.0, 1.0, 2.5, 3.0, 4.5, 7.0};
  const auto f = [](double x) { return 2.0 - x + 0.3 * x * x - 0.05 * x * x * x; };
  const auto f2 = [](double x) { return 0.6 - 0.3 * x; };
  std::vector<double> values;
  for (double x : s) values.push_back(f(x));
  for (int k = 0; k + 1 < static_cast<int>(s.size()); ++k) {
    const double h = s[k + 1] - s[k], mid = 0.5 * (s[k] + s[k + 1]);
    EXPECT_NEAR(TrapezoidDefect(s, values, k), -h * h * h / 12.0 * f2(mid), 1e-12) << k;
  }
  // On a straight line the trapezoid is exact.
  for (double& v : values) v = 0.0;
  for (size_t i = 0; i < s.size(); ++i) values[i] = 3.0 - 2.0 * s[i];
  for (int k = 0; k + 1 < static_cast<int>(s.size()); ++k) {
    EXPECT_NEAR(TrapezoidDefect(s, values, k), 0.0, 1e-12);
  }
}

// The objective's own part: with no states (no costates) the estimate is the trapezoid's error
// in the integral of dt/ds, with the sign of T(mesh) - T(exact).
TEST(EstimateMeshErrorTest, WithoutStatesIsTheQuadratureErrorOfTheLapTime) {
  CollocationRates r;
  const int n = 41;
  for (int k = 0; k < n; ++k) {
    const double s = 10.0 * k;
    r.node_m.push_back(s);
    r.dt_ds.push_back(1.0 / (40.0 + 10.0 * std::sin(s / 60.0)));
  }
  r.states = 0;
  const MeshErrorEstimate e = EstimateMeshError(r);
  ASSERT_EQ(e.interval_s.size(), static_cast<size_t>(n - 1));
  // The exact integral by a fine trapezoid, against the 10 m trapezoid.
  double trapezoid = 0.0, exact = 0.0;
  for (int k = 0; k + 1 < n; ++k) trapezoid += 5.0 * (r.dt_ds[k] + r.dt_ds[k + 1]);
  const int fine = 40000;
  for (int i = 0; i < fine; ++i) {
    const double a = 400.0 * i / fine, b = 400.0 * (i + 1) / fine;
    exact += 0.5 * (b - a) *
             (1.0 / (40.0 + 10.0 * std::sin(a / 60.0)) + 1.0 / (40.0 + 10.0 * std::sin(b / 60.0)));
  }
  EXPECT_NEAR(e.lap_time_error_s, trapezoid - exact, 0.02 * std::abs(trapezoid - exact));
}

// The optimal lap of the short stadium (the Gen-7-like car after one QSS out-lap) on uniform
// meshes given as non-uniform ones (the adaptive mesh's penalties, LapProblemOptions::mesh_m):
// the 24 m lap from the QSS guess, the 12 m lap from it and the 3 m lap from the 12 m one (with
// the car's tuned wear neither the 12 m nor the 3 m lap converges from the guess in 300
// iterations). The estimate of the 12 m lap (the 3 m lap's own estimate taken off: the
// difference is between two meshes, not from the exact lap) has the sign of its difference from
// the 3 m lap and is not above three times it. Not tested: within a factor 3 below, because the
// local optima of this track are wider than the error: -8.4 ms estimated against -41.8 ms here,
// and earlier, on the untuned wear, -7.6 ms against -9.0 ms from the guess but -8.3 against
// -34.6 ms from a 1.5 m lap (docs/validation/optimal-lap.md, "Mesh").
struct StadiumLap {
  vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  track::Track track = test::ShortStadium();
  OptimalLapOptions options;
  LapWarmUp warm_up;
  StadiumLap() {
    options.ambient_temp = CelsiusToKelvin(25.0);
    options.track_temp = CelsiusToKelvin(40.0);
    options.thermal_start = ThermalStart::kWarm;
    options.coarse_step_m = 0.0;
    options.ipopt.max_iterations = 300;
    // The paper's models: the estimator is judged on discretisation, and on this short lap the
    // car's own models' local optima (solves from the same start ending tens of ms apart) swamp it.
    options.paper_models = true;
    // The case as measured (docs/validation/optimal-lap.md, "Mesh"): the tyres without their
    // pressure terms, on the .tir's free radii. The estimator is judged on discretisation, and
    // this short lap's local optima are wider than the error: with the shipped pressure window
    // and cold rollouts the 24 m or the 3 m solve stops at the iteration limit, or a 4 m one
    // lands 50.8 ms from the 12 m lap against 8.5 ms estimated.
    for (vehicle::CornerSetup& c : car.vehicle->corners) {
      auto& mf = std::get<tyre::MagicFormulaModel<double>>(c.forces.params).params;
      mf.NOMPRES = mf.INFLPRES;
      mf.PPX1 = mf.PPX4 = mf.PPY1 = mf.PPY4 = 0.0;
      c.rolling_radius = mf.UNLOADED_RADIUS;
    }
    warm_up = RunLapWarmUp(car, track, options);
  }
  // On a uniform mesh of `step_m` from the lap `from` (its point; the wear kept in the
  // programme, as from the guess).
  OptimalLapRun SolveFrom(double step_m, const OptimalLapRun& from) const {
    OptimalLapOptions o = options;
    const int n = static_cast<int>(std::round(track.length_m() / step_m));
    for (int k = 0; k <= n; ++k) o.mesh_m.push_back(track.length_m() * k / n);
    StartFromSolutionOnMesh(from.solution.solve, from.solution.layout, track.length_m(), o.mesh_m,
                            false, o.start_point, o.ipopt);
    o.wear_in_programme = true;
    return RunOptimalLap(car, track, o, &warm_up);
  }
};

TEST(EstimateMeshErrorTest, HasTheSignOfTheErrorAgainstAFineSolve) {
  const StadiumLap lap;
  OptimalLapOptions coarse = lap.options;
  coarse.step_m = 24.0;
  const OptimalLapRun start = RunOptimalLap(lap.car, lap.track, coarse, &lap.warm_up);
  ASSERT_TRUE(start.solution.solve.ok()) << start.solution.solve.message;
  const OptimalLapRun run = lap.SolveFrom(12.0, start);
  ASSERT_TRUE(run.solution.solve.ok()) << run.solution.solve.message;
  const OptimalLapRun fine = lap.SolveFrom(3.0, run);
  ASSERT_TRUE(fine.solution.solve.ok()) << fine.solution.solve.message;
  const double truth = run.solution.lap_time - fine.solution.lap_time;
  const double estimate = run.mesh_error.lap_time_error_s - fine.mesh_error.lap_time_error_s;
  RecordProperty("true_error_ms_12m", fmt::format("{:.4f}", 1e3 * truth));
  RecordProperty("estimate_ms_12m", fmt::format("{:.4f}", 1e3 * estimate));
  // The same sign, and within a factor 3 either way.
  EXPECT_GT(estimate * truth, 0.0) << estimate << " against " << truth;
  EXPECT_LT(std::abs(estimate), 3.0 * std::abs(truth));
  EXPECT_GT(std::abs(estimate), std::abs(truth) / 3.0);
  // The intervals' magnitudes sum to more than their signed sum; on 3 m the estimate is under a
  // tenth of the 12 m lap's (second order: about a sixteenth).
  EXPECT_GE(run.mesh_error.abs_error_s, std::abs(run.mesh_error.lap_time_error_s));
  EXPECT_LT(std::abs(fine.mesh_error.lap_time_error_s), 0.1 * std::abs(estimate));
}

}  // namespace
}  // namespace hotlap::ocp
