#pragma once
/// @file
/// Set-up sensitivities of the optimal lap: the derivative of the minimum lap time with respect
/// to each number a crew chief sets (cold pressures, camber, brake balance, brake ducts, weight
/// split, aero, mass), from the solved lap alone, without solving again.
///
/// Method (the envelope theorem of parametric nonlinear programming; sIPOPT, Pirnay, Lopez-Negrete
/// and Biegler 2012): at a local optimum x* with multipliers (lambda*, z*) of the programme
/// min f(x; p) s.t. g(x; p) = b(p), x_L(p) <= x <= x_U(p), the optimal objective J*(p) has
///
///   dJ*/dp = d/dp [ f(x*; p) + lambda*' (g(x*; p) - b(p)) - z_L*' (x* - x_L(p)) + z_U*' (x* -
///   x_U(p)) ]
///
/// (Ipopt's sign convention, L = f + lambda' g), the partial derivative at the fixed point. Here
/// the programme is posed again for the car with the parameter at p +- h (EvaluateRunProgramme:
/// no solve) and the Lagrangian differenced centrally. Ipopt's multipliers are those of the scaled
/// programme the solver sees (f / F, g_r / t_r, x_i / s_i: element_nlp.h), so they are weighed
/// with the base programme's scales: physical row multiplier F lambda_r / t_r, bound multiplier
/// F z_i / s_i. The objective is the programme's (the lap time plus the small control-smoothness
/// penalty), and the derivative is first order: a step's effect is its slope times the step.
/// docs/optimal-control.md, "Set-up sensitivities".

#include <string>
#include <vector>

#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ocp {

/// A set-up parameter by its car-override key (docs/overrides.md).
struct SetupParameter {
  std::string key;        ///< e.g. "tyre_forces.rr.pressure_kPa"
  std::string label;      ///< e.g. "right-rear cold pressure"
  std::string unit;       ///< the key's own unit, e.g. "kPa"
  double typical_step;    ///< a step a crew chief makes, in `unit`
  std::string step_text;  ///< that step in words, e.g. "+1 psi"
};

/// The parameters the sensitivities cover, each a key the Gen-7-like car accepts: the four cold
/// pressures and cambers, the brake balance, the four brake duct factors, the static front and
/// left weight fractions, the drag and downforce areas, the aero balance and the chassis mass.
const std::vector<SetupParameter>& CrewChiefParameters();

/// The value of `key` (one of CrewChiefParameters, or any number of the vehicle's field tables,
/// vehicle/vehicle_fields.h) on `car`, in the key's unit: an override the car was loaded with,
/// else the car's own (a duct factor not overridden: 1). InputError for a key it does not know or
/// a car without vehicle sections.
double SetupValue(const vehicle::Car& car, const std::string& key);

/// One parameter's sensitivity.
struct LapSensitivity {
  SetupParameter parameter;
  double value = 0.0;                ///< the car's value, in the unit
  double step = 0.0;                 ///< h of the central difference, in the unit
  double d_lap_time_per_unit = 0.0;  ///< dJ*/dp, s per unit
  /// The effect of the typical step, d_lap_time_per_unit * typical_step, s.
  double typical_effect_s() const { return d_lap_time_per_unit * parameter.typical_step; }
};

struct SensitivityOptions {
  /// h = relative_step * max(|value|, typical step): the derivative is flat in h from 1e-4 to
  /// 1e-2 on the Gen-7-like car's lap (docs/optimal-control.md).
  double relative_step = 1e-3;
  std::vector<std::string> keys;  ///< of CrewChiefParameters; empty: all of them
};

/// dJ*/dp from the programme evaluated at the solution with the parameter at p + h (`plus`) and
/// p - h (`minus`), the solve's multipliers and the base programme's scales (`base`), s per unit
/// of p. InputError if the sizes do not match.
double LagrangianDerivative(const SolveResult& solve, const LapProgrammeValues& base,
                            const LapProgrammeValues& plus, const LapProgrammeValues& minus,
                            double h);

/// The sensitivities of `run` (a converged RunOptimalLap of `car` on `track` with `options`),
/// each parameter's perturbed car loaded from car.path with car.overrides and the parameter's
/// override (vehicle::LoadCar); with every parameter (sensitivity.keys empty), one the car does
/// not take at p +- h is left out. InputError if the run did not converge, the car has no file,
/// or a key asked for is unknown or refused.
std::vector<LapSensitivity> ComputeLapSensitivities(const vehicle::Car& car,
                                                    const track::Track& track,
                                                    const OptimalLapOptions& options,
                                                    const OptimalLapRun& run,
                                                    const SensitivityOptions& sensitivity = {});

/// The car loaded again from its file with its overrides and `key` set to `value`.
vehicle::Car CarWithSetup(const vehicle::Car& car, const std::string& key, double value);

}  // namespace hotlap::ocp
