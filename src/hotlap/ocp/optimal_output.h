#pragma once
/// @file
/// What the optimal lap reports: its channels as CSV columns in the shared format and its figures
/// (the report's charts: optimal_lap_charts.h).

#include <string>
#include <vector>

#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/sim/replay_io.h"

namespace hotlap::ocp {

/// Columns (docs/optimal-control.md): distance_m (centre line), time_s, speed_mps, lateral
/// speed, yaw rate, offset_m, heading error, steer_deg, pedal (drive +, brake -; 0 throughout in
/// the old two-control formulation), drive_power_W, brake_force_N, x_m, y_m,
/// then per corner the tyre channels (speed, fx, fy, fz, slip angle, slip ratio), the optimiser's
/// temperatures and wear, brake power, and the exact replay's tread and disc temperatures
/// (`tread_temp_<c>_exact_C`, `disc_temp_<c>_exact_C`).
sim::ColumnSet OptimalLapColumns(const OptimalLapRun& run, const track::Track& track);

/// Headline figures of a run.
struct OptimalLapFigures {
  double lap_time_s = 0.0;
  double top_speed_mps = 0.0;
  double min_speed_mps = 0.0;
  double max_front_disc_temp_C = 0.0;
  std::array<double, 4> peak_disc_temp_C{}, peak_tread_temp_C{}, wear_mm{};
  /// Work done by the four brakes over the lap, J (the trapezoid in time of the brake power).
  double brake_energy_J = 0.0;
  /// The part of brake_energy_J done while the drive power is above 2% of the wheel power
  /// (braking against the engine), J: node by node, each node's brake power counted when its
  /// drive power is above that.
  double brake_energy_under_drive_J = 0.0;
  /// Highest |d pedal / dt| and |d steer / dt| between neighbouring nodes, 1/s and rad/s.
  double max_pedal_rate_per_s = 0.0, max_steer_rate_radps = 0.0;
};
/// `wheel_power` (W, the drive's maximum) sets the 2% threshold of brake_energy_under_drive_J.
OptimalLapFigures CalcOptimalLapFigures(const OptimalLapRun& run, double wheel_power);

}  // namespace hotlap::ocp
