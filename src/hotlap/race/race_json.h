#pragma once
/// @file
/// What `hotlap race` reports (docs/race.md, docs/json-output.md "race"): the rules, the fall-off,
/// the optimal plan and the fixed plans it was tried against, as JSON and as terminal text.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/race/cautions.h"
#include "hotlap/race/race_plan.h"
#include "hotlap/race/race_run.h"

namespace hotlap::race {

/// One plan: name, race_time_s, tyre_sets_used, stops [{lap, service, time_lost_s}].
nlohmann::json PlanJson(const RacePlan& plan, const FallOff& fall_off);

/// The whole report: rules, fall_off {laps, lap_time_s[], spread_s, fuel_s_per_kg,
/// reference_fuel_kg}, plan (the optimal), fixed_plans[], gain_over_best_fixed_s, and monte_carlo
/// (null where the plans were not raced under cautions) {races, caution_rate_per_lap,
/// caution_laps, mean_cautions, plans [{name, mean_time_s, standard_error_s}], gain_over_best_fixed
/// {mean_s, standard_error_s}: the paired gain under the same cautions}.
nlohmann::json RaceJson(const RaceRun& run, const CautionModel& cautions);

/// The terminal summary of the same.
std::string RaceText(const RaceRun& run);

}  // namespace hotlap::race
