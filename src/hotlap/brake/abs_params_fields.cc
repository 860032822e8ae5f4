#include "hotlap/brake/abs_params_fields.h"

#include <array>

#include "hotlap/common/units.h"

namespace hotlap::brake {

namespace {

constexpr double kMPa = 1e6;

double GToSi(double g) { return kGravity * g; }
double MPaToSi(double mpa) { return kMPa * mpa; }
double PerMPaToSi(double per_mpa) { return per_mpa / kMPa; }

}  // namespace

Range AbsControllerField::RangeGiven(double period_s) const {
  // Steps and timers act at controller ticks, so none is shorter than one period.
  return at_least_a_period ? Range{period_s, 10.0, true, true, "s"} : range;
}

std::span<const AbsControllerField> AbsControllerFields() {
  using P = AbsControllerParams;
  const Range tick;  // replaced by RangeGiven
  // clang-format off
  static const auto table = std::to_array<AbsControllerField>({
      {"period_s", &P::period_s, Range::OpenClosed(0.0, 0.1, "s")},
      {"decel_threshold_g", &P::decel_threshold_mps2, Range::Positive("g"), &GToSi},
      {"accel_threshold_g", &P::accel_threshold_mps2, Range::Positive("g"), &GToSi},
      {"high_accel_threshold_g", &P::high_accel_threshold_mps2, Range::Positive("g"), &GToSi},
      {"accel_filter_time_constant_s", &P::accel_filter_time_constant_s, Range::Closed(0.0, 1.0, "s")},
      {"slip_threshold", &P::slip_threshold, Range{0.0, 1.0, false, false, ""}},
      {"exit_speed_mps", &P::exit_speed_mps, Range::NonNegative("m/s")},
      {"release_pressure_MPa", &P::release_pressure_Pa, Range::NonNegative("MPa"), &MPaToSi},
      {"decrease_rate_MPa_per_s", &P::decrease_rate_Pa_per_s, Range::Positive("MPa/s"), &MPaToSi},
      {"fast_increase_rate_MPa_per_s", &P::fast_increase_rate_Pa_per_s, Range::Positive("MPa/s"), &MPaToSi},
      {"step_increase_MPa", &P::step_increase_Pa, Range::Positive("MPa"), &MPaToSi},
      {"step_increase_interval_s", &P::step_increase_interval_s, tick, nullptr, true},
      {"reapply_fraction", &P::reapply_fraction, Range{0.0, 1.0, true, false, ""}},
      {"step_decrease_MPa", &P::step_decrease_Pa, Range::Positive("MPa"), &MPaToSi},
      {"step_decrease_interval_s", &P::step_decrease_interval_s, tick, nullptr, true},
      {"first_hold_max_s", &P::first_hold_max_s, tick, nullptr, true},
      {"low_grip_hold_s", &P::low_grip_hold_s, tick, nullptr, true},
  });
  // clang-format on
  return table;
}

std::span<const BrakeHydraulicsField> BrakeHydraulicsFields() {
  using H = BrakeHydraulicsParams<double>;
  // clang-format off
  static const auto table = std::to_array<BrakeHydraulicsField>({
      {"delay_s", &H::delay, Range::Closed(0.0, 1.0, "s")},
      {"time_constant_s", &H::time_constant, Range::OpenClosed(0.0, 1.0, "s")},
      {"max_rise_rate_MPa_per_s", &H::max_rise_rate, Range::Positive("MPa/s"), &MPaToSi},
      {"max_fall_rate_MPa_per_s", &H::max_fall_rate, Range::Positive("MPa/s"), &MPaToSi},
      {"max_pressure_MPa", &H::max_pressure, Range::Positive("MPa"), &MPaToSi},
      {"torque_gain_Nm_per_MPa", &H::torque_gain, Range::Positive("N m/MPa"), &PerMPaToSi},
  });
  // clang-format on
  return table;
}

}  // namespace hotlap::brake
