#include "hotlap/vehicle/vehicle_model.h"

#include <cmath>
#include <type_traits>

#include "hotlap/common/units.h"
#include "hotlap/tyre/tyre_force_model.h"

namespace hotlap::vehicle {

template <Scalar T>
AeroLoads<T> CalcAeroLoads(const AeroParams& aero, const T& u) {
  const T q = 0.5 * aero.air_density * u * u;  // dynamic pressure, Pa
  const T downforce = q * aero.downforce_area;
  return {q * aero.drag_area, downforce * aero.front_downforce_share,
          downforce * (1.0 - aero.front_downforce_share)};
}

template <Scalar T>
std::array<T, 3> CalcGravity(const RoadGeometry<T>& road, const T& heading_error) {
  using std::cos;
  using std::sin;
  // Road axes: along the tangent -g sin(phi); to the left +g sin(theta) cos(phi) (the right edge is
  // up); into the road g cos(theta) cos(phi). Body axes are turned by the heading error.
  const T along = -kGravity * sin(road.grade);
  const T left = kGravity * sin(road.bank) * cos(road.grade);
  const T c = cos(heading_error), s = sin(heading_error);
  return {along * c + left * s, -along * s + left * c, kGravity * cos(road.bank) * cos(road.grade)};
}

template <Scalar T>
std::array<T, 4> CalcNormalLoads(const VehicleParams& p, const ChassisMotion<T>& motion,
                                 const RoadGeometry<T>& road, const T& sum_fx, const T& sum_fy) {
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

template <Scalar T>
std::array<WheelKinematics<T>, 4> CalcWheelKinematics(const VehicleParams& p,
                                                      const ChassisMotion<T>& motion) {
  using std::atan;
  using std::cos;
  using std::sin;
  std::array<WheelKinematics<T>, 4> out;
  const T cs = cos(motion.steer), sn = sin(motion.steer);
  for (Corner c : kAllCorners) {
    const auto [x, y] = p.CornerPosition(c);
    // Contact-point velocity of a rigid body: (u - r y, v + r x).
    const T vx = motion.u - motion.r * y;
    const T vy = motion.v + motion.r * x;
    WheelKinematics<T>& w = out[CornerIndex(c)];
    if (IsFront(c)) {
      w.vx = vx * cs + vy * sn;
      w.vy = -vx * sn + vy * cs;
    } else {
      w.vx = vx;
      w.vy = vy;
    }
    w.slip_angle = atan(w.vy / w.vx);
  }
  return out;
}

template <Scalar T>
std::array<CornerForces<T>, 4> CalcCornerForces(const VehicleParams& p,
                                                const ChassisMotion<T>& motion,
                                                const std::array<WheelKinematics<T>, 4>& wheels,
                                                const std::array<CornerState<T>, 4>& corners) {
  using std::cos;
  using std::sin;
  const T cs = cos(motion.steer), sn = sin(motion.steer);
  std::array<CornerForces<T>, 4> out;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerSetup& setup = p.corners[i];
    tyre::TyreOperatingPoint<T> op;
    op.fz = corners[i].fz;
    op.slip_ratio = corners[i].slip_ratio;
    op.slip_angle = wheels[i].slip_angle;
    op.camber = T(setup.camber);
    op.speed = wheels[i].vx;
    op.pressure = T(setup.pressure);
    op.tread_temp = corners[i].tread_temp;
    tyre::TyreForces<T> raw;
    if constexpr (std::is_same_v<T, double>) {
      raw = tyre::CalcTyreForces(setup.forces, op);
    } else {
      // Parameters are constants here; the cast only changes their type.
      raw = tyre::CalcTyreForces(setup.forces.template Cast<T>(), op);
    }
    CornerForces<T>& f = out[i];
    f.wheel = tyre::ApplyGripFactor(raw, corners[i].grip_factor);
    f.rolling_resistance = f.wheel.my / setup.rolling_radius;
    if (IsFront(c)) {
      f.fx_body = f.wheel.fx * cs - f.wheel.fy * sn;
      f.fy_body = f.wheel.fx * sn + f.wheel.fy * cs;
    } else {
      f.fx_body = f.wheel.fx;
      f.fy_body = f.wheel.fy;
    }
  }
  return out;
}

template <Scalar T>
ChassisAccelerations<T> CalcChassisAccelerations(const VehicleParams& p,
                                                 const ChassisMotion<T>& motion,
                                                 const RoadGeometry<T>& road,
                                                 const T& heading_error,
                                                 const std::array<CornerForces<T>, 4>& forces) {
  const ChassisParams& c = p.chassis;
  T fx(0.0), fy(0.0), mz(0.0);
  for (Corner corner : kAllCorners) {
    const int i = CornerIndex(corner);
    const auto [x, y] = p.CornerPosition(corner);
    fx += forces[i].fx_body + forces[i].rolling_resistance;
    fy += forces[i].fy_body;
    mz += x * forces[i].fy_body - y * forces[i].fx_body;
  }
  const AeroLoads<T> aero = CalcAeroLoads(p.aero, motion.u);
  const std::array<T, 3> g = CalcGravity(road, heading_error);
  ChassisAccelerations<T> a;
  a.du = (fx - aero.drag) / c.mass + g[0] + motion.v * motion.r;
  a.dv = fy / c.mass + g[1] - motion.u * motion.r;
  a.dr = mz / c.yaw_inertia;
  return a;
}

#define HOTLAP_INSTANTIATE(T)                                                                  \
  template AeroLoads<T> CalcAeroLoads<T>(const AeroParams&, const T&);                         \
  template std::array<T, 3> CalcGravity<T>(const RoadGeometry<T>&, const T&);                  \
  template std::array<T, 4> CalcNormalLoads<T>(const VehicleParams&, const ChassisMotion<T>&,  \
                                               const RoadGeometry<T>&, const T&, const T&);    \
  template std::array<WheelKinematics<T>, 4> CalcWheelKinematics<T>(const VehicleParams&,      \
                                                                    const ChassisMotion<T>&);  \
  template std::array<CornerForces<T>, 4> CalcCornerForces<T>(                                 \
      const VehicleParams&, const ChassisMotion<T>&, const std::array<WheelKinematics<T>, 4>&, \
      const std::array<CornerState<T>, 4>&);                                                   \
  template ChassisAccelerations<T> CalcChassisAccelerations<T>(                                \
      const VehicleParams&, const ChassisMotion<T>&, const RoadGeometry<T>&, const T&,         \
      const std::array<CornerForces<T>, 4>&);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE)
#undef HOTLAP_INSTANTIATE

}  // namespace hotlap::vehicle
