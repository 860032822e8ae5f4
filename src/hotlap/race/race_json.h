#pragma once
/// @file
/// What `hotlap race` reports (docs/race.md, docs/json-output.md "race"): the rules, the fall-off,
/// the optimal plan and the fixed plans it was tried against, as JSON and as terminal text.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/race/race_plan.h"

namespace hotlap::race {

/// One plan: name, race_time_s, tyre_sets_used, stops [{lap, service, time_lost_s}].
nlohmann::json PlanJson(const RacePlan& plan);

/// The whole report: rules, fall_off {laps, lap_time_s[], spread_s, fuel_s_per_kg,
/// reference_fuel_kg}, plan (the optimal), fixed_plans[], gain_over_best_fixed_s.
nlohmann::json RaceJson(const RaceRules& rules, const FallOff& fall_off, const RacePlan& plan,
                        const std::vector<RacePlan>& fixed);

/// The terminal summary of the same.
std::string RaceText(const RaceRules& rules, const FallOff& fall_off, const RacePlan& plan,
                     const std::vector<RacePlan>& fixed);

}  // namespace hotlap::race
