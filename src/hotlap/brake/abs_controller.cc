#include "hotlap/brake/abs_controller.h"

#include <algorithm>

#include "hotlap/common/enum_names.h"

namespace hotlap::brake {

constexpr EnumNames<AbsState, 8> kAbsStates{{{{AbsState::kInitialise, "initialise"},
                                              {AbsState::kHold, "hold"},
                                              {AbsState::kIncrease, "increase"},
                                              {AbsState::kFastIncrease, "fast_increase"},
                                              {AbsState::kDecrease, "decrease"},
                                              {AbsState::kStepIncrease, "step_increase"},
                                              {AbsState::kStepDecrease, "step_decrease"},
                                              {AbsState::kExit, "exit"}}}};

std::string_view AbsStateName(AbsState state) { return kAbsStates.Name(state, "unknown"); }

namespace {

// The transitions of one tick, on the measured slip and wheel acceleration. Returns true when
// the state changed (the new state's action then starts this tick).
bool Transition(const AbsControllerParams& p, AbsControllerState& s, double driver_pressure,
                double vehicle_speed) {
  const double a = s.wheel_accel;
  const double lambda = s.slip;
  const bool released = driver_pressure <= p.release_pressure_Pa;
  const bool slow = vehicle_speed < p.exit_speed_mps;
  const auto go = [&](AbsState next, AbsHoldPhase phase = AbsHoldPhase::kNone) {
    s.state = next;
    s.hold_phase = phase;
    s.time_in_state = 0.0;
    s.step_timer = 0.0;
    s.seen_accel_above_a = false;
    return true;
  };
  // A control cycle begins with a release that follows a build-up (Bosch phases 3 and 8).
  const auto start_cycle = [&] {
    ++s.cycles;
    s.release_pressure = s.pressure_command;
    return go(AbsState::kDecrease);
  };

  switch (s.state) {
    case AbsState::kInitialise:
      // a_w needs two wheel-speed samples; then braking starts when the driver presses.
      if (s.ticks >= 2 && !released && !slow) return go(AbsState::kIncrease);
      return false;
    case AbsState::kExit:
      // A new braking event starts only after the driver has let go of the brake.
      if (released) {
        s.cycles = 0;
        return go(AbsState::kInitialise);
      }
      return false;
    default:
      break;
  }
  if (released || slow) return go(AbsState::kExit);

  switch (s.state) {
    case AbsState::kIncrease:  // phase 1: the driver's build-up
      if (a < -p.decel_threshold_mps2) {
        // The first cycle holds first (phase 2, filters a disturbance); later ones release at once.
        return s.cycles == 0 ? go(AbsState::kHold, AbsHoldPhase::kFirst) : start_cycle();
      }
      if (lambda > p.slip_threshold) return start_cycle();
      return false;

    case AbsState::kHold:
      switch (s.hold_phase) {
        case AbsHoldPhase::kFirst:  // phase 2
          if (lambda > p.slip_threshold) return start_cycle();
          if (s.time_in_state >= p.first_hold_max_s - 0.5 * p.period_s) {
            return go(AbsState::kStepIncrease);
          }
          return false;
        case AbsHoldPhase::kAfterDecrease:  // phase 4
          if (a > p.accel_threshold_mps2) s.seen_accel_above_a = true;
          if (a > p.high_accel_threshold_mps2) return go(AbsState::kFastIncrease);
          if (s.seen_accel_above_a && a < p.accel_threshold_mps2) {
            return go(AbsState::kStepIncrease);
          }
          if (a < -p.decel_threshold_mps2 && lambda > p.slip_threshold) {
            return go(AbsState::kDecrease);  // still slipping away: release more, same cycle
          }
          if (!s.seen_accel_above_a && s.time_in_state >= p.low_grip_hold_s - 0.5 * p.period_s) {
            // The wheel did not re-accelerate: low grip. Release in steps while slipping.
            return go(lambda > p.slip_threshold ? AbsState::kStepDecrease
                                                : AbsState::kStepIncrease);
          }
          return false;
        case AbsHoldPhase::kAfterFastIncrease:  // phase 6
          if (a > p.high_accel_threshold_mps2) return go(AbsState::kFastIncrease);
          if (a < p.accel_threshold_mps2) return go(AbsState::kStepIncrease);
          return false;
        case AbsHoldPhase::kNone:
          return false;
      }
      return false;

    case AbsState::kDecrease:  // phases 3 and 8: until the wheel stops slowing past -a
      if (a > -p.decel_threshold_mps2) return go(AbsState::kHold, AbsHoldPhase::kAfterDecrease);
      return false;

    case AbsState::kFastIncrease:  // phase 5: while beyond +A
      if (a < p.high_accel_threshold_mps2) {
        return go(AbsState::kHold, AbsHoldPhase::kAfterFastIncrease);
      }
      return false;

    case AbsState::kStepIncrease:  // phase 7: until the wheel slows past -a again
      if (a < -p.decel_threshold_mps2) return start_cycle();
      if (s.pressure_command >= driver_pressure) return go(AbsState::kIncrease);
      return false;

    case AbsState::kStepDecrease:  // low grip: until the wheel re-accelerates or slip recovers
      if (a > p.accel_threshold_mps2) {
        go(AbsState::kHold, AbsHoldPhase::kAfterDecrease);
        s.seen_accel_above_a = true;
        return true;
      }
      if (lambda <= p.slip_threshold) return go(AbsState::kStepIncrease);
      return false;

    default:
      return false;
  }
}

}  // namespace

AbsCommand StepAbsController(const AbsControllerParams& p, AbsControllerState& s,
                             const AbsSensors& in) {
  const double dt = p.period_s;
  const double driver = std::max(in.driver_pressure, 0.0);
  // Measurements: braking slip (002:2) and the wheel's circumferential acceleration.
  s.slip = in.vehicle_speed > 0.0
               ? (in.vehicle_speed - p.wheel_radius_m * in.wheel_speed) / in.vehicle_speed
               : 0.0;
  if (s.has_previous) {
    const double raw = p.wheel_radius_m * (in.wheel_speed - s.previous_wheel_speed) / dt;
    // First-order low-pass (backward Euler), started from the first difference.
    const double k = dt / (p.accel_filter_time_constant_s + dt);
    s.wheel_accel = s.ticks >= 2 ? s.wheel_accel + k * (raw - s.wheel_accel) : raw;
  }
  s.previous_wheel_speed = in.wheel_speed;
  s.has_previous = true;
  ++s.ticks;
  s.time_in_state += dt;
  s.step_timer += dt;

  const bool entered = Transition(p, s, driver, in.vehicle_speed);

  // The (new) state's action on the pressure command. The ABS can only lower the driver's
  // pressure, never raise it above.
  double& cmd = s.pressure_command;
  const double interval =
      s.state == AbsState::kStepIncrease ? p.step_increase_interval_s : p.step_decrease_interval_s;
  const bool step_due = entered || s.step_timer >= interval - 0.5 * dt;
  switch (s.state) {
    case AbsState::kInitialise:
    case AbsState::kIncrease:
    case AbsState::kExit:
      cmd = driver;
      break;
    case AbsState::kHold:
      break;
    case AbsState::kDecrease:
      cmd -= p.decrease_rate_Pa_per_s * dt;
      break;
    case AbsState::kFastIncrease:
      cmd += p.fast_increase_rate_Pa_per_s * dt;
      break;
    case AbsState::kStepIncrease:
      if (step_due) {
        cmd += p.step_increase_Pa;
        s.step_timer = 0.0;
      }
      // The first step returns to near the pressure at which the wheel last began to lock.
      if (entered) cmd = std::max(cmd, p.reapply_fraction * s.release_pressure);
      break;
    case AbsState::kStepDecrease:
      if (step_due) {
        cmd -= p.step_decrease_Pa;
        s.step_timer = 0.0;
      }
      break;
  }
  cmd = std::clamp(cmd, 0.0, driver);
  return {cmd, s.state};
}

}  // namespace hotlap::brake
