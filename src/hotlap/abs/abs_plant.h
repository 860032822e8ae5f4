#pragma once
/// @file
/// The plant an ABS controller brakes: one wheel on the road, with its spin, the tyre's
/// longitudinal force with a relaxation length, the brake hydraulics, and the vehicle either free
/// (quarter car, m = Fz/g) or held at constant speed (drum); spec section 8, docs/abs.md.
///
/// Axes and signs (tyre_force.h, spec section 0): x forward; Fx < 0 brakes; omega > 0 rolls
/// forward; My < 0 resists forward rolling; the brake torque T_b >= 0 opposes the spin.
///
///   dx/dt      = Vx
///   m dVx/dt   = Fx                       (free; drum: dVx/dt = 0)
///   J domega/dt = -R_l Fx + My - T_b      (Fx < 0 spins the wheel up; the brake slows it)
///   dkappa'/dt = (R_l omega - Vx - |Vx| kappa') / sigma     (transient slip, relaxation length)
///   dp/dt      = hydraulics (brake_hydraulics.h),  T_b = k_T p
///
/// Fx and My come from the tyre force model at the transient slip kappa' on a road of friction
/// mu(v_s), v_s = |Vx kappa'| (abs_surface.h): the model's own friction is scaled by
/// mu(v_s) / mu_ref (CalcAbsTyreForces). My adds c_rr Fz R_l of rolling resistance to the model's
/// own (the brush model has none).
///
/// Locked wheel: T_b is a friction torque, so a stopped wheel stays stopped while the brake can
/// hold it, |-R_l Fx + My| <= T_b (WheelMode::kLocked: domega/dt = 0, no brake power). The run
/// (abs_run.h) switches modes where omega reaches zero and where the holding torque passes the
/// brake's capacity, locating both events inside the step.
///
/// Energy: the state integrates the powers, so that the kinetic energy lost plus the drum's work
/// equals brake heat plus tyre slip heat plus rolling resistance, at the integrator's accuracy:
///   d/dt(m Vx^2/2 + J omega^2/2) = -T_b omega + Fx (Vx - R_l omega) + My omega  (free mode).

#include "hotlap/abs/abs_surface.h"
#include "hotlap/brake/brake_hydraulics.h"
#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/tyre_force_model.h"

namespace hotlap::sim {

/// Whether the vehicle decelerates (quarter car) or is held at its speed (drum, as a test rig).
enum class AbsVehicleMode { kFree, kDrum };

/// Whether the wheel spins or is held stopped by the brake.
enum class WheelMode { kRolling, kLocked };

/// The wheel and its share of the vehicle. SI units.
template <Scalar T>
struct AbsWheelParams {
  T vertical_load{};       ///< Fz, N (> 0)
  T mass{};                ///< m, kg: the quarter car, Fz / g
  T inertia{};             ///< J, kg m^2: wheel, tyre, hub and disc about the spin axis
  T radius{};              ///< R_l, m: loaded radius (slip, brake-torque arm)
  T relaxation_length{};   ///< sigma_kappa, m (> 0)
  T rolling_resistance{};  ///< c_rr, 1: rolling-resistance moment c_rr Fz R_l beyond the model's
  T tread_temp{};          ///< K, for the temperature-dependent force models
  T reference_friction{};  ///< mu_ref, 1: friction of the road the tyre file describes

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.vertical_load, s.mass, s.inertia, s.radius, s.relaxation_length,
                    s.rolling_resistance, s.tread_temp, s.reference_friction);
  }
  template <Scalar U>
  AbsWheelParams<U> Cast() const {
    AbsWheelParams<U> out;
    CastFields(*this, out);
    return out;
  }
};

/// The plant's constant parts.
template <Scalar T>
struct AbsPlantModel {
  AbsWheelParams<T> wheel;
  tyre::TyreForceModel<T> tyre;
  brake::BrakeHydraulicsParams<T> hydraulics;

  template <Scalar U>
  AbsPlantModel<U> Cast() const {
    return {wheel.template Cast<U>(), tyre.template Cast<U>(), hydraulics.template Cast<U>()};
  }
};

