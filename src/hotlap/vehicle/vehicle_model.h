#pragma once
/// @file
/// The vehicle model shared by the quasi-steady-state lap (sim/qss_lap.h) and the optimal-control
/// problem: a rigid chassis moving in the plane of a banked, graded road, with aerodynamic loads,
/// quasi-static longitudinal and lateral load transfer (roll stiffness split per axle), and four
/// tyres whose forces come from each corner's tyre force model scaled by g(T_tread) h(wear).
///
/// How to use: per evaluation, build a ChassisMotion (speeds, yaw rate, steer) and a RoadGeometry
/// (bank, grade and normal curvature under the car), then
///   CalcNormalLoads(...)     -> per-corner Fz from the total tyre forces (load transfer),
///   CalcWheelKinematics(...) -> per-corner wheel-frame velocity and slip angle,
///   CalcCornerForces(...)    -> per-corner tyre forces in wheel and body axes,
///   CalcChassisAccelerations -> du/dt, dv/dt, dr/dt.
/// The load transfer depends on the tyre forces, which depend on the loads: the QSS lap knows the
/// forces it needs and evaluates the loads directly; the optimal-control problem carries the
/// loads as variables and CalcNormalLoads as constraints.
///
/// Axes and signs (ISO 8855, spec section 10): body x forward, y left, z up; yaw rate r > 0 turning
/// left. Bank theta > 0 raises the right edge (an anticlockwise oval's outside), so gravity pulls
/// the car to the left by g sin(theta); grade phi > 0 climbs. On a banked turn the tyres must make
/// sum Fy = m u^2 kappa_g - m g sin(theta), and the road carries
/// sum Fz = m g cos(theta) + m u^2 kappa_n + downforce (spec section 10).
///
/// Every function is templated on the scalar (double, ceres::Jet, the optimal-control AD type);
/// the parameters stay double.

#include <array>
#include <cmath>

#include "hotlap/common/scalar.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/tyre_force.h"
#include "hotlap/vehicle/vehicle_params.h"

