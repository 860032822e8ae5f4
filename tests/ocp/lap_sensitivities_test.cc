// Set-up sensitivities of the optimal lap (ocp/lap_sensitivities.h): the envelope theorem's
// derivative from the solved lap against a central difference of two solves of the perturbed
// cars, each warm-started from the base solution (same mesh, same warm-up).

#include "hotlap/ocp/lap_sensitivities.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

TEST(LapSensitivitiesTest, EveryParameterIsAKeyOfTheGen7CarWithItsValue) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  EXPECT_EQ(CrewChiefParameters().size(), 19u);
  EXPECT_NEAR(SetupValue(car, "tyre_forces.rr.pressure_kPa"), 303.4, 1e-9);
  EXPECT_NEAR(SetupValue(car, "tyre_forces.fr.camber_deg"), -3.0, 1e-9);
  EXPECT_NEAR(SetupValue(car, "brake_system.front_share"), 0.60, 1e-12);
  EXPECT_NEAR(SetupValue(car, "chassis.mass_kg"), 1542.0, 1e-9);
  EXPECT_NEAR(SetupValue(car, "aero.downforce_area_m2"), 2.3, 1e-12);
  EXPECT_EQ(SetupValue(car, "brakes.fl.duct_factor"), 1.0);
  // Every key loads (the car accepts it), and a loaded override is the value.
  for (const SetupParameter& p : CrewChiefParameters()) {
    const double v = SetupValue(car, p.key);
    const vehicle::Car changed = CarWithSetup(car, p.key, v + 0.5 * p.typical_step);
    EXPECT_NEAR(SetupValue(changed, p.key), v + 0.5 * p.typical_step, 1e-12) << p.key;
  }
  EXPECT_THROW(SetupValue(car, "chassis.cross_weight"), InputError);
}

TEST(LapSensitivitiesTest, LagrangianDerivativeWeighsTheScaledMultipliers) {
  // One variable (scale 2), rows: an equality (scale 10) and an inequality at its upper bound
  // (scale 4, the bound moving with p), and a lower variable bound moving with p.
  SolveResult s;
  s.lambda = {0.5, 0.25};
  s.z_lower = {0.1};
  s.z_upper = {0.0};
  const auto values = [](double p) {
    LapProgrammeValues v;
    v.objective = 3.0 * p;
    v.objective_scale = 2.0;
    v.rows = {7.0 * p, 1.0};
    v.row_lower = {0.0, -INFINITY};
    v.row_upper = {0.0, 5.0 * p};
    v.row_scale = {10.0, 4.0};
    v.lower = {p};
    v.upper = {INFINITY};
    v.scale = {2.0};
    return v;
  };
  // F (3/F + 0.5 * 7 / 10 + 0.25 * (-5) / 4 + 0.1 * 1 / 2) = 3 + 0.7 - 0.625 + 0.1.
  EXPECT_NEAR(LagrangianDerivative(s, values(1.0), values(1.1), values(0.9), 0.1), 3.175, 1e-12);
  LapProgrammeValues wrong = values(1.0);
  wrong.rows.pop_back();
  EXPECT_THROW(LagrangianDerivative(s, values(1.0), wrong, values(0.9), 0.1), InputError);
}

