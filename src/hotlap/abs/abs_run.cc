#include "hotlap/abs/abs_run.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "hotlap/brake/brake_hydraulics.h"
#include "hotlap/common/error.h"
#include "hotlap/common/rk4.h"

namespace hotlap::sim {

namespace {

using State = AbsPlantState<double>;
using Input = AbsPlantInput<double>;
using Outputs = AbsPlantOutputs<double>;

/// The moments inside a step at which the plant's right-hand side changes form.
enum class Event { kWheelStops, kWheelSpins, kVehicleStops, kSurfaceChanges };

/// One classical RK4 step of length h from x, whose derivative k1 is known.
State Rk4From(const AbsPlantModel<double>& model, const State& x, const State& k1, const Input& in,
              double h) {
  const auto f = [&](const State& s) { return CalcAbsPlantDerivatives(model, s, in); };
  const State k2 = f(x + (0.5 * h) * k1);
  const State k3 = f(x + (0.5 * h) * k2);
  const State k4 = f(x + h * k3);
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/// Integrates the plant across ticks and events, and keeps the records.
class AbsIntegrator {
 public:
  AbsIntegrator(const AbsPlantModel<double>& model, const Surface& surface, const AbsEvent& event,
                AbsRunResult& result)
      : model_(model), surface_(surface), event_(event), r_(result) {
    segment_ = surface_.SegmentAt(0.0);
    in_.road = surface_.segments[segment_].law;
    in_.vehicle = event.vehicle;
  }

  Input& input() { return in_; }
  /// A guard against a run that stops making progress: at most this many steps.
  void set_max_steps(long n) { max_steps_ = n; }

  /// Integrates from t to t_end in steps of at most h_max, recording at each step's start.
  /// Stops early when the vehicle stops.
  void Advance(State& x, double& t, double t_end, double h_max, double driver, int state_code) {
    while (t_end - t > 1e-12 && !r_.stopped) {
      const double h = std::min(h_max, t_end - t);
      Outputs o;
      State k1 = CalcAbsPlantDerivatives(model_, x, in_, &o);
      // At rest, the mode is decided at the step's start by one rule, so it cannot flip back
      // and forth: the brake holds the wheel while it can (holding torque <= capacity).
      if (in_.wheel == WheelMode::kRolling && x.wheel_speed <= 0.0 &&
          o.holding_torque <= o.brake_capacity) {
        x.wheel_speed = 0.0;
        in_.wheel = WheelMode::kLocked;
        k1 = CalcAbsPlantDerivatives(model_, x, in_, &o);
      } else if (in_.wheel == WheelMode::kLocked && o.holding_torque > o.brake_capacity) {
        in_.wheel = WheelMode::kRolling;
        k1 = CalcAbsPlantDerivatives(model_, x, in_, &o);
      }
      Record(t, x, o, driver, state_code);
      if (++r_.steps > max_steps_) {
        throw NumericalError(fmt::format(
            "ABS run: no progress at t = {:.9f} s after {} integration steps", t, r_.steps));
      }

      State x1 = Rk4From(model_, x, k1, in_, h);
      // Did anything change form inside the step? Locate the earliest such moment. An event
      // whose function is not positive at the step's start was settled by the rule above.
      double earliest = 2.0;
      Event which = Event::kWheelStops;
      for (Event e :
           {Event::kWheelStops, Event::kWheelSpins, Event::kVehicleStops, Event::kSurfaceChanges}) {
        if (!Applies(e) || G(e, x1) > 0.0 || G(e, x) <= 0.0) continue;
        const double theta = Locate(e, x, k1, h);
        if (theta < earliest) {
          earliest = theta;
          which = e;
        }
      }
      if (earliest <= 1.0) {
        x1 = Rk4From(model_, x, k1, in_, earliest * h);
        t += earliest * h;
        x = x1;
        Apply(which, x);
      } else {
        t = h == t_end - t ? t_end : t + h;  // land on the tick exactly
        x = x1;
      }
      CheckFinite(x, t);
    }
    if (!r_.stopped) t = t_end;  // ticks stay on the controller's grid (residual < 1e-12 s)
  }

  /// The last record, at the end of the run.
  void RecordEnd(const State& x, double t, double driver, int state_code) {
    Outputs o;
    CalcAbsPlantDerivatives(model_, x, in_, &o);
    Record(t, x, o, driver, state_code);
  }

 private:
  bool Applies(Event e) const {
    switch (e) {
      case Event::kWheelStops:
        return in_.wheel == WheelMode::kRolling;
      case Event::kWheelSpins:
        return in_.wheel == WheelMode::kLocked;
      case Event::kVehicleStops:
        return in_.vehicle == AbsVehicleMode::kFree;
      case Event::kSurfaceChanges:
        return std::isfinite(surface_.SegmentEnd(segment_));
    }
    return false;
  }

  /// The event function: positive while the event has not happened.
  double G(Event e, const State& x) const {
    switch (e) {
      case Event::kWheelStops:
        return x.wheel_speed;
      case Event::kWheelSpins: {
        Outputs o;
        CalcAbsPlantDerivatives(model_, x, in_, &o);
        return o.brake_capacity - o.holding_torque;
      }
      case Event::kVehicleStops:
        return x.speed - event_.stop_speed_mps;
      case Event::kSurfaceChanges:
        return surface_.SegmentEnd(segment_) - x.distance;
    }
    return 1.0;
  }

  /// The step fraction theta in (0, 1] at which event `e` happens (G > 0 at the start, <= 0 at
  /// theta),
  /// by the Illinois variant of regula falsi on G(RK4 step of theta h).
  double Locate(Event e, const State& x, const State& k1, double h) const {
    double a = 0.0, ga = G(e, x);
    double b = 1.0, gb = G(e, Rk4From(model_, x, k1, in_, h));
    int side = 0;
    for (int it = 0; it < 100 && b - a > 1e-10; ++it) {
      const double c = std::clamp((a * gb - b * ga) / (gb - ga), a, b);
      const double gc = G(e, Rk4From(model_, x, k1, in_, c * h));
      if (gc > 0.0) {
        a = c;
        ga = gc;
        if (side == 1) gb *= 0.5;
        side = 1;
      } else {
        b = c;
        gb = gc;
        if (side == -1) ga *= 0.5;
        side = -1;
      }
    }
    return b;
  }

  void Apply(Event e, State& x) {
    switch (e) {
      case Event::kWheelStops:
        x.wheel_speed = 0.0;  // within the location tolerance of zero already
        in_.wheel = WheelMode::kLocked;
        break;
      case Event::kWheelSpins:
        in_.wheel = WheelMode::kRolling;
        break;
      case Event::kVehicleStops:
        r_.stopped = true;
        break;
      case Event::kSurfaceChanges:
        segment_ = std::max(segment_ + 1, surface_.SegmentAt(x.distance));
        segment_ = std::min(segment_, surface_.segments.size() - 1);
        in_.road = surface_.segments[segment_].law;
        break;
    }
  }

  void Record(double t, const State& x, const Outputs& o, double driver, int state_code) {
    AbsHistory& h = r_.history;
    h.time.push_back(t);
    h.distance.push_back(x.distance);
    h.speed.push_back(x.speed);
    h.wheel_speed.push_back(x.wheel_speed);
    h.lambda.push_back(x.speed > 0.0 ? (x.speed - model_.wheel.radius * x.wheel_speed) / x.speed
                                     : 0.0);
    h.transient_slip.push_back(x.slip);
    h.driver_pressure.push_back(driver);
    h.pressure_target.push_back(in_.pressure_target);
    h.pressure.push_back(x.pressure);
    h.brake_torque.push_back(o.brake_torque);
    h.fx.push_back(o.fx);
    h.friction.push_back(o.friction);
    h.disc_temp.push_back(std::numeric_limits<double>::quiet_NaN());  // filled per tick
    h.calliper_temp.push_back(std::numeric_limits<double>::quiet_NaN());
    h.state.push_back(state_code);
    h.locked.push_back(in_.wheel == WheelMode::kLocked ? 1 : 0);
  }

  static void CheckFinite(const State& x, double t) {
    if (!std::isfinite(x.speed) || !std::isfinite(x.wheel_speed) || !std::isfinite(x.slip) ||
        !std::isfinite(x.pressure) || !std::isfinite(x.slip_energy)) {
      throw NumericalError(fmt::format(
          "ABS run: the wheel state is not finite at t = {:.6f} s (Vx {}, omega {}, slip {})", t,
          x.speed, x.wheel_speed, x.slip));
    }
  }

  const AbsPlantModel<double>& model_;
  const Surface& surface_;
  const AbsEvent& event_;
  AbsRunResult& r_;
  Input in_;
  size_t segment_ = 0;
  long max_steps_ = 0;
};

}  // namespace

AbsRunResult RunAbs(const AbsConfig& config, const AbsEvent& event) {
  const Surface& surface = config.SurfaceNamed(event.surface);
  const AbsPlantModel<double>& model = config.plant;
  const double period = config.controller.period_s;
  const double h_max = period / std::max(event.steps_per_period, 1);
  const bool use_abs = event.control == AbsControl::kAbs;
  const brake::BrakeThermalParams<double>& bp = config.brake.params;
  const brake::BrakeConstants<double> bk = brake::CalcBrakeConstants(bp);

  AbsRunResult r;
  r.ambient_temp_K = event.ambient_temp_K;
  brake::AbsController controller(config.controller);
  // The wheel speed the controller sees (brake/wheel_speed_filter.h; kNone: as measured).
  brake::WheelSpeedFilter speed_filter(config.wheel_speed_filter, config.controller.period_s);
  brake::PressureDelayLine delay(config.DelayTicks(), 0.0);
  AbsIntegrator integrator(model, surface, event, r);
  // Each tick takes steps_per_period steps plus a few at events; far more means no progress.
  integrator.set_max_steps(static_cast<long>(20.0 * (event.duration_s / h_max + 1.0)) + 100000);

  // Free rolling at the start: omega R_l = Vx, no slip, no pressure.
  State x;
  x.speed = event.initial_speed_mps;
  x.wheel_speed = x.speed / model.wheel.radius;
  r.initial = x;
  brake::BrakeState<double> thermal{event.initial_disc_temp_K, event.initial_calliper_temp_K};

  double t = 0.0, driver = 0.0;
  int state_code = use_abs ? static_cast<int>(brake::AbsState::kInitialise) : -1;
  int cycles_seen = 0;
  bool braking_began = false;
  for (long k = 0; !r.stopped; ++k) {
    const double t_tick = static_cast<double>(k) * period;
    if (t_tick >= event.duration_s - 1e-9) break;
    driver = config.driver.PressureAt(t_tick);
    double target = driver;
    if (use_abs) {
      const brake::AbsCommand cmd =
          controller.Step({x.speed, speed_filter.Step(x.wheel_speed), driver});
      target = cmd.pressure_target;
      state_code = static_cast<int>(cmd.state);
      if (controller.state().cycles > cycles_seen) r.cycle_starts_s.push_back(t_tick);
      cycles_seen = controller.state().cycles;
      if (cmd.state != brake::AbsState::kInitialise && cmd.state != brake::AbsState::kExit) {
        braking_began = true;
      }
      if (cmd.state == brake::AbsState::kExit && braking_began && !r.abs_exit_s) {
        r.abs_exit_s = t_tick;
      }
    }
    integrator.input().pressure_target = delay.Push(target);

    // The plant to the next tick, then the brake's temperatures over the same interval.
    const double t0 = t, energy0 = x.brake_energy, distance0 = x.distance;
    const size_t first = r.history.size();
    integrator.Advance(x, t, std::min(static_cast<double>(k + 1) * period, event.duration_s), h_max,
                       driver, state_code);
    const double dt = t - t0;
    const brake::BrakeState<double> before = thermal;
    if (dt > 0.0) {
      brake::BrakeInputTerms<double> terms = brake::CalcBrakeInputTerms(
          bp, bk, {(x.distance - distance0) / dt, 0.0, event.ambient_temp_K});
      terms.power = (x.brake_energy - energy0) / dt;  // T_b omega, mean over the tick
      thermal = Rk4Step(
          [&](double, const brake::BrakeState<double>& s) {
            return brake::CalcBrakeDerivatives(bp, s, terms);
          },
          0.0, thermal, dt);
    }
    AbsHistory& h = r.history;
    for (size_t i = first; i < h.size(); ++i) {
      const double f = dt > 0.0 ? (h.time[i] - t0) / dt : 0.0;
      h.disc_temp[i] = before.disc_temp + f * (thermal.disc_temp - before.disc_temp);
      h.calliper_temp[i] =
          before.calliper_temp + f * (thermal.calliper_temp - before.calliper_temp);
    }
  }
  integrator.RecordEnd(x, t, driver, state_code);
  r.history.disc_temp.back() = thermal.disc_temp;
  r.history.calliper_temp.back() = thermal.calliper_temp;
  r.final = x;
  r.final_brake = thermal;
  r.end_time_s = t;
  return r;
}

}  // namespace hotlap::sim
