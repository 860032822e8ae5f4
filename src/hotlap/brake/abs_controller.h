#pragma once
/// @file
/// The ABS controller of the FE/ABS paper (002 §2.2) as an explicit state machine with the paper's
/// eight states, its logic that of the Bosch control cycle (spec section 8, docs/abs.md).
///
/// How to use: fill AbsControllerParams (or read them with ReadAbsControllerParams,
/// abs_params_io.h), make an AbsController and call Step() once per controller period with what
/// the sensors read; apply the returned pressure target through the hydraulics
/// (brake_hydraulics.h). The controller knows nothing of the tyre, the wheel or the road: it sees
/// the vehicle speed, the wheel speed and the driver's pressure, and commands a wheel-cylinder
/// pressure. The same controller therefore drives the quarter-car plant (abs/abs_plant.h) and,
/// later, the finite-element tyre.
///
///   brake::AbsController abs(params);
///   for (int k = 0; ...; ++k) {
///     const brake::AbsCommand cmd = abs.Step({.vehicle_speed = vx, .wheel_speed = omega,
///                                             .driver_pressure = p_driver});
///     // cmd.pressure_target goes to the hydraulics; cmd.state is for logging.
///   }
///
/// Signs: the wheel's circumferential acceleration a_w = R_l d(omega)/dt is negative when the
/// wheel slows; the thresholds are given as positive magnitudes (a_w < -a is "decelerating past
/// -a"). Braking slip lambda = (Vx - R_l omega) / Vx is positive when braking (spec section 0).
///
/// The wheel acceleration a_w is the backward difference of the wheel speed over one period,
/// low-pass filtered (first order, AbsControllerParams::accel_filter_time_constant_s), as ABS
/// units filter their wheel-speed signals.
///
/// Pitfall: a_w is first known on the second call after Reset(); the controller stays in
/// kInitialise for that first call, and the filter starts from that first difference.

#include <cstdint>
#include <string_view>

