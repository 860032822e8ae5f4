#pragma once
/// @file
/// What `hotlap replay` writes of a replay besides its channels: the JSON summary
/// (docs/json-output.md) and the HTML report (docs/reports.md), from the corners' summaries
/// (SummarizeReplay).

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/sim/replay.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// A temperature's statistics as "peak/mean/final" in degC, one decimal each.
std::string TemperatureStatsText(const HistoryStats& stats);

/// The summary: the inputs (the car by its name and overrides), samples and duration, and per
/// corner each temperature's peak, mean and final value (degC), the wear, the lowest grip factor
/// and the brake energy.
/// The terminal table of the gas-and-rim tyres' gas, rim and hot pressure, the bulk discs' bulk,
/// and each corner's energy audit over the run (work, heat, their ratio, the largest closure);
/// empty when no corner has those models.
std::string ReplayHeatText(const ReplayResult& result,
                           const std::array<CornerReplaySummary, 4>& summaries);

nlohmann::json ReplayJson(const ReplayResult& result,
                          const std::array<CornerReplaySummary, 4>& corners,
                          const std::string& telemetry, const vehicle::Car& car,
                          const std::string& out_csv);

/// Writes the report to `path` atomically: the inputs (with the log's metadata), the per-corner
/// summary table and every history against time, one chart per quantity.
void WriteReplayReport(const std::filesystem::path& path, const std::string& telemetry,
                       const std::string& out_csv, const vehicle::Car& car,
                       const std::vector<std::pair<std::string, std::string>>& log_metadata,
                       const ReplayResult& result,
                       const std::array<CornerReplaySummary, 4>& corners);

}  // namespace hotlap::sim
