#pragma once
/// @file
/// The brake hydraulics between an ABS (or the driver) and the brake: a pure delay on the
/// pressure target, then a rate-limited first-order lag of the wheel-cylinder pressure toward it,
/// and the pressure-to-torque gain of the calliper (spec section 8; docs/abs.md).
///
///   dp/dt = clamp((clamp(p_target(t - delay), 0, p_max) - p) / tau, -fall_max, +rise_max)
///   T_brake = k_T max(p, 0)
///
/// T_brake is the brake's friction-torque capacity: it opposes the wheel's spin, and on a stopped
/// wheel holds it up to that torque (abs/abs_plant.h).
///
/// How to use: the delay lives in PressureDelayLine (one entry per controller tick, so the delay
/// is a whole number of controller periods); CalcPressureRate is the right-hand side an
/// integrator steps.

#include <tuple>
#include <vector>

#include "hotlap/common/field_cast.h"
#include "hotlap/common/scalar.h"

namespace hotlap::brake {

/// Parameters of the hydraulics and calliper. SI units.
template <Scalar T>
struct BrakeHydraulicsParams {
  T delay{};          ///< transport delay from command to wheel cylinder, s (>= 0)
  T time_constant{};  ///< tau of the lag toward the delayed target, s (> 0)
  T max_rise_rate{};  ///< rise_max, Pa/s (> 0)
  T max_fall_rate{};  ///< fall_max, Pa/s (> 0)
  T max_pressure{};   ///< p_max: the highest pressure the system delivers, Pa (> 0)
  T torque_gain{};    ///< k_T: brake torque per wheel-cylinder pressure, N m/Pa (> 0)

  template <class Self>
  static auto FieldsOf(Self& s) {
    return std::tie(s.delay, s.time_constant, s.max_rise_rate, s.max_fall_rate, s.max_pressure,
                    s.torque_gain);
  }
  /// The same parameters in another scalar type (derivative parts start at zero).
  template <Scalar U>
  BrakeHydraulicsParams<U> Cast() const {
    BrakeHydraulicsParams<U> out;
    CastFields(*this, out);
    return out;
  }
};

/// dp/dt of the wheel-cylinder pressure `pressure` (Pa) toward the delayed target `target` (Pa),
/// Pa/s: clamp((clamp(target, 0, p_max) - p) / tau, -fall_max, rise_max). Continuous in both
/// arguments (piecewise smooth: kinks where the rate limits start to act).
template <Scalar T>
T CalcPressureRate(const BrakeHydraulicsParams<T>& params, const T& pressure, const T& target);

/// Brake torque capacity k_T max(p, 0), N m (>= 0).
template <Scalar T>
T CalcBrakeTorqueCapacity(const BrakeHydraulicsParams<T>& params, const T& pressure);

/// A pure delay of `delay_ticks` controller periods on the pressure target: Push(x) at tick k
/// returns the value pushed at tick k - delay_ticks (the initial value before that).
class PressureDelayLine {
 public:
  /// `initial` is returned until the first command has been delayed long enough; a negative
  /// delay counts as none (callers validate user input).
  PressureDelayLine(int delay_ticks, double initial);

  /// Stores this tick's command and returns the one in effect for the coming period, Pa.
  double Push(double command);
  /// The delay in ticks.
  int delay_ticks() const { return static_cast<int>(buffer_.size()); }

 private:
  std::vector<double> buffer_;  // ring of the last delay_ticks commands
  size_t next_ = 0;             // oldest entry, replaced by the next Push
};

}  // namespace hotlap::brake
