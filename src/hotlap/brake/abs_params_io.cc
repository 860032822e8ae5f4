#include "hotlap/brake/abs_params_io.h"

#include <fmt/format.h>

#include "hotlap/common/units.h"

namespace hotlap::brake {

AbsControllerParams ReadAbsControllerParams(YamlReader& c) {
  constexpr double kMPa = 1e6;
  AbsControllerParams p;
  p.period_s = c.Number("period_s", Range::OpenClosed(0.0, 0.1, "s"));
  p.decel_threshold_mps2 = kGravity * c.Number("decel_threshold_g", Range::Positive("g"));
  p.accel_threshold_mps2 = kGravity * c.Number("accel_threshold_g", Range::Positive("g"));
  p.high_accel_threshold_mps2 = kGravity * c.Number("high_accel_threshold_g", Range::Positive("g"));
  if (!(p.high_accel_threshold_mps2 > p.accel_threshold_mps2)) {
    c.Fail("high_accel_threshold_g",
           fmt::format("{:g} must be above accel_threshold_g ({:g})",
                       p.high_accel_threshold_mps2 / kGravity, p.accel_threshold_mps2 / kGravity));
  }
  p.accel_filter_time_constant_s =
      c.Number("accel_filter_time_constant_s", Range::Closed(0.0, 1.0, "s"));
  p.slip_threshold = c.Number("slip_threshold", {0.0, 1.0, false, false, ""});
  p.exit_speed_mps = c.Number("exit_speed_mps", Range::NonNegative("m/s"));
  p.release_pressure_Pa = kMPa * c.Number("release_pressure_MPa", Range::NonNegative("MPa"));
  p.decrease_rate_Pa_per_s = kMPa * c.Number("decrease_rate_MPa_per_s", Range::Positive("MPa/s"));
  p.fast_increase_rate_Pa_per_s =
      kMPa * c.Number("fast_increase_rate_MPa_per_s", Range::Positive("MPa/s"));
  // Steps and timers act at controller ticks, so none is shorter than one period.
  const Range at_least_a_period{p.period_s, 10.0, true, true, "s"};
  p.step_increase_Pa = kMPa * c.Number("step_increase_MPa", Range::Positive("MPa"));
  p.step_increase_interval_s = c.Number("step_increase_interval_s", at_least_a_period);
  p.reapply_fraction = c.Number("reapply_fraction", {0.0, 1.0, true, false, ""});
  p.step_decrease_Pa = kMPa * c.Number("step_decrease_MPa", Range::Positive("MPa"));
  p.step_decrease_interval_s = c.Number("step_decrease_interval_s", at_least_a_period);
  p.first_hold_max_s = c.Number("first_hold_max_s", at_least_a_period);
  p.low_grip_hold_s = c.Number("low_grip_hold_s", at_least_a_period);
  c.Finish();
  return p;
}

BrakeHydraulicsParams<double> ReadBrakeHydraulicsParams(YamlReader& h) {
  constexpr double kMPa = 1e6;
  BrakeHydraulicsParams<double> p;
  p.delay = h.Number("delay_s", Range::Closed(0.0, 1.0, "s"));
  p.time_constant = h.Number("time_constant_s", Range::OpenClosed(0.0, 1.0, "s"));
  p.max_rise_rate = kMPa * h.Number("max_rise_rate_MPa_per_s", Range::Positive("MPa/s"));
  p.max_fall_rate = kMPa * h.Number("max_fall_rate_MPa_per_s", Range::Positive("MPa/s"));
  p.max_pressure = kMPa * h.Number("max_pressure_MPa", Range::Positive("MPa"));
  p.torque_gain = h.Number("torque_gain_Nm_per_MPa", Range::Positive("N m/MPa")) / kMPa;
  h.Finish();
  return p;
}

}  // namespace hotlap::brake
