#pragma once
/// @file
/// The slips one point of the quasi-steady-state lap needs (sim/qss_lap.h, step 3): each front
/// wheel's solve and the rear axle's on the spool (vehicle/slip_inversion.h), and their
/// first-order update to nearby target forces, which the cornering drag's fixed point uses for
/// every profile of a pass after the first (the profiles differ by millimetres per second, so a
/// solve's Jacobian carries the slips to the next profile's forces to well within the solve's own
/// tolerance, 1 N, at no cost in tyre-model evaluations).

#include <array>
#include <span>

#include "hotlap/vehicle/slip_inversion.h"

namespace hotlap::sim {

/// What the four tyres must make at a point: conditions (load, wheel speed, tread temperature,
/// grip) and target forces per corner (CornerIndex); the rear wheels' Fx targets only as a sum.
struct PointTargets {
  std::array<vehicle::TyreConditions, 4> conditions;
  std::array<double, 4> fx{}, fy{};  ///< N
};

/// The slips that make a point's target forces, and what their first-order update needs; per unit
/// (kFrontLeftUnit, kFrontRightUnit, kRearAxleUnit: each front wheel, the rear wheels on the
/// spool).
struct PointSlips {
  static constexpr int kFrontLeftUnit = 0, kFrontRightUnit = 1, kRearAxleUnit = 2;

  std::array<vehicle::WheelSlips, 4> wheels;  ///< per corner (CornerIndex)
  double rear_wheel_speed = 0.0;              ///< the spool's, rad/s
  std::array<bool, 3> reached{};  ///< every target met (vehicle/slip_inversion.h), per unit
  std::array<bool, 3> solved{};   ///< by a solve here (false: updated from one, or none yet)
  double force_deficit = 0.0;     ///< N, the largest shortfall of a target
  /// The solves' Jacobians (FreeWheelSolution, SpoolAxleSolution) and loads, N.
  std::array<std::array<double, 4>, 2> front_jacobian{};
  std::array<double, 12> rear_jacobian{};
  std::array<double, 4> fz{};

  bool Reached() const { return reached[0] && reached[1] && reached[2]; }
};

/// Solves a point's slips, each wheel from `guess`'s (the last point's, along the lap).
PointSlips SolvePointSlips(std::span<const vehicle::InvertibleTyre> tyres,
                           const PointTargets& targets, const PointSlips& guess);

/// A point's slips at `targets` from `base`, solved at nearby targets, to first order: each unit's
/// slips move by the inverse of its solve's Jacobian times the change of its targets less the
/// change its loads make at fixed slips (the forces taken in proportion to the load there). A unit
/// whose step is not small (a slip moving by more than 1e-3), or whose base was no solve, missed
/// its targets or lies past a force peak, is solved instead, from the step's slips, and replaces
/// its part of `base`.
PointSlips UpdatePointSlips(std::span<const vehicle::InvertibleTyre> tyres,
                            const PointTargets& targets, PointSlips& base);

}  // namespace hotlap::sim
