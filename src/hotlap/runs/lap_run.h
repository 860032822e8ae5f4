#pragma once
/// @file
/// The quasi-steady-state lap run as `hotlap lap --method qss` and Python's `hotlap.qss_lap` make
/// it: the road along the chosen line, the options and starting temperatures from plain values,
/// the laps, and what is written of them (lap.csv, lap.html, the JSON summary). The command and
/// the binding parse their own arguments into LapRunOptions and call these, nothing else.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/runs/option_name.h"
#include "hotlap/sim/lap_summary.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::runs {

/// A QSS lap run's options, in the units the command line and Python take (degC, km/h, m).
struct LapRunOptions {
  /// The path driven: "min-curvature" (the minimum-curvature racing line), "centre", or a CSV
  /// file with distance_m and offset_m columns (e.g. `hotlap optimise`'s channels).
  std::string line = "min-curvature";
  double line_margin_m = 1.5;  ///< space the racing line keeps from each edge
  double step_m = 1.0;         ///< distance between road points
  int laps = 1;                ///< laps in the stint, in [1, 1000]
  double ambient_C = 25.0;
  double track_C = 40.0;
  /// Starting temperatures, degC; the car file's where not given.
  std::optional<double> tread_C, carcass_C, disc_C, calliper_C, rim_C, disc_bulk_C;
  std::string caution_laps;          ///< laps behind the pace car, e.g. "11-15,40"
  double caution_speed_kph = 110.0;  ///< the pace car's speed
};

/// What a run is made of before it runs: the road and the simulation's options.
struct LapPlan {
  std::vector<sim::RoadPoint> road;
  sim::QssOptions options;
};

/// The road points along `line` (as LapRunOptions::line) every `step_m`.
std::vector<sim::RoadPoint> SampleLapRoad(const track::Track& track, const std::string& line,
                                          double step_m, double line_margin_m);

/// The road and options of a run, every option checked (InputError naming it in `style`).
LapPlan PlanLap(const vehicle::Car& car, const track::Track& track, const LapRunOptions& options,
                NameStyle style);

/// The laps, their summary and their channels as CSV columns.
struct LapRun {
  sim::QssResult result;
  sim::StintSummary stint;
  sim::ColumnSet columns;
};

/// Runs the planned laps (no Python and no output: safe without the GIL).
LapRun RunLap(const vehicle::Car& car, const track::Track& track, const LapPlan& plan);

/// The files a run writes into its folder.
struct LapFiles {
  std::filesystem::path csv;   ///< lap.csv: every channel, with the run's metadata lines
  std::filesystem::path html;  ///< lap.html: the report
};

/// Writes lap.csv and lap.html into `out` (created), each atomically.
LapFiles WriteLapFiles(const std::filesystem::path& out, const LapRun& run,
                       const LapRunOptions& options, const vehicle::Car& car,
                       const track::Track& track);

}  // namespace hotlap::runs
