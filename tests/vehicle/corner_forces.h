#pragma once
// The forces a corner's tyre model makes at given slips under given conditions (grip factor
// applied), evaluated directly in double: the tests' reference for the slip solvers.

#include <utility>

#include "hotlap/tyre/tyre_force_model.h"
#include "hotlap/vehicle/slip_inversion.h"

namespace hotlap::vehicle::testing {

inline std::pair<double, double> CornerForces(const CornerSetup& s, const TyreConditions& c,
                                              double kappa, double alpha) {
  tyre::TyreOperatingPoint<double> op;
  op.fz = c.fz;
  op.slip_ratio = kappa;
  op.slip_angle = alpha;
  op.camber = s.camber;
  op.speed = c.vx;
  op.pressure = s.pressure;
  op.tread_temp = c.tread_temp;
  const tyre::TyreForces<double> f = tyre::CalcTyreForces(s.forces, op);
  return {c.grip_factor * f.fx, c.grip_factor * f.fy};
}

}  // namespace hotlap::vehicle::testing
