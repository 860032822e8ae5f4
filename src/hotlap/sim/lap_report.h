#pragma once
/// @file
/// The HTML report of `hotlap lap --method qss` (docs/lap-simulation.md, docs/reports.md): summary
/// tables, every channel against stint distance, and the track map coloured by speed.

#include <filesystem>
#include <string>

#include "hotlap/sim/lap_summary.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// The run's settings the report names.
struct LapReportSettings {
  std::string line;  ///< the path driven: min-curvature, centre or a file
  int laps = 1;
  double ambient_C = 25.0;
  double track_C = 40.0;
};

/// Writes the report to `path` (atomically, as report::HtmlReport does): the laps, per corner
/// peaks and wear, and braking zones of `stint`, then the map and charts of `columns`
/// (LapResultColumns of the same stint).
void WriteLapReport(const std::filesystem::path& path, const LapReportSettings& settings,
                    const vehicle::Car& car, const track::Track& track, const ColumnSet& columns,
                    const StintSummary& stint);

}  // namespace hotlap::sim
