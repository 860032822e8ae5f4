#pragma once
/// @file
/// What a logged channel may physically hold (issue 25): the range outside which a value is
/// refused as impossible, and the narrow band just outside the physical range that a real logger
/// does produce (a wheel in the air, a speed sensor's noise at standstill, a locked wheel's slip
/// ratio a little past -1), where the value is set to the physical limit and a warning counts the
/// rows. docs/telemetry-formats.md lists the table.

#include <optional>
#include <string_view>

namespace hotlap {

/// The limits of one quantity, in internal SI units (Telemetry's: m/s, N, rad, K, m, W).
struct ChannelLimits {
  /// Values below this are refused. -infinity: no lower limit.
  double refuse_below;
  /// Values in [refuse_below, physical_min) are set to physical_min, with a warning.
  /// Equal to refuse_below where nothing is treated.
  double physical_min;
  /// Values above this are refused. +infinity: no upper limit.
  double refuse_above;
  /// What a treated value means, for the warning (e.g. "a wheel in the air"); empty if none.
  std::string_view treated_as;
  /// Why the limits are what they are, for the refusal message (e.g. "faster than any race car").
  std::string_view reason;
};

/// The limits of a telemetry quantity (speed, fz, slip_angle, slip_ratio, the temperatures,
/// rolling_radius, brake_power ...); nullopt for a quantity with none (time, distance, fx, fy,
/// the heat flows, wear, grip_factor).
std::optional<ChannelLimits> LimitsOf(std::string_view quantity);

/// True if `value` (SI) of `quantity` is one LimitsOf() refuses (outside [refuse_below,
/// refuse_above]); false for NaN and for quantities without limits.
bool IsRefused(std::string_view quantity, double value);

}  // namespace hotlap
