#pragma once
// What `hotlap optimise` and `hotlap lap --method ocp` print and write of a solved lap: the JSON
// object of one run (docs/json-output.md), its terminal summary and its CSV.

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/ocp/disc_limit_comparison.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::app {

/// One run's JSON object; `thermal_start` is the --thermal-start given.
nlohmann::json RunJson(const ocp::SolvedLap& s, const std::string& thermal_start);

/// `fmtstr` of the value, or "-".
std::string Opt(const std::optional<double>& v, const char* fmtstr);

/// One run's summary on the terminal.
void PrintRun(const ocp::SolvedLap& s, const std::string& thermal_start);

/// One run's channels as CSV in the shared format.
void WriteRunCsv(const std::filesystem::path& path, const ocp::SolvedLap& s,
                 const track::Track& track, const vehicle::Car& car);

}  // namespace hotlap::app
