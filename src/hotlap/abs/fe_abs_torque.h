#pragma once
/// @file
/// The brake torque of the FE tyre's ABS stop (docs/fe-tyre.md): the ABS controller of
/// `hotlap abs` (brake/abs_controller.h), its hydraulic delay line and the wheel-cylinder
/// pressure, stepped at the controller's period inside the FE braking step
/// (fe::TyreRun::Brake calls it before every FE step), with what a checkpoint needs.
///
///   sim::FeAbsTorque torque(abs_config, controller_params);  // wheel_radius_m: R_l
///   run.Brake(duration, [&](double t, double vx, double spin) { return torque(t, vx, spin); },
///             hooks);

#include <deque>
#include <optional>
#include <vector>

#include "hotlap/abs/abs_config.h"
#include "hotlap/brake/abs_controller.h"
#include "hotlap/brake/brake_hydraulics.h"
#include "hotlap/brake/wheel_speed_filter.h"
#include "hotlap/fe/checkpoint.h"

namespace hotlap::sim {

/// The ABS controller, its hydraulic delay line and the wheel-cylinder pressure.
class FeAbsTorque {
 public:
  /// Keeps a reference to `config`. `params` is config.controller with the wheel radius the
  /// slip uses (the FE tyre's free-rolling radius, (002:2)).
  FeAbsTorque(const AbsConfig& config, const brake::AbsControllerParams& params)
      : config_(config),
        params_(params),
        delay_(config.DelayTicks(), 0.0),
        filter_(config.wheel_speed_filter, params.period_s) {}

  /// Brake torque capacity at brake-step time t (s from the braking step's start), given the
  /// rim's forward speed vx (m/s) and spin (rad/s), N m. Calls must not go back in time.
  ///
  /// The wheel-speed sensor: at each tick the controller reads the means of spin and vx over
  /// the period since the last tick (the sums of the values passed, each times the time since
  /// the call before), as a toothed-wheel sensor counts teeth over its period (issue 27): a
  /// sample of the instantaneous spin would see wherever the contact's high-frequency ripple
  /// (facets passing, 300-400 Hz at 11 m/s on a 5 deg mesh) happens to be at that FE step,
  /// which the time step moves. The first tick, with no period behind it, reads the values.
  /// The spin read then passes the ABS file's wheel-speed filter (brake/wheel_speed_filter.h).
  double operator()(double t, double vx, double spin);

  const brake::AbsControllerState& state() const { return state_; }
  /// Brake-step times (s from the braking step's start) of the controller's ticks that began a
  /// control cycle (a pressure release, as the lumped `hotlap abs` counts them).
  const std::vector<double>& cycle_starts() const { return cycle_starts_; }
  /// Brake-step time of the first tick in kExit (the ABS handing back to the driver), if any.
  std::optional<double> abs_exit() const { return abs_exit_; }

  /// Writes the controller's state, the pending commands, the pressure, the next tick, the cycle
  /// starts, the exit and the wheel-speed filter's state (section "ABS_").
  void Save(fe::BinaryWriter& w) const;
  /// Reads what Save wrote; InputError (via the reader) if it is damaged or does not fit the
  /// configuration's delay line. Nothing changes unless everything was read.
  void Load(fe::BinaryReader& r);

 private:
  double Push(double command);

  const AbsConfig& config_;
  brake::AbsControllerParams params_;
  brake::AbsControllerState state_;
  brake::PressureDelayLine delay_;
  brake::WheelSpeedFilter filter_;
  std::deque<double> pushed_;  // the last delay_ticks commands pushed, oldest first
  std::vector<double> cycle_starts_;
  std::optional<double> abs_exit_;
  double next_tick_ = 0.0, target_ = 0.0, pressure_ = 0.0, t_prev_ = 0.0;
  double spin_sum_ = 0.0, vx_sum_ = 0.0, window_ = 0.0;  // the sensor's sums since the last tick
};

}  // namespace hotlap::sim