// Each of `keys` (all with HOTLAP_SENSITIVITY_ALL=1) on the Gen-7-like car's lap at Darlington
// on a 15 m mesh from the QSS guess (the wear in the programme; `disc_limit_C` if given), against
// the central difference of two solves at +- its typical step warm-started from the base solution
// and its multipliers (same mesh and warm-up). Within 5% or 0.2 ms on the typical step, whichever
// is larger; `h_keys` are checked to be flat in h too.
void CompareWithSolves(std::vector<std::string> keys, std::optional<double> disc_limit_C,
                       const std::vector<size_t>& h_keys) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const track::Track track = track::LoadTrack("darlington");
  OptimalLapOptions o;
  o.step_m = 15.0;
  // HOTLAP_SENSITIVITY_STEP_M: another mesh (below 15 m from a 15 m coarse solve), for the
  // measurements of docs/optimal-control.md.
  if (const char* step = std::getenv("HOTLAP_SENSITIVITY_STEP_M")) o.step_m = std::atof(step);
  o.coarse_step_m = o.step_m < 15.0 ? 15.0 : 0.0;
  o.wear_in_programme = true;
  o.ambient_temp = CelsiusToKelvin(25.0);
  o.track_temp = CelsiusToKelvin(40.0);
  if (disc_limit_C) o.front_disc_limit = CelsiusToKelvin(*disc_limit_C);
  const LapWarmUp warm_up = RunLapWarmUp(car, track, o);
  const OptimalLapRun base = RunOptimalLap(car, track, o, &warm_up);
  ASSERT_TRUE(base.solution.solve.ok()) << base.solution.solve.message;

  SensitivityOptions so;
  so.keys = std::move(keys);
  if (const char* all = std::getenv("HOTLAP_SENSITIVITY_ALL"); all && std::string(all) == "1") {
    so.keys.clear();
    for (const SetupParameter& p : CrewChiefParameters()) so.keys.push_back(p.key);
  }
  // HOTLAP_SENSITIVITY_KEY: that key alone; HOTLAP_SENSITIVITY_STEP_SCALE: the solves' steps
  // times this (measurements).
  if (const char* key = std::getenv("HOTLAP_SENSITIVITY_KEY")) so.keys = {key};
  double step_scale = 1.0;
  if (const char* f = std::getenv("HOTLAP_SENSITIVITY_STEP_SCALE")) step_scale = std::atof(f);
  const auto started = std::chrono::steady_clock::now();
  const std::vector<LapSensitivity> analytic = ComputeLapSensitivities(car, track, o, base, so);
  const double analytic_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  ::testing::Test::RecordProperty("analytic_seconds", fmt::format("{:.2f}", analytic_s));
  // The derivative hardly moves with h (first order in the Lagrangian, the central difference
  // second order).
  for (size_t k : h_keys) {
    if (k >= analytic.size()) continue;
    SensitivityOptions one = so;
    one.keys = {analytic[k].parameter.key};
    for (double rel : {1e-4, 1e-2}) {
      one.relative_step = rel;
      const double other = ComputeLapSensitivities(car, track, o, base, one)[0].d_lap_time_per_unit;
      EXPECT_NEAR(other, analytic[k].d_lap_time_per_unit,
                  2e-3 * std::abs(analytic[k].d_lap_time_per_unit) + 1e-9)
          << one.keys[0] << " h relative " << rel;
    }
  }

  const auto solve = [&](const std::string& key, double value) {
    OptimalLapOptions r = o;
    StartFromSolution(base.solution.solve, base.solution.layout, base.solution.layout.nodes,
                      o.collocation, true, r.start_point, r.ipopt);
    r.ipopt.tolerance = 1e-9;
    return RunOptimalLap(CarWithSetup(car, key, value), track, r, &warm_up);
  };
  const double objective_scale = EvaluateRunProgramme(car, track, o, base).objective_scale;
  std::cout << fmt::format("base lap {:.6f} s ({} iterations); analytic {:.2f} s for {}\n",
                           base.solution.lap_time, base.solution.solve.iterations, analytic_s,
                           analytic.size());
  std::cout << fmt::format("{:<32} {:>10} {:>12} {:>12} {:>12} {:>8} {:>9}\n", "key", "step",
                           "analytic ms", "solves ms", "objective ms", "diff %", "iters");
  for (const LapSensitivity& s : analytic) {
    const double step = step_scale * s.parameter.typical_step;
    const auto solves_started = std::chrono::steady_clock::now();
    const OptimalLapRun plus = solve(s.parameter.key, s.value + step);
    const OptimalLapRun minus = solve(s.parameter.key, s.value - step);
    const double solves_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - solves_started).count();
    ASSERT_TRUE(plus.solution.solve.ok()) << s.parameter.key << ": " << plus.solution.solve.message;
    ASSERT_TRUE(minus.solution.solve.ok()) << s.parameter.key;
    const double fd_effect = 0.5 * (plus.solution.lap_time - minus.solution.lap_time);
    const double fd_objective =
        0.5 * (plus.solution.solve.objective - minus.solution.solve.objective) * objective_scale;
    const double effect = s.d_lap_time_per_unit * step;
    // One-sided, against the base objective: a kink (another branch of optima) shows here.
    const double base_objective = base.solution.solve.objective * objective_scale;
    std::cout << fmt::format(
        "  one-sided objective: +step {:.4f} ms, -step {:.4f} ms\n",
        1e3 * (plus.solution.solve.objective * objective_scale - base_objective),
        1e3 * (base_objective - minus.solution.solve.objective * objective_scale));
    std::cout << fmt::format(
        "{:<32} {:>10} {:>12.4f} {:>12.4f} {:>12.4f} {:>8.2f} {:>3}+{:<3} {:.1f} s\n",
        s.parameter.key, s.parameter.step_text, 1e3 * effect, 1e3 * fd_effect, 1e3 * fd_objective,
        100.0 * (effect - fd_effect) / std::max(std::abs(fd_effect), 1e-12),
        plus.solution.solve.iterations, minus.solution.solve.iterations, solves_s);
    EXPECT_NEAR(effect, fd_effect, std::max(0.05 * std::abs(fd_effect), 2e-4)) << s.parameter.key;
    ::testing::Test::RecordProperty(
        s.parameter.key, fmt::format("{:.4f} ms against {:.4f} ms", 1e3 * effect, 1e3 * fd_effect));
  }
}

// The acceptance check: eight parameters of the free lap.
TEST(LapSensitivitiesTest, MatchesTheCentralDifferenceOfTwoSolves) {
  CompareWithSolves(
      {"tyre_forces.rr.pressure_kPa", "tyre_forces.fl.pressure_kPa", "tyre_forces.fr.camber_deg",
       "brake_system.front_share", "chassis.left_weight_fraction", "aero.downforce_area_m2",
       "aero.drag_area_m2", "chassis.mass_kg"},
      std::nullopt, {0, 5});
}

// With the front discs limited to 500 degC the ducts and the brake balance act through the
// limit's multipliers.
TEST(LapSensitivitiesTest, MatchesTheSolvesWithADiscLimit) {
  CompareWithSolves({"brakes.fl.duct_factor", "brakes.fr.duct_factor", "brake_system.front_share",
                     "chassis.mass_kg"},
                    500.0, {0});
}

}  // namespace
}  // namespace hotlap::ocp
