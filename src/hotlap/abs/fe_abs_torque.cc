#include "hotlap/abs/fe_abs_torque.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace hotlap::sim {

double FeAbsTorque::operator()(double t, double vx, double spin) {
  const double dt = t - t_prev_;
  spin_sum_ += dt * spin;
  vx_sum_ += dt * vx;
  window_ += dt;
  while (t >= next_tick_ - 1e-12) {
    const int cycles = state_.cycles;
    const double spin_read = filter_.Step(window_ > 0.0 ? spin_sum_ / window_ : spin);
    const double vx_read = window_ > 0.0 ? vx_sum_ / window_ : vx;
    spin_sum_ = vx_sum_ = window_ = 0.0;
    const brake::AbsCommand cmd = brake::StepAbsController(
        params_, state_, {vx_read, spin_read, config_.driver.PressureAt(next_tick_)});
    if (state_.cycles > cycles) cycle_starts_.push_back(next_tick_);
    if (state_.state == brake::AbsState::kExit && !abs_exit_) abs_exit_ = next_tick_;
    target_ = Push(cmd.pressure_target);
    next_tick_ += params_.period_s;
  }
  const brake::BrakeHydraulicsParams<double>& hyd = config_.plant.hydraulics;
  pressure_ += (t - t_prev_) * brake::CalcPressureRate(hyd, pressure_, target_);
  t_prev_ = t;
  return brake::CalcBrakeTorqueCapacity(hyd, pressure_);
}

double FeAbsTorque::Push(double command) {
  pushed_.push_back(command);
  if (pushed_.size() > static_cast<size_t>(std::max(0, delay_.delay_ticks()))) {
    pushed_.pop_front();
  }
  return delay_.Push(command);
}

void FeAbsTorque::Save(fe::BinaryWriter& w) const {
  w.PutTag("ABS_");
  const brake::AbsControllerState& s = state_;
  w.PutU64(static_cast<std::uint64_t>(s.state));
  w.PutU64(static_cast<std::uint64_t>(s.hold_phase));
  w.PutU64((s.has_previous ? 1 : 0) | (s.seen_accel_above_a ? 2 : 0));
  w.PutI64(s.cycles);
  w.PutI64(s.ticks);
  for (double d : {s.pressure_command, s.time_in_state, s.step_timer, s.previous_wheel_speed,
                   s.release_pressure, s.slip, s.wheel_accel, next_tick_, target_, pressure_,
                   t_prev_, spin_sum_, vx_sum_, window_}) {
    w.PutDouble(d);
  }
  w.PutDoubles(std::vector<double>(pushed_.begin(), pushed_.end()));
  w.PutDoubles(cycle_starts_);
  w.PutDoubles(abs_exit_ ? std::vector<double>{*abs_exit_} : std::vector<double>{});
  w.PutU64(filter_.started() ? 1 : 0);
  w.PutDouble(filter_.z1());
  w.PutDouble(filter_.z2());
}

void FeAbsTorque::Load(fe::BinaryReader& r) {
  r.ExpectTag("ABS_");
  brake::AbsControllerState s;
  const std::uint64_t state = r.GetU64(), phase = r.GetU64(), flags = r.GetU64();
  if (state > static_cast<std::uint64_t>(brake::AbsState::kExit) ||
      phase > static_cast<std::uint64_t>(brake::AbsHoldPhase::kAfterFastIncrease) || flags > 3) {
    r.Damaged("an ABS controller state out of range");
  }
  s.state = static_cast<brake::AbsState>(state);
  s.hold_phase = static_cast<brake::AbsHoldPhase>(phase);
  s.has_previous = flags & 1;
  s.seen_accel_above_a = flags & 2;
  const std::int64_t cycles = r.GetI64(), ticks = r.GetI64();
  if (cycles < 0 || ticks < 0 || cycles > ticks || ticks > (std::int64_t{1} << 40)) {
    r.Damaged("ABS controller counters out of range");
  }
  s.cycles = static_cast<int>(cycles);
  s.ticks = static_cast<int>(ticks);
  double next_tick, target, pressure, t_prev, spin_sum, vx_sum, window;
  for (double* d : {&s.pressure_command, &s.time_in_state, &s.step_timer, &s.previous_wheel_speed,
                    &s.release_pressure, &s.slip, &s.wheel_accel, &next_tick, &target, &pressure,
                    &t_prev, &spin_sum, &vx_sum, &window}) {
    *d = r.GetFinite();
  }
  if (window < 0.0) r.Damaged("a negative wheel-speed sensor window");
  const size_t n = r.GetCount(sizeof(double));
  if (n > static_cast<size_t>(std::max(0, config_.DelayTicks()))) {
    r.Damaged("more delayed pressure commands than the hydraulic delay holds");
  }
  std::vector<double> pushed(n);
  for (double& d : pushed) d = r.GetFinite();
  // Every cycle begun has its start time (the controller's own count restarts after an exit).
  const size_t starts = r.GetCount(sizeof(double));
  if (starts < static_cast<size_t>(s.cycles)) {
    r.Damaged("fewer ABS cycle start times than the controller's cycle count");
  }
  std::vector<double> cycle_starts(starts);
  for (double& d : cycle_starts) d = r.GetFinite();
  const size_t exits = r.GetCount(sizeof(double));
  if (exits > 1) r.Damaged("more than one ABS exit time");
  std::optional<double> abs_exit;
  if (exits == 1) abs_exit = r.GetFinite();
  const std::uint64_t filter_started = r.GetU64();
  if (filter_started > 1) r.Damaged("a wheel-speed filter state out of range");
  const double filter_z1 = r.GetFinite(), filter_z2 = r.GetFinite();
  // Everything read: restore. The delay line is rebuilt by pushing the pending commands again.
  state_ = s;
  next_tick_ = next_tick;
  target_ = target;
  pressure_ = pressure;
  t_prev_ = t_prev;
  spin_sum_ = spin_sum;
  vx_sum_ = vx_sum;
  window_ = window;
  delay_ = brake::PressureDelayLine(config_.DelayTicks(), 0.0);
  pushed_.clear();
  for (double d : pushed) Push(d);
  cycle_starts_ = std::move(cycle_starts);
  abs_exit_ = abs_exit;
  filter_.SetState(filter_started == 1, filter_z1, filter_z2);
}

}  // namespace hotlap::sim
