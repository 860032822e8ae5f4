#pragma once
/// @file
/// The slips that make a tyre produce given forces: the inverse of the tyre force model, as the
/// quasi-steady-state lap needs it once it knows each corner's forces.
///
/// A free wheel (a front corner) has two unknowns, slip ratio and slip angle, for two targets,
/// Fx and Fy. The two rear wheels on a locked differential (spool) turn at one speed, so their
/// slip ratios are tied: kappa_i = omega R_i / vx_i - 1. Their three unknowns (omega and the two
/// slip angles) meet three targets: each wheel's Fy and the axle's total Fx; how the axle's Fx
/// splits between the wheels follows from the spool (and the tyres' stagger).
///
/// Method: Levenberg-Marquardt on the force residuals with exact Jacobians (ceres::Jet through the
/// force model), slips kept in [-0.6, 0.6] and slip angles in [-0.5, 0.5] rad. A target outside
/// the tyre's combined-slip envelope cannot be met: the result is then the closest force the
/// model can make, flagged `reached = false`.

#include <array>

#include "hotlap/common/scalar.h"
#include "hotlap/tyre/tyre_force_model.h"
#include "hotlap/vehicle/vehicle_params.h"

namespace hotlap::vehicle {

/// One tyre's operating conditions other than its slips.
struct TyreConditions {
  double fz = 0.0;           ///< N (> 0)
  double vx = 0.0;           ///< wheel-frame longitudinal speed, m/s (> 0)
  double tread_temp = 0.0;   ///< K
  double grip_factor = 1.0;  ///< g(T) h(wear) applied to Fx, Fy
};

/// A corner's tyre ready for the inversion: its set-up and its force model cast for derivatives.
struct InvertibleTyre {
  const CornerSetup* setup = nullptr;
  tyre::TyreForceModel<Jet2> model_jet;

  explicit InvertibleTyre(const CornerSetup& corner);
};

struct WheelSlips {
  double slip_ratio = 0.0;
  double slip_angle = 0.0;  ///< rad
  double fx = 0.0;          ///< achieved, N (grip factor applied)
  double fy = 0.0;          ///< achieved, N
};

struct FreeWheelSolution {
  WheelSlips wheel;
  bool reached = false;  ///< both targets met within 1 N (or 1e-4 of the load)
  int iterations = 0;
  /// d(fx, fy) / d(slip ratio, slip angle) at the solution, row-major, N (grip factor applied).
  std::array<double, 4> jacobian{};
};

/// Slips of a free-rolling or independently braked wheel for targets (fx, fy), from the guess.
FreeWheelSolution SolveFreeWheelSlips(const InvertibleTyre& tyre, const TyreConditions& conditions,
                                      double fx_target, double fy_target, const WheelSlips& guess);

struct SpoolAxleSolution {
  std::array<WheelSlips, 2> wheels;  ///< left, right
  double wheel_speed = 0.0;          ///< common angular speed, rad/s
  bool reached = false;
  int iterations = 0;
  /// d(fy_left, fy_right, fx_left, fx_right) / d(s, alpha_left, alpha_right) at the solution,
  /// row-major (4 x 3), N; s = omega R_mean / vx_mean - 1 (R_mean, vx_mean: the two wheels'
  /// means), the slip of the mean wheel: at a given s each wheel's slip ratio depends only on the
  /// ratio of the wheels' speeds, not on the car's.
  std::array<double, 12> jacobian{};
};

/// Slips of two wheels on a spool: targets fy_left, fy_right and fx_total (sum of both Fx).
/// `guess_wheel_speed` <= 0 starts from free rolling of the mean wheel.
SpoolAxleSolution SolveSpoolAxleSlips(const InvertibleTyre& left, const InvertibleTyre& right,
                                      const TyreConditions& left_conditions,
                                      const TyreConditions& right_conditions, double fy_left,
                                      double fy_right, double fx_total,
                                      const SpoolAxleSolution& guess);

/// Free-wheel slips for targets (fx, fy) from `slips` near them, by chord steps with the Jacobian
/// of a solve nearby (FreeWheelSolution::jacobian; a fixed one, whose steps stay on its side of the
/// force peak where an updated one can cross it), each step one evaluation of the force model in
/// double precision, at most `max_steps`. True, with `slips` and its forces those that meet the
/// targets within a tenth of SolveFreeWheelSlips' tolerance (near a force peak a slip angle is only
/// loosely held by a force, and the first iterate inside a tolerance lies to one side of the
/// solution: a looser check moves a lap by milliseconds); false otherwise (`slips` then the last
/// step's, a solve's starting point). A check of a predicted solution, not a solve: it does not
/// look for the branch below the force peak.
bool RefineFreeWheelSlips(const InvertibleTyre& tyre, const TyreConditions& conditions,
                          double fx_target, double fy_target, const std::array<double, 4>& jacobian,
                          WheelSlips* slips, int max_steps = 6);

/// The same for two wheels on a spool (SolveSpoolAxleSlips' targets, a tenth of its tolerance),
/// from `axle`'s wheel speed and slip angles, with a SpoolAxleSolution::jacobian nearby updated
/// by Broyden's rule (the fixed one converges too slowly here), and false where the updated one
/// puts a wheel past its side-force peak.
bool RefineSpoolAxleSlips(const InvertibleTyre& left, const InvertibleTyre& right,
                          const TyreConditions& left_conditions,
                          const TyreConditions& right_conditions, double fy_left, double fy_right,
                          double fx_total, const std::array<double, 12>& jacobian,
                          SpoolAxleSolution* axle, int max_steps = 6);

}  // namespace hotlap::vehicle
