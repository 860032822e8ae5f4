#pragma once
/// @file
/// The operating point and the result shared by every steady-state tyre force model (Magic
/// Formula, brush, UniTire), so that the vehicle model, the ABS plant and the commands can use
/// any of them.
///
/// Axes and signs (ISO 8855 and TYDEX/ISO-W agree here, see docs/tyre-forces.md): the wheel frame
/// has x forward along the wheel's heading, y to the left, z up, origin at the contact point.
/// - `slip_ratio` kappa = (r_e omega - V_x) / |V_x|: positive drives, negative brakes.
/// - `slip_angle` alpha = atan(V_y / |V_x|) of the contact point: a positive slip angle (the
///   wheel moving to its left) gives a negative (rightward) Fy.
/// - `camber` is the inclination angle, a right-handed rotation about x: positive when the top of
///   the wheel leans to the right (-y); the camber thrust then pushes to the right (Fy < 0 for the
///   usual PKY6 < 0; mfeval's oracle: gamma = +3 deg at alpha = 0 gives Fy = -429 N). On a car,
///   tops leaning inboard ("negative camber") is gamma > 0 on the left wheels and gamma < 0 on the
///   right; an oval set-up leaning every top into the left turns has gamma < 0 on all four.
/// - Fz > 0 is the load pressing the tyre onto the road; forces are those of the road on the
///   tyre; Mx, My, Mz are about x, y, z at the contact point (My < 0 resists forward rolling).

#include "hotlap/common/scalar.h"

namespace hotlap::tyre {

/// Where a tyre operates. SI units: N, rad, m/s, Pa, K.
template <Scalar T>
struct TyreOperatingPoint {
  T fz{};          ///< vertical load, N (> 0 in contact)
  T slip_ratio{};  ///< kappa, 1 (see the file comment)
  T slip_angle{};  ///< alpha, rad
  T camber{};      ///< inclination gamma, rad
  T speed{};       ///< longitudinal speed of the wheel centre V_x, m/s (> 0 forward)
  T pressure{};    ///< inflation pressure, Pa; 0 means the model's nominal pressure
  T tread_temp{};  ///< tread temperature, K (used by the temperature-dependent models)
};

/// Forces and moments of the road on the tyre at the contact point, wheel axes. N and N m.
template <Scalar T>
struct TyreForces {
  T fx{};  ///< longitudinal force, N (> 0 drives)
  T fy{};  ///< lateral force, N (> 0 to the left)
  T mx{};  ///< overturning moment, N m
  T my{};  ///< rolling-resistance moment, N m
  T mz{};  ///< aligning moment, N m
};

}  // namespace hotlap::tyre
