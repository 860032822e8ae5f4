#include "hotlap/ocp/lap_sensitivities.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/vehicle/vehicle_fields.h"

namespace hotlap::ocp {

namespace {

constexpr double kPsiInKpa = 6.894757293168361;

constexpr const char* kCornerKeys[4] = {"fl", "fr", "rl", "rr"};
constexpr const char* kCornerWords[4] = {"left-front", "right-front", "left-rear", "right-rear"};

std::vector<SetupParameter> MakeParameters() {
  std::vector<SetupParameter> out;
  for (int c = 0; c < 4; ++c) {
    out.push_back({fmt::format("tyre_forces.{}.pressure_kPa", kCornerKeys[c]),
                   fmt::format("{} cold pressure", kCornerWords[c]), "kPa", kPsiInKpa, "+1 psi"});
  }
  for (int c = 0; c < 4; ++c) {
    out.push_back({fmt::format("tyre_forces.{}.camber_deg", kCornerKeys[c]),
                   fmt::format("{} camber", kCornerWords[c]), "deg", 0.25, "+0.25 deg"});
  }
  out.push_back({"brake_system.front_share", "brake balance (front share)", "1", 0.01, "+1%"});
  for (int c = 0; c < 4; ++c) {
    out.push_back({fmt::format("brakes.{}.duct_factor", kCornerKeys[c]),
                   fmt::format("{} brake duct factor", kCornerWords[c]), "1", 0.1, "+0.1"});
  }
  out.push_back({"chassis.front_weight_fraction", "front weight fraction", "1", 0.01, "+1%"});
  out.push_back({"chassis.left_weight_fraction", "left weight fraction", "1", 0.01, "+1%"});
  out.push_back({"aero.drag_area_m2", "drag area C_D A", "m^2", 0.01, "+0.01 m^2"});
  out.push_back({"aero.downforce_area_m2", "downforce area C_L A", "m^2", 0.01, "+0.01 m^2"});
  out.push_back({"aero.front_downforce_share", "aero balance (front share)", "1", 0.01, "+1%"});
  out.push_back({"chassis.mass_kg", "chassis mass (fuel)", "kg", 10.0, "+10 kg"});
  return out;
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The row's value less its active bound: the bound the multiplier's sign says holds (Ipopt: > 0
// at an upper bound, < 0 at a lower one), none where the multiplier is zero or the bound infinite.
double RowResidual(const LapProgrammeValues& v, size_t r, double lambda) {
  const double bound = lambda > 0.0 ? v.row_upper[r] : v.row_lower[r];
  return std::isfinite(bound) ? v.rows[r] - bound : v.rows[r];
}

}  // namespace

const std::vector<SetupParameter>& CrewChiefParameters() {
  static const std::vector<SetupParameter> parameters = MakeParameters();
  return parameters;
}

double SetupValue(const vehicle::Car& car, const std::string& key) {
  for (const vehicle::CarOverride& o : car.overrides) {
    if (o.key == key) return o.value;
  }
  const vehicle::VehicleParams& p = vehicle::RequireVehicle(car, "set-up sensitivities");
  if (key.rfind("brakes.", 0) == 0 && EndsWith(key, ".duct_factor")) return 1.0;  // derived
  if (const std::optional<double> v = vehicle::VehicleFileValue(p, key)) return *v;
  throw InputError(fmt::format("set-up sensitivities: no sensitivity for the key '{}'", key));
}

vehicle::Car CarWithSetup(const vehicle::Car& car, const std::string& key, double value) {
  if (car.path.empty()) {
    throw InputError("set-up sensitivities: the car has no file to load its set-ups from");
  }
  std::vector<vehicle::CarOverride> overrides;
  for (const vehicle::CarOverride& o : car.overrides) {
    if (o.key != key) overrides.push_back(o);
  }
  overrides.push_back({key, value});
  return vehicle::LoadCar(car.path, overrides);
}

double LagrangianDerivative(const SolveResult& solve, const LapProgrammeValues& base,
                            const LapProgrammeValues& plus, const LapProgrammeValues& minus,
                            double h) {
  const size_t m = solve.lambda.size(), n = solve.z_lower.size();
  for (const LapProgrammeValues* v : {&base, &plus, &minus}) {
    if (v->rows.size() != m || v->lower.size() != n || solve.z_upper.size() != n) {
      throw InputError(fmt::format(
          "set-up sensitivities: a programme of {} rows and {} variables for multipliers of {} "
          "and {}",
          v->rows.size(), v->lower.size(), m, n));
    }
  }
  // The scaled Lagrangian's change (the objective f / F, rows g_r / t_r, variables x_i / s_i).
  double change = (plus.objective - minus.objective) / base.objective_scale;
  for (size_t r = 0; r < m; ++r) {
    const double lambda = solve.lambda[r];
    if (lambda == 0.0) continue;
    change +=
        lambda * (RowResidual(plus, r, lambda) - RowResidual(minus, r, lambda)) / base.row_scale[r];
  }
  for (size_t i = 0; i < n; ++i) {
    // -z_L (x - x_L) + z_U (x - x_U): only a bound that moves with p counts.
    const auto moved = [](double a, double b) {
      return std::isfinite(a) && std::isfinite(b) ? a - b : 0.0;
    };
    change += (solve.z_lower[i] * moved(plus.lower[i], minus.lower[i]) -
               solve.z_upper[i] * moved(plus.upper[i], minus.upper[i])) /
              base.scale[i];
  }
  return base.objective_scale * change / (2.0 * h);
}

std::vector<LapSensitivity> ComputeLapSensitivities(const vehicle::Car& car,
                                                    const track::Track& track,
                                                    const OptimalLapOptions& options,
                                                    const OptimalLapRun& run,
                                                    const SensitivityOptions& sensitivity) {
  const SolveResult& solve = run.solution.solve;
  if (!solve.ok() || solve.lambda.empty()) {
    throw InputError("set-up sensitivities: the lap did not converge (no optimum to expand at)");
  }
  std::vector<SetupParameter> parameters;
  if (sensitivity.keys.empty()) {
    parameters = CrewChiefParameters();
  } else {
    for (const std::string& key : sensitivity.keys) {
      const auto& all = CrewChiefParameters();
      const auto it = std::find_if(all.begin(), all.end(),
                                   [&](const SetupParameter& p) { return p.key == key; });
      if (it == all.end()) {
        throw InputError(fmt::format("set-up sensitivities: no sensitivity for the key '{}'", key));
      }
      parameters.push_back(*it);
    }
  }
  const LapProgrammeValues base = EvaluateRunProgramme(car, track, options, run);
  std::vector<LapSensitivity> out;
  for (const SetupParameter& parameter : parameters) {
    LapSensitivity s;
    s.parameter = parameter;
    s.value = SetupValue(car, parameter.key);
    s.step = sensitivity.relative_step * std::max(std::abs(s.value), parameter.typical_step);
    std::optional<vehicle::Car> up, down;
    try {
      up = CarWithSetup(car, parameter.key, s.value + s.step);
      down = CarWithSetup(car, parameter.key, s.value - s.step);
    } catch (const InputError&) {
      // A car without this key (or at the edge of its range): left out of the full list, an
      // error where it was asked for.
      if (!sensitivity.keys.empty()) throw;
      continue;
    }
    const LapProgrammeValues plus = EvaluateRunProgramme(*up, track, options, run);
    const LapProgrammeValues minus = EvaluateRunProgramme(*down, track, options, run);
    s.d_lap_time_per_unit = LagrangianDerivative(solve, base, plus, minus, s.step);
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace hotlap::ocp
