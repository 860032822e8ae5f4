#pragma once
/// @file
/// What `hotlap stint` prints and writes of a stint (ocp/stint.h; keys in docs/json-output.md):
/// the per-lap table, the channels of the whole stint as CSV with a lap column, the JSON summary
/// and the HTML report (the lap-time fall-off of the stint and of the greedy driver, per-lap
/// temperature envelopes, cumulative wear per corner).

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/ocp/stint.h"
#include "hotlap/sim/replay_io.h"

namespace hotlap::ocp {

/// OptimalLapColumns over the whole stint, with `lap` (1..N; a node on a lap line starts the next
/// lap) and `lap_distance_m` (centre-line distance from that lap's line) after `distance_m`.
sim::ColumnSet StintColumns(const StintResult& result, const track::Track& track);

/// The per-lap table (lap time, greedy lap time, top speed, peaks, wear, fuel) and the totals.
std::string StintText(const StintResult& result);

/// The summary: `laps[]`, `greedy_laps[]`, `total_time_s`, `greedy_total_time_s`,
/// `managing_gain_s`, `solve_time_s`, `ipopt_iterations`, `status`, ... (docs/json-output.md).
nlohmann::json StintJson(const StintResult& result, const StintOptions& options,
                         const std::string& track_name, const vehicle::Car& car,
                         double wall_time_s);

/// Creates `out` and writes stint.csv (StintColumns) and stint.html; returns their paths.
std::vector<std::filesystem::path> WriteStintFiles(const std::filesystem::path& out,
                                                   const StintResult& result,
                                                   const StintOptions& options,
                                                   const vehicle::Car& car,
                                                   const track::Track& track);

}  // namespace hotlap::ocp
