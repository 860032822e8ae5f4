#pragma once
/// @file
/// The JSON summary of `hotlap lap --method qss --json` (docs/json-output.md).

#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/sim/lap_summary.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// The stint's summary: track, car (its name and overrides), each lap's time and speeds, the last
/// lap's at the top level, the braking zones, per corner the peaks (degC) and wear, the slip points
/// not reached and the output files' paths.
nlohmann::json StintJson(const StintSummary& stint, const track::Track& track,
                         const vehicle::Car& car, const std::string& out_csv,
                         const std::string& out_report);

}  // namespace hotlap::sim
