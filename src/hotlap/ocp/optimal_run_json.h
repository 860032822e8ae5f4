#pragma once
/// @file
/// The JSON summary of an optimal-lap run (`hotlap optimise --json`, `hotlap lap --method ocp
/// --json`; docs/json-output.md).

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/ocp/optimal_run.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ocp {

/// One lap's object: lap and QSS times, the solve (and the coarse one), the disc limit, speeds,
/// per corner the peak temperatures and wear, the turns' lift and brake points, the thermal start
/// (`thermal_start` is its mode's name), brake energy, control rates and the problem's size.
nlohmann::json SolvedLapJson(const SolvedLap& lap, const std::string& thermal_start);

/// The run's summary: one lap's object with "command": "optimise", or for the comparison both
/// ("unconstrained", "constrained"), "delta_s" and the free lap's headline keys at the top level;
/// then the track, car (its name and overrides), mesh spacing, `wall_time_s` and, where given, the
/// mesh check's change of the lap time.
nlohmann::json OptimalRunsJson(const OptimalRuns& runs, const OptimalRunOptions& options,
                               const std::string& track_name, const vehicle::Car& car,
                               double wall_time_s,
                               const std::optional<double>& mesh_check_delta_s = std::nullopt);

}  // namespace hotlap::ocp