namespace hotlap::brake {

/// The paper's eight controller states (002 §2.2); the integer values are written to CSV files.
enum class AbsState : std::uint8_t {
  kInitialise = 0,    ///< waits for the driver; passes the driver's pressure through
  kHold = 1,          ///< pressure held (Bosch phases 2, 4, 6; AbsHoldPhase says which)
  kIncrease = 2,      ///< pressure follows the driver at the driver's rate (phase 1)
  kFastIncrease = 3,  ///< fast rise while the wheel accelerates beyond +A (phase 5)
  kDecrease = 4,      ///< pressure released (phases 3 and 8)
  kStepIncrease = 5,  ///< stepped re-apply, a slow average rise (phase 7)
  kStepDecrease = 6,  ///< stepped release when the wheel does not recover (low grip)
  kExit = 7,          ///< ABS off: low speed or brake released; driver's pressure passed through
};

/// Lower-case name of a state ("initialise", "hold", ..., "exit").
std::string_view AbsStateName(AbsState state);

/// Which hold a kHold is: it decides how the hold ends.
enum class AbsHoldPhase : std::uint8_t {
  kNone,               ///< not holding
  kFirst,              ///< phase 2: after the first -a; ends when lambda passes lambda_1
  kAfterDecrease,      ///< phase 4: after a release; ends on +A, on +a then below +a, or a timer
  kAfterFastIncrease,  ///< phase 6: +a < a_w < +A; ends when a_w falls below +a
};

/// Thresholds, rates and timers of the controller. SI units; every value comes from the
/// configuration file (data/abs/paper.yaml documents the defaults and their sources).
struct AbsControllerParams {
  double period_s = 0.0;                   ///< controller period, s (> 0)
  double wheel_radius_m = 0.0;             ///< R_l used for lambda and a_w, m (> 0)
  double decel_threshold_mps2 = 0.0;       ///< a: the -a threshold on a_w, m/s^2 (> 0)
  double accel_threshold_mps2 = 0.0;       ///< +a, m/s^2 (> 0)
  double high_accel_threshold_mps2 = 0.0;  ///< +A, m/s^2 (> +a)
  /// Time constant of the first-order low-pass filter on a_w, s (0: none). Suppresses the
  /// wheel-tyre torsional oscillation (tens of Hz) that would otherwise trip the thresholds.
  double accel_filter_time_constant_s = 0.0;
  double slip_threshold = 0.0;               ///< lambda_1, 1 (in (0, 1))
  double exit_speed_mps = 0.0;               ///< ABS exits when Vx falls below this, m/s
  double release_pressure_Pa = 0.0;          ///< driver pressure at or below this: released, Pa
  double decrease_rate_Pa_per_s = 0.0;       ///< command fall in kDecrease, Pa/s (> 0)
  double fast_increase_rate_Pa_per_s = 0.0;  ///< command rise in kFastIncrease, Pa/s (> 0)
  double step_increase_Pa = 0.0;             ///< one step of kStepIncrease, Pa (> 0)
  /// On entering kStepIncrease the command rises at once to at least this fraction of the
  /// command at which the last release began (the pressure memory of the cycle), 1 in [0, 1);
  /// 0: plain steps.
  double reapply_fraction = 0.0;
  double step_increase_interval_s = 0.0;  ///< time from one step to the next, s
  double step_decrease_Pa = 0.0;          ///< one step of kStepDecrease, Pa (> 0)
  double step_decrease_interval_s = 0.0;  ///< time from one step to the next, s
  double first_hold_max_s =
      0.0;  ///< phase 2 timer: lambda below lambda_1 this long -> step increase
  double low_grip_hold_s = 0.0;  ///< phase 4 timer: no +a this long -> step decrease (or increase)
};

/// What the sensors read at one controller tick. SI units.
struct AbsSensors {
  double vehicle_speed = 0.0;    ///< Vx, m/s (> 0 forward)
  double wheel_speed = 0.0;      ///< omega, rad/s (> 0 rolling forward)
  double driver_pressure = 0.0;  ///< master-cylinder pressure the driver asks for, Pa
};

/// What the controller asks of the hydraulics for the next period.
struct AbsCommand {
  double pressure_target = 0.0;  ///< wheel-cylinder pressure target, Pa, in [0, driver pressure]
  AbsState state = AbsState::kInitialise;  ///< the state after this tick
};

/// Everything the controller remembers between ticks.
struct AbsControllerState {
  AbsState state = AbsState::kInitialise;
  AbsHoldPhase hold_phase = AbsHoldPhase::kNone;
  double pressure_command = 0.0;      ///< the controller's pressure target, Pa
  double time_in_state = 0.0;         ///< s since the last transition
  double step_timer = 0.0;            ///< s since the last pressure step (step states)
  double previous_wheel_speed = 0.0;  ///< omega at the previous tick, rad/s
  bool has_previous = false;          ///< previous_wheel_speed is valid
  bool seen_accel_above_a = false;    ///< a_w passed +a during this hold (phase 4)
  int cycles = 0;                 ///< control cycles begun: entries into kDecrease that start one
  double release_pressure = 0.0;  ///< the command when the last release began, Pa
  int ticks = 0;                  ///< Step() calls since Reset()
  double slip = 0.0;              ///< lambda at the last tick, 1
  double wheel_accel = 0.0;       ///< filtered a_w at the last tick, m/s^2 (< 0 slowing)
};

/// One controller tick: reads `sensors`, updates `state` (transition first, then the new state's
/// action on the pressure command) and returns the command. Pure apart from `state`.
AbsCommand StepAbsController(const AbsControllerParams& params, AbsControllerState& state,
                             const AbsSensors& sensors);

/// The controller as an object: its parameters and its state.
class AbsController {
 public:
  explicit AbsController(const AbsControllerParams& params) : params_(params) {}

  /// One tick (StepAbsController).
  AbsCommand Step(const AbsSensors& sensors) { return StepAbsController(params_, state_, sensors); }
  /// Back to kInitialise with nothing remembered.
  void Reset() { state_ = AbsControllerState{}; }

  const AbsControllerParams& params() const { return params_; }
  const AbsControllerState& state() const { return state_; }

 private:
  AbsControllerParams params_;
  AbsControllerState state_;
};

}  // namespace hotlap::brake