/// The integrated state (and, from CalcAbsPlantDerivatives, its time derivative).
template <Scalar T>
struct AbsPlantState {
  T distance{};        ///< x, m
  T speed{};           ///< Vx, m/s
  T wheel_speed{};     ///< omega, rad/s
  T slip{};            ///< transient slip kappa', 1 (< 0 braking)
  T pressure{};        ///< wheel-cylinder pressure p, Pa
  T brake_energy{};    ///< integral of T_b omega, J: heat into the brake
  T slip_energy{};     ///< integral of -Fx (Vx - R_l omega), J: tyre slip heat
  T rolling_energy{};  ///< integral of -My omega, J: rolling resistance
  T drum_energy{};     ///< integral of -Fx Vx in drum mode, J: work the drum does

  friend AbsPlantState operator+(const AbsPlantState& a, const AbsPlantState& b) {
    return {a.distance + b.distance,       a.speed + b.speed,
            a.wheel_speed + b.wheel_speed, a.slip + b.slip,
            a.pressure + b.pressure,       a.brake_energy + b.brake_energy,
            a.slip_energy + b.slip_energy, a.rolling_energy + b.rolling_energy,
            a.drum_energy + b.drum_energy};
  }
  friend AbsPlantState operator*(double k, const AbsPlantState& a) {
    return {k * a.distance,    k * a.speed,          k * a.wheel_speed,
            k * a.slip,        k * a.pressure,       k * a.brake_energy,
            k * a.slip_energy, k * a.rolling_energy, k * a.drum_energy};
  }
};

/// What is held constant over an integration step.
template <Scalar T>
struct AbsPlantInput {
  T pressure_target{};  ///< the delayed pressure target, Pa
  FrictionLaw<T> road;  ///< the friction law under the tyre
  AbsVehicleMode vehicle = AbsVehicleMode::kFree;
  WheelMode wheel = WheelMode::kRolling;
};

/// Quantities computed on the way, for records and event detection.
template <Scalar T>
struct AbsPlantOutputs {
  T fx{};              ///< tyre longitudinal force, N (< 0 braking)
  T my{};              ///< rolling-resistance moment, model's plus c_rr Fz R_l, N m (< 0)
  T friction{};        ///< road friction mu(v_s), 1
  T slip_speed{};      ///< v_s = |Vx kappa'|, m/s
  T brake_capacity{};  ///< k_T p, N m
  T brake_torque{};    ///< torque the brake applies against forward spin, N m
  T holding_torque{};  ///< -R_l Fx + My: what the brake must hold on a stopped wheel, N m
  T brake_power{};     ///< T_b omega, W
  T slip_power{};      ///< -Fx (Vx - R_l omega), W
  T rolling_power{};   ///< -My omega, W
  T drum_power{};      ///< -Fx Vx in drum mode, W
};

/// Tyre forces at `op` on a road whose friction is `friction_scale` times the reference road's:
/// Magic Formula LMUX, the brush model's `friction` and UniTire's `friction_x` and `friction_y`
/// are multiplied by it, so the peak scales and the slip stiffness stays (Pacejka 2012 §4.3.2 for
/// LMUX).
template <Scalar T>
tyre::TyreForces<T> CalcAbsTyreForces(const tyre::TyreForceModel<T>& tyre,
                                      const tyre::TyreOperatingPoint<T>& op,
                                      const T& friction_scale);

/// Time derivative of the plant state (the file comment's equations). If `outputs` is given,
/// the intermediate quantities are written there.
template <Scalar T>
AbsPlantState<T> CalcAbsPlantDerivatives(const AbsPlantModel<T>& model,
                                         const AbsPlantState<T>& state,
                                         const AbsPlantInput<T>& input,
                                         AbsPlantOutputs<T>* outputs = nullptr);

/// Kinetic energy of the quarter car and the wheel, m Vx^2 / 2 + J omega^2 / 2, J.
template <Scalar T>
T CalcAbsKineticEnergy(const AbsWheelParams<T>& wheel, const AbsPlantState<T>& state) {
  return 0.5 * wheel.mass * state.speed * state.speed +
         0.5 * wheel.inertia * state.wheel_speed * state.wheel_speed;
}

}  // namespace hotlap::sim
