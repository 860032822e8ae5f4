#pragma once
/// @file
/// The replay run as `hotlap replay` and Python's `hotlap.replay` make it: the starting and
/// ambient temperatures the options give (degC) where the log has none, the four tyres and four
/// brakes integrated over the log, the summaries and channels; the channels CSV with the run's
/// metadata and the text the command prints.

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "hotlap/logs/telemetry.h"
#include "hotlap/runs/option_name.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/replay_report.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::runs {

/// A replay run's options, in the units the command line and Python take (degC, s).
struct ReplayRunOptions {
  bool heat_flows = false;   ///< also q1..q7 of every tyre
  double max_step_s = 0.02;  ///< longest RK4 sub-step
  /// Starting temperatures where the log has none; air and track where it has no such column.
  std::optional<double> tread_C, carcass_C, disc_C, calliper_C, ambient_C, track_C;
};

/// The replay, its per-corner summaries and its channels.
struct ReplayRun {
  sim::ReplayResult result;
  std::array<sim::CornerReplaySummary, 4> summaries;
  sim::ColumnSet columns;
};

/// Replays `log` with `car` (no Python and no output: safe without the GIL). InputError for a
/// step that is not positive (named in `style`).
ReplayRun RunReplay(const vehicle::Car& car, const Telemetry& log, const ReplayRunOptions& options,
                    NameStyle style);

/// Writes the channels to `path` with the log's metadata and the run's (source, telemetry, car,
/// overrides), atomically.
void WriteReplayChannels(const std::filesystem::path& path, const ReplayRun& run,
                         const Telemetry& log, const vehicle::Car& car);

/// What `hotlap replay` prints: the log, MoTeC channels not mapped, each corner's temperatures,
/// wear and grip, and the heat over the log.
std::string ReplayRunText(const ReplayRun& run, const Telemetry& log, const vehicle::Car& car);

}  // namespace hotlap::runs
