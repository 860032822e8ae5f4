#pragma once
/// @file
/// The race run as `hotlap race` and Python's `hotlap.race` make it (docs/race.md): the fall-off
/// from the car's QSS laps on the given road, the optimal plan and the fixed plans.

#include <span>
#include <vector>

#include "hotlap/race/fall_off.h"
#include "hotlap/race/race_plan.h"
#include "hotlap/race/race_rules.h"
#include "hotlap/sim/qss_lap.h"

namespace hotlap::race {

struct RaceRunOptions {
  RaceRules rules = SouthernFiveHundred();
  int fall_off_laps = 60;           ///< QSS laps on a new set, 2 to 400
  double reference_fuel_kg = 25.0;  ///< the fuel the car's mass includes
  double ambient_temp = 298.15;     ///< K
  double track_temp = 313.15;       ///< K
};

struct RaceRun {
  RaceRules rules;
  FallOff fall_off;
  RacePlan plan;
  std::vector<RacePlan> fixed;
  double fall_off_seconds = 0.0;  ///< wall time of the QSS laps
  double plan_seconds = 0.0;      ///< wall time of the plans
};

/// The run. InputError for bad rules or options (before any lap is driven).
RaceRun RunRace(const vehicle::Car& car, double track_length_m,
                std::span<const sim::RoadPoint> road, const RaceRunOptions& options);

/// The stage ends of a list such as "115,230" (laps that end a stage, inside the race);
/// InputError naming `option` otherwise.
std::vector<int> ParseStageEnds(const std::string& text, int laps, std::string_view option);

}  // namespace hotlap::race
