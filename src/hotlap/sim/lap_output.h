#pragma once
/// @file
/// What a lap simulation reports: the channels as CSV columns in the shared format, the braking
/// zones, and per-lap figures, from a QssResult.

#include <array>
#include <string>
#include <vector>

#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/track/track.h"

namespace hotlap::sim {

/// One stretch of braking (total longitudinal tyre force below zero and the car slowing by at
/// least `min_decel`), distances from its lap's start line.
struct BrakingZone {
  int lap = 0;               ///< 1-based
  double start_m = 0.0;      ///< where the braking starts
  double end_m = 0.0;        ///< where it ends
  double entry_speed = 0.0;  ///< m/s
  double exit_speed = 0.0;   ///< m/s
  double peak_decel = 0.0;   ///< m/s^2 (> 0)
  double duration_s = 0.0;
};

/// Braking zones of one lap: runs of samples whose longitudinal acceleration is below
/// -min_decel m/s^2, merged across gaps shorter than 10 m.
std::vector<BrakingZone> FindBrakingZones(const QssLap& lap, int lap_number,
                                          double min_decel = 0.5);

/// One corner's lap means (time-weighted), K and Pa; zero where the models have no such node.
struct CornerLapMeans {
  double tread = 0.0, carcass = 0.0, disc = 0.0;
  double gas = 0.0, rim = 0.0, pressure = 0.0, disc_bulk = 0.0;
  double peak_pressure = 0.0;
  double rolling_radius = 0.0;  ///< m, the lap's (QssLap::rolling_radius)
};

/// Per-lap figures.
struct LapFigures {
  double lap_time_s = 0.0;
  double top_speed = 0.0;                                        ///< m/s
  double min_speed = 0.0;                                        ///< m/s
  std::array<double, 4> peak_tread_temp{}, peak_carcass_temp{};  ///< K
  std::array<double, 4> peak_disc_temp{}, peak_calliper_temp{};  ///< K
  std::array<double, 4> wear{};                                  ///< mm lost on this lap
  std::array<CornerLapMeans, 4> means;                           ///< the lap's means
  std::array<CornerEnergyAudit, 4> audit;                        ///< the lap's energy audit
};

LapFigures CalcLapFigures(const QssLap& lap);

/// The whole stint as CSV columns (docs/lap-simulation.md): distance_m (along the centre line),
/// path_distance_m (along the driven line) and time_s from the stint's start, offset_m (the line's
/// lateral offset), lap, speed_mps, accelerations, steer, the car's x_m and y_m, ambient and track
/// temperatures, then per corner the inputs of the thermal models under their telemetry names
/// (speed_<c>_mps, fx_<c>_N, fy_<c>_N, fz_<c>_N, slip_angle_<c>_deg, slip_ratio_<c>) and the
/// replay's outputs (tread_temp_<c>_C ... brake_power_<c>_W), so the file can be replayed or
/// fitted as a log. Each lap's closing sample is dropped except the last lap's.
ColumnSet LapResultColumns(const QssResult& result, const track::Track& track, double ambient_temp,
                           double track_temp);

/// "cornering", "traction", "power", "braking" or "pace car".
const char* SpeedLimitName(SpeedLimit limit);

}  // namespace hotlap::sim
