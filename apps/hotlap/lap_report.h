#pragma once
/// @file
/// The HTML report of `hotlap lap --method qss` (docs/lap-simulation.md, docs/reports.md): summary
/// tables, every channel against stint distance, and the track map coloured by speed.

#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/sim/lap_output.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::app {

/// The run's settings the report names.
struct LapReportSettings {
  std::string line;  ///< --line
  int laps = 1;
  double ambient_C = 25.0;
  double track_C = 40.0;
};

/// Writes the report to `path` (atomically, as report::HtmlReport does).
void WriteLapReport(const std::filesystem::path& path, const LapReportSettings& a,
                    const vehicle::Car& car, const track::Track& track,
                    const sim::QssResult& result, const sim::ColumnSet& columns,
                    const std::vector<std::vector<std::string>>& lap_rows,
                    const std::vector<std::vector<std::string>>& corner_rows,
                    const std::vector<sim::BrakingZone>& zones);

}  // namespace hotlap::app
