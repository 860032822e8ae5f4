#pragma once
/// @file
/// The JSON summary of an optimal-lap run (`hotlap optimise --json`, `hotlap lap --method ocp
/// --json`; docs/json-output.md).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/ocp/optimal_run.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ocp {

/// One lap's object: lap and QSS times, the solve (and the coarse one), the disc limit, speeds,
/// per corner the peak temperatures and wear, the turns' lift and brake points, the thermal start
/// (`thermal_start` is its mode's name), brake energy, control rates, the problem's size and the
/// set-up sensitivities (null if not computed).
nlohmann::json SolvedLapJson(const SolvedLap& lap, const std::string& thermal_start);

/// The set-up sensitivities: a list of {key, label, unit, value, step, d_lap_time_s_per_unit,
/// typical_step, typical_step_text, typical_step_effect_ms} (docs/json-output.md).
nlohmann::json SensitivitiesJson(const std::vector<LapSensitivity>& sensitivities);

/// What each set-up step does to the disc limit's cost (LimitCostSensitivities), ranked: a list of
/// {key, label, unit, d_delta_s_per_unit, typical_step_text, typical_step_effect_ms}; null unless
/// both laps have sensitivities.
nlohmann::json LimitCostSensitivitiesJson(const SolvedLap& free, const SolvedLap& limited);

/// The run's summary: one lap's object with "command": "optimise", or for the comparison both
/// ("unconstrained", "constrained"), "delta_s" and the free lap's headline keys at the top level;
/// then the track, car (its name and overrides), mesh spacing, `wall_time_s` and, where given, the
/// mesh check's change of the lap time.
nlohmann::json OptimalRunsJson(const OptimalRuns& runs, const OptimalRunOptions& options,
                               const std::string& track_name, const vehicle::Car& car,
                               double wall_time_s,
                               const std::optional<double>& mesh_check_delta_s = std::nullopt);

}  // namespace hotlap::ocp
