#include "hotlap/abs/abs_plant.h"

#include <cmath>
#include <type_traits>
#include <variant>

namespace hotlap::sim {

template <Scalar T>
tyre::TyreForces<T> CalcAbsTyreForces(const tyre::TyreForceModel<T>& tyre,
                                      const tyre::TyreOperatingPoint<T>& op,
                                      const T& friction_scale) {
  return std::visit(
      [&](const auto& p) -> tyre::TyreForces<T> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, tyre::MagicFormulaModel<T>>) {
          // Copy-and-scale keeps the loaded model untouched; the copy is ~1.5 kB for double.
          tyre::MagicFormulaParams<T> scaled = p.params;
          scaled.LMUX = p.params.LMUX * friction_scale;
          return tyre::CalcMagicFormula(scaled, op, p.options);
        } else if constexpr (std::is_same_v<P, tyre::BrushParams<T>>) {
          tyre::BrushParams<T> scaled = p;
          scaled.friction = p.friction * friction_scale;
          return tyre::CalcBrushForces(scaled, op);
        } else {
          tyre::UniTireParams<T> scaled = p;
          scaled.friction_x = p.friction_x * friction_scale;
          scaled.friction_y = p.friction_y * friction_scale;
          return tyre::CalcUniTireForces(scaled, op);
        }
      },
      tyre.params);
}

template <Scalar T>
AbsPlantState<T> CalcAbsPlantDerivatives(const AbsPlantModel<T>& model, const AbsPlantState<T>& x,
                                         const AbsPlantInput<T>& in, AbsPlantOutputs<T>* outputs) {
  using std::abs;
  const AbsWheelParams<T>& w = model.wheel;
  const bool rolling = in.wheel == WheelMode::kRolling;

  // The road: friction at the slip speed the transient slip stands for (002:1).
  const T slip_speed = abs(x.speed * x.slip);
  const T friction = in.road.Friction(slip_speed);

  // The tyre at the transient slip, its friction scaled to this road.
  tyre::TyreOperatingPoint<T> op;
  op.fz = w.vertical_load;
  op.slip_ratio = x.slip;
  op.speed = x.speed;
  op.tread_temp = w.tread_temp;
  const tyre::TyreForces<T> f =
      CalcAbsTyreForces(model.tyre, op, T(friction / w.reference_friction));
  // Rolling resistance beyond the model's own acts only while the wheel turns.
  const T my = rolling ? T(f.my - w.rolling_resistance * w.vertical_load * w.radius) : f.my;

  // The wheel: the brake's friction torque opposes the spin; a stopped wheel is held.
  const T capacity = brake::CalcBrakeTorqueCapacity(model.hydraulics, x.pressure);
  const T holding = -w.radius * f.fx + my;
  const T brake_torque = rolling ? capacity : holding;

  AbsPlantState<T> d;
  d.distance = x.speed;
  d.speed = in.vehicle == AbsVehicleMode::kFree ? T(f.fx / w.mass) : T(0.0);
  d.wheel_speed = rolling ? T((holding - capacity) / w.inertia) : T(0.0);
  d.slip = (w.radius * x.wheel_speed - x.speed - abs(x.speed) * x.slip) / w.relaxation_length;
  d.pressure = brake::CalcPressureRate(model.hydraulics, x.pressure, in.pressure_target);
  // Powers (zero spin when locked, so no brake or rolling power there).
  d.brake_energy = rolling ? T(capacity * x.wheel_speed) : T(0.0);
  d.slip_energy = -f.fx * (x.speed - w.radius * x.wheel_speed);
  d.rolling_energy = rolling ? T(-my * x.wheel_speed) : T(0.0);
  d.drum_energy = in.vehicle == AbsVehicleMode::kDrum ? T(-f.fx * x.speed) : T(0.0);

  if (outputs != nullptr) {
    outputs->fx = f.fx;
    outputs->my = my;
    outputs->friction = friction;
    outputs->slip_speed = slip_speed;
    outputs->brake_capacity = capacity;
    outputs->brake_torque = brake_torque;
    outputs->holding_torque = holding;
    outputs->brake_power = d.brake_energy;
    outputs->slip_power = d.slip_energy;
    outputs->rolling_power = d.rolling_energy;
    outputs->drum_power = d.drum_energy;
  }
  return d;
}

#define HOTLAP_INSTANTIATE_ABS_PLANT(T)                                                            \
  template tyre::TyreForces<T> CalcAbsTyreForces<T>(const tyre::TyreForceModel<T>&,                \
                                                    const tyre::TyreOperatingPoint<T>&, const T&); \
  template AbsPlantState<T> CalcAbsPlantDerivatives<T>(                                            \
      const AbsPlantModel<T>&, const AbsPlantState<T>&, const AbsPlantInput<T>&,                   \
      AbsPlantOutputs<T>*);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_ABS_PLANT)

}  // namespace hotlap::sim