namespace hotlap::vehicle {

/// The road under the car.
template <Scalar T>
struct RoadGeometry {
  T bank{};              ///< theta, rad (> 0: right edge up)
  T grade{};             ///< phi, rad (> 0: uphill)
  T normal_curvature{};  ///< kappa_n of the car's path, 1/m (> 0 presses the car onto the road)
};

/// The chassis' motion in body axes.
template <Scalar T>
struct ChassisMotion {
  T u{};      ///< longitudinal speed, m/s (> 0)
  T v{};      ///< lateral speed, m/s (> 0 to the left)
  T r{};      ///< yaw rate, rad/s (> 0 turning left)
  T steer{};  ///< road-wheel steer angle of both front wheels, rad (> 0 to the left)
};

/// Aerodynamic loads at longitudinal speed u.
template <Scalar T>
struct AeroLoads {
  T drag{};             ///< N, opposing motion (acts along -x)
  T downforce_front{};  ///< N, pressing the front axle down
  T downforce_rear{};   ///< N
};

template <Scalar T>
inline AeroLoads<T> CalcAeroLoads(const AeroParams& aero, const T& u) {
  const T q = 0.5 * aero.air_density * u * u;  // dynamic pressure, Pa
  const T downforce = q * aero.downforce_area;
  return {q * aero.drag_area, downforce * aero.front_downforce_share,
          downforce * (1.0 - aero.front_downforce_share)};
}

/// Gravity in body axes, per unit mass, m/s^2, for a car whose heading is `heading_error` rad from
/// the road's tangent (positive to the left): x and y in the road plane, z the component pressing
/// the car onto the road (g cos(theta) cos(phi) > 0).
template <Scalar T>
inline std::array<T, 3> CalcGravity(const RoadGeometry<T>& road, const T& heading_error) {
  using std::cos;
  using std::sin;
  // Road axes: along the tangent -g sin(phi); to the left +g sin(theta) cos(phi) (the right edge is
  // up); into the road g cos(theta) cos(phi). Body axes are turned by the heading error.
  const T along = -kGravity * sin(road.grade);
  const T left = kGravity * sin(road.bank) * cos(road.grade);
  const T c = cos(heading_error), s = sin(heading_error);
  return {along * c + left * s, -along * s + left * c, kGravity * cos(road.bank) * cos(road.grade)};
}

/// Quasi-static normal loads, N, indexed by CornerIndex, from the total tyre forces in body axes
/// (`sum_fx`, `sum_fy`; drag and inertia act at the centre of gravity):
///   Z      = m (g cos(theta) cos(phi) + (u^2 + v^2) kappa_n)      split statically per corner,
///   front += downforce_front - h sum_fx / L,  rear += downforce_rear + h sum_fx / L,
///   left  -= share_axle h sum_fy / track_axle, right += the same (roll stiffness split),
/// downforce shared equally left and right.
template <Scalar T>
inline std::array<T, 4> CalcNormalLoads(const VehicleParams& p, const ChassisMotion<T>& motion,
                                        const RoadGeometry<T>& road, const T& sum_fx,
                                        const T& sum_fy) {
  using std::cos;
  const ChassisParams& c = p.chassis;
  const T speed2 = motion.u * motion.u + motion.v * motion.v;
  // Weight and the centripetal load of the road's normal curvature, both at the CoG.
  const T z =
      c.mass * (kGravity * cos(road.bank) * cos(road.grade) + speed2 * road.normal_curvature);
  const AeroLoads<T> aero = CalcAeroLoads(p.aero, motion.u);
  const double f = c.front_weight_fraction, l = c.left_weight_fraction;
  const T pitch = c.cog_height * sum_fx / c.wheelbase;  // to the rear when driving
  const T front = z * f + aero.downforce_front - pitch;
  const T rear = z * (1.0 - f) + aero.downforce_rear + pitch;
  // Lateral transfer: the d'Alembert force -sum_fy at the CoG height rolls the car; each axle
  // takes its roll-stiffness share. The static left-side weight follows the same split.
  const T roll = c.cog_height * sum_fy;
  const T front_left_shift = c.roll_stiffness_front_share * roll / c.track_front;
  const T rear_left_shift = (1.0 - c.roll_stiffness_front_share) * roll / c.track_rear;
  const T zf = z * f, zr = z * (1.0 - f);
  std::array<T, 4> fz;
  fz[CornerIndex(Corner::kFrontLeft)] = zf * l + 0.5 * (front - zf) - front_left_shift;
  fz[CornerIndex(Corner::kFrontRight)] = zf * (1.0 - l) + 0.5 * (front - zf) + front_left_shift;
  fz[CornerIndex(Corner::kRearLeft)] = zr * l + 0.5 * (rear - zr) - rear_left_shift;
  fz[CornerIndex(Corner::kRearRight)] = zr * (1.0 - l) + 0.5 * (rear - zr) + rear_left_shift;
  return fz;
}

/// One wheel's velocity in its own axes and its slip angle.
template <Scalar T>
struct WheelKinematics {
  T vx{};          ///< m/s along the wheel's heading
  T vy{};          ///< m/s to the wheel's left
  T slip_angle{};  ///< atan(vy / vx), rad (ISO-W: > 0 gives Fy < 0)
};

template <Scalar T>
inline WheelKinematics<T> CalcCornerKinematics(const VehicleParams& p,
                                               const ChassisMotion<T>& motion, Corner c) {
  using std::atan;
  using std::cos;
  using std::sin;
  const auto [x, y] = p.CornerPosition(c);
  // Contact-point velocity of a rigid body: (u - r y, v + r x), turned by the steer at the front.
  const T vx = motion.u - motion.r * y;
  const T vy = motion.v + motion.r * x;
  WheelKinematics<T> w;
  if (IsFront(c)) {
    const T cs = cos(motion.steer), sn = sin(motion.steer);
    w.vx = vx * cs + vy * sn;
    w.vy = -vx * sn + vy * cs;
  } else {
    w.vx = vx;
    w.vy = vy;
  }
  w.slip_angle = atan(w.vy / w.vx);
  return w;
}

template <Scalar T>
inline std::array<WheelKinematics<T>, 4> CalcWheelKinematics(const VehicleParams& p,
                                                             const ChassisMotion<T>& motion) {
  std::array<WheelKinematics<T>, 4> out;
  for (Corner c : kAllCorners) out[CornerIndex(c)] = CalcCornerKinematics(p, motion, c);
  return out;
}

/// One corner's tyre forces.
template <Scalar T>
struct CornerForces {
  tyre::TyreForces<T> wheel;  ///< in wheel axes, already scaled by the grip factor
  T fx_body{};                ///< N, body x
  T fy_body{};                ///< N, body y
  T rolling_resistance{};     ///< N along body x (< 0 rolling forward): -My / rolling radius
};

/// What each tyre needs besides the chassis motion.
template <Scalar T>
struct CornerState {
  T fz{};           ///< N
  T slip_ratio{};   ///< kappa
  T tread_temp{};   ///< K (only the temperature-dependent force models use it)
  T grip_factor{};  ///< g(T_t) h(wear) of the corner's compound, 1
};

/// Tyre forces of every corner: each corner's force model at (Fz, kappa, its slip angle, camber,
/// wheel speed, pressure), Fx, Fy and Mz scaled by the grip factor, front forces turned through
/// the steer angle into body axes.
template <Scalar T>
std::array<CornerForces<T>, 4> CalcCornerForces(const VehicleParams& p,
                                                const ChassisMotion<T>& motion,
                                                const std::array<WheelKinematics<T>, 4>& wheels,
                                                const std::array<CornerState<T>, 4>& corners);

/// The free-rolling resistance coefficient -My / (R Fz) of a corner's force model at load `fz`
/// (N), zero slip, 50 m/s and the set-up's pressure and camber; at least 0.
double CalcFreeRollingCoefficient(const CornerSetup& setup, double fz);

/// Body-axis accelerations of the planar chassis:
///   du/dt = (sum Fx + rolling resistance - drag) / m + g_x + v r
///   dv/dt = sum Fy / m + g_y - u r
///   dr/dt = sum (x_i Fy_i - y_i Fx_i) / I_z
template <Scalar T>
struct ChassisAccelerations {
  T du{};
  T dv{};
  T dr{};
};

/// The same from the totals: `sum_fx` the body-x tyre forces including rolling resistance,
/// `sum_fy` the body-y tyre forces, `yaw_moment` their moment about the CoG.
template <Scalar T>
inline ChassisAccelerations<T> CalcChassisAccelerationsFromTotals(
    const VehicleParams& p, const ChassisMotion<T>& motion, const RoadGeometry<T>& road,
    const T& heading_error, const T& sum_fx, const T& sum_fy, const T& yaw_moment) {
  const ChassisParams& c = p.chassis;
  const AeroLoads<T> aero = CalcAeroLoads(p.aero, motion.u);
  const std::array<T, 3> g = CalcGravity(road, heading_error);
  ChassisAccelerations<T> a;
  a.du = (sum_fx - aero.drag) / c.mass + g[0] + motion.v * motion.r;
  a.dv = sum_fy / c.mass + g[1] - motion.u * motion.r;
  a.dr = yaw_moment / c.yaw_inertia;
  return a;
}

/// A front wheel's forces turned through the steer angle into body axes: (fx_body, fy_body).
template <Scalar T>
inline std::array<T, 2> SteeredToBody(const T& steer, const T& fx, const T& fy) {
  using std::cos;
  using std::sin;
  const T cs = cos(steer), sn = sin(steer);
  return {fx * cs - fy * sn, fx * sn + fy * cs};
}

template <Scalar T>
ChassisAccelerations<T> CalcChassisAccelerations(const VehicleParams& p,
                                                 const ChassisMotion<T>& motion,
                                                 const RoadGeometry<T>& road,
                                                 const T& heading_error,
                                                 const std::array<CornerForces<T>, 4>& forces);

}  // namespace hotlap::vehicle
