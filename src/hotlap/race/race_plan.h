#pragma once
/// @file
/// The race plan: on which laps to stop and what to do there (four tyres and fuel, or fuel only),
/// chosen by dynamic programming over the laps with the tyre set's age, the fuel aboard and the
/// sets used as the state, to the least race time under the rules (docs/race.md). Deterministic:
/// no cautions but the stage ends.

#include <string>
#include <vector>

#include "hotlap/race/fall_off.h"
#include "hotlap/race/race_rules.h"

namespace hotlap::race {

enum class Service {
  kFourTyresAndFuel,  ///< four new tyres, the cell filled
  kFuelOnly,          ///< the cell filled, the tyres kept
};

struct PitStop {
  int lap = 0;  ///< the stop is made at the end of this lap
  Service service = Service::kFourTyresAndFuel;
  double time_lost_s = 0.0;  ///< pit loss and service
};

struct RacePlan {
  std::string name;                ///< "optimal", or the fixed plan's name
  std::vector<PitStop> stops;      ///< in lap order
  std::vector<double> lap_time_s;  ///< per lap, stops not included
  double race_time_s = 0.0;        ///< the laps and the stops
  int tyre_sets_used = 0;          ///< the starting set included
};

/// The time a stop loses: the pit loss (green, or under a stage end's caution) and the longer of
/// the tyre change and the fill of `fuel_added_kg`.
double StopTime(const RaceRules& rules, int lap, Service service, double fuel_added_kg);

/// The race run with the given stops (lap order, each inside the race): its lap times, stops and
/// total. InputError if the fuel runs out or more tyre sets are used than the rules allow.
RacePlan EvaluatePlan(const RaceRules& rules, const FallOff& fall_off,
                      const std::vector<PitStop>& stops, std::string name);

/// The least-time plan (CheckRaceRules first). Its race time is never more than any plan
/// EvaluatePlan accepts.
RacePlan OptimalPlan(const RaceRules& rules, const FallOff& fall_off);

/// The fixed plans a crew chief would try: four tyres and fuel as late as the fuel allows
/// ("fuel windows"), and the same but stopping at each stage end ("stage ends"); those the rules
/// allow.
std::vector<RacePlan> FixedPlans(const RaceRules& rules, const FallOff& fall_off);

}  // namespace hotlap::race
