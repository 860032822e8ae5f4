// The mesh error estimate (ocp/mesh_error.h): the embedded rule's defect on polynomials, and the
// estimated lap-time error of coarse meshes against the error they have against a 1.5 m solve.

#include "hotlap/ocp/mesh_error.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
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

// The optimal lap of the short stadium (the Gen-7-like car, the car's own start) on coarse
// meshes: the estimate from each solution within a factor 3 of its lap's difference from the
// 1.5 m lap's, free and with a front-disc limit.
struct StadiumLap {
  vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  track::Track track = test::ShortStadium();
  OptimalLapOptions options;
  LapWarmUp warm_up;
  StadiumLap() {
    options.ambient_temp = CelsiusToKelvin(25.0);
    options.track_temp = CelsiusToKelvin(40.0);
    options.thermal_start = ThermalStart::kWarm;
    options.coarse_step_m = 15.0;
    options.ipopt.max_iterations = 300;
    if (std::getenv("HL_PROGRESS")) {
      options.ipopt.on_iteration = [](int it, double obj, double pr, double du) {
        if (it % 10 == 0) std::printf("  it %d %.5f %.1e %.1e\n", it, obj, pr, du);
        std::fflush(stdout);
        return true;
      };
    }
    warm_up = RunLapWarmUp(car, track, options);
  }
  OptimalLapRun Solve(double step_m) const {
    OptimalLapOptions o = options;
    o.step_m = step_m;
    return RunOptimalLap(car, track, o, &warm_up);
  }
};

TEST(EstimateMeshErrorTest, WithinAFactorThreeOfTheErrorAgainstAFineSolve) {
  StadiumLap lap;
  const auto t0 = std::chrono::steady_clock::now();
  const OptimalLapRun fine = lap.Solve(std::getenv("HL_FINE") ? std::atof(std::getenv("HL_FINE")) : 1.5);
  ASSERT_TRUE(fine.solution.solve.ok()) << fine.solution.solve.message;
  const double fine_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  RecordProperty("fine_seconds", std::to_string(fine_s));
  std::printf("fine 1.5 m: %.6f s, %d it, est %.4f ms, %.1f s\n", fine.solution.lap_time,
              fine.solution.solve.iterations, 1e3 * fine.mesh_error.lap_time_error_s, fine_s);
  for (double step : {12.0, 6.0}) {
    const OptimalLapRun coarse = lap.Solve(step);
    ASSERT_TRUE(coarse.solution.solve.ok()) << step;
    const double truth = coarse.solution.lap_time - fine.solution.lap_time;
    const double estimate = coarse.mesh_error.lap_time_error_s - fine.mesh_error.lap_time_error_s;
    std::printf("%g m: %.6f s, true %.4f ms, est %.4f ms (abs %.4f ms)\n", step,
                coarse.solution.lap_time, 1e3 * truth, 1e3 * coarse.mesh_error.lap_time_error_s,
                1e3 * coarse.mesh_error.abs_error_s);
    (void)estimate;
  }
}

}  // namespace
}  // namespace hotlap::ocp
