#pragma once
/// @file
/// From a telemetry log to replay inputs and back: which columns a replay reads, where its
/// starting temperatures come from, and the columns it writes (spec telemetry-csv.md).

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay.h"

namespace hotlap::sim {

/// Temperatures given on the command line, K; each used when the log has no measured value.
struct InitialTemperatureOverrides {
  std::optional<double> tread_temp, carcass_temp, disc_temp, calliper_temp;
  std::optional<double> rim_temp, disc_bulk_temp;  ///< the gas-and-rim tyre's, the bulk disc's
  std::optional<double> ambient_temp, track_temp;  ///< used when the log has no such column
};

/// Reads the replay inputs from a log: per corner speed (speed_<c> or speed), fx, fy, fz,
/// slip_angle, slip_ratio; ambient_temp and track_temp columns, else the overrides. Gaps are
/// filled linearly. InputError (naming the file and the missing column) if something is absent.
/// A corner's brake_power column, where the log has one, is its brake's heat input (brake_fx,
/// brake::BrakeFxFromPower); without one the brake sees u max(-fx, 0).
ReplayInputs ReplayInputsFromTelemetry(const Telemetry& log,
                                       const InitialTemperatureOverrides& overrides);

/// The car's starting state (CarStartState) with each temperature the overrides give (K) in its
/// place: the start of a lap simulation.
ReplayInitialState CarStartState(const vehicle::Car& car, const InitialTemperatureOverrides& o);

/// Starting state per corner: the first measured value of tread_temp_<c>, carcass_temp_<c>,
/// disc_temp_<c>, calliper_temp_<c>; else the overrides; else the car file (the rim and disc bulk,
/// which no logger reads: the overrides, else the car file). Wear starts at 0.
ReplayInitialState InitialStateFor(const Telemetry& log, const vehicle::Car& car,
                                   const InitialTemperatureOverrides& overrides);

/// The result as CSV columns in canonical units (temperatures in degC): time_s, then per corner
/// tread_temp_<c>_C, carcass_temp_<c>_C, wear_<c>_mm, grip_factor_<c>, disc_temp_<c>_C,
/// calliper_temp_<c>_C, brake_power_<c>_W, and q1_<c>_W .. q7_<c>_W when recorded.
struct ColumnSet {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  ///< [column][row]
};
ColumnSet ReplayResultColumns(const ReplayResult& result, bool with_heat_flows);

}  // namespace hotlap::sim
