#include "hotlap/vehicle/vehicle_model.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "hotlap/common/units.h"
#include "hotlap/tyre/tyre_force_model.h"

namespace hotlap::vehicle {

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

double CalcFreeRollingCoefficient(const CornerSetup& setup, double fz) {
  tyre::TyreOperatingPoint<double> op;
  op.fz = fz;
  op.camber = setup.camber;
  op.speed = 50.0;
  op.pressure = setup.pressure;
  const double my = tyre::CalcTyreForces(setup.forces, op).my;
  return std::max(0.0, -my / (setup.rolling_radius * fz));
}

template <Scalar T>
ChassisAccelerations<T> CalcChassisAccelerations(const VehicleParams& p,
                                                 const ChassisMotion<T>& motion,
                                                 const RoadGeometry<T>& road,
                                                 const T& heading_error,
                                                 const std::array<CornerForces<T>, 4>& forces) {
  T fx(0.0), fy(0.0), mz(0.0);
  for (Corner corner : kAllCorners) {
    const int i = CornerIndex(corner);
    const auto [x, y] = p.CornerPosition(corner);
    fx += forces[i].fx_body + forces[i].rolling_resistance;
    fy += forces[i].fy_body;
    mz += x * forces[i].fy_body - y * forces[i].fx_body;
  }
  return CalcChassisAccelerationsFromTotals(p, motion, road, heading_error, fx, fy, mz);
}

#define HOTLAP_INSTANTIATE(T)                                                                  \
  template std::array<CornerForces<T>, 4> CalcCornerForces<T>(                                 \
      const VehicleParams&, const ChassisMotion<T>&, const std::array<WheelKinematics<T>, 4>&, \
      const std::array<CornerState<T>, 4>&);                                                   \
  template ChassisAccelerations<T> CalcChassisAccelerations<T>(                                \
      const VehicleParams&, const ChassisMotion<T>&, const RoadGeometry<T>&, const T&,         \
      const std::array<CornerForces<T>, 4>&);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE)
#undef HOTLAP_INSTANTIATE

}  // namespace hotlap::vehicle
