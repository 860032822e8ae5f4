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
  kFourTyresAndFuel,   ///< four new tyres, the cell filled
  kFuelOnly,           ///< the cell filled, the tyres kept
  kRightTyresAndFuel,  ///< two new right-side tyres, the cell filled (RaceRules::right_side_stops)
};

/// The service's name in the summaries ("four tyres and fuel", "right-side tyres and fuel",
/// "fuel only").
const char* ServiceName(Service service);
/// Its mark in a list of stops: "" four tyres, "r" right-side tyres, "f" fuel only.
const char* ServiceMark(Service service);

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
  int tyre_sets_used = 0;          ///< the starting set included (right sides: RaceRules)
  /// How far the plan may be from the least race time, s: 0 where the programme is exact; with
  /// right-side stops and the tyre sets binding, the Lagrangian bound's gap (docs/race.md).
  double optimality_gap_s = 0.0;
};

/// The service's time: the longer of the tyre change (four or two) and the fill of
/// `fuel_added_kg`.
double ServiceTime(const RaceRules& rules, Service service, double fuel_added_kg);

/// The time a stop loses: the pit loss (green, or under a stage end's caution) and the longer of
/// the tyre change and the fill of `fuel_added_kg`.
double StopTime(const RaceRules& rules, int lap, Service service, double fuel_added_kg);

/// The race run with the given stops (lap order, each inside the race): its lap times, stops and
/// total. InputError if the fuel runs out, more tyre sets are used than the rules allow, or a
/// right-side stop where the rules do not allow one.
RacePlan EvaluatePlan(const RaceRules& rules, const FallOff& fall_off,
                      const std::vector<PitStop>& stops, std::string name);

/// The least-time plan (CheckRaceRules first). Its race time is never more than any plan
/// EvaluatePlan accepts. Where the rules allow right-side stops, OptimalPlanWithRightSideStops.
RacePlan OptimalPlan(const RaceRules& rules, const FallOff& fall_off);

/// The least-time plan with right-side stops among the services (race_plan_sides.cc): a dynamic
/// programme over the two sides' ages (each kept up to `max_tyre_age` laps; 0: two fuel windows)
/// and the fuel, the tyre sets priced by a Lagrange multiplier where they bind (then
/// RacePlan::optimality_gap_s bounds how far from the least time the plan may be). InputError if
/// the fall-off has no side curves (FallOff::HasSides) or no plan meets the rules.
RacePlan OptimalPlanWithRightSideStops(const RaceRules& rules, const FallOff& fall_off,
                                       int max_tyre_age = 0);

/// The fixed plans a crew chief would try: four tyres and fuel as late as the fuel allows
/// ("fuel windows"), and the same but stopping at each stage end ("stage ends"); where the rules
/// allow right-side stops, the fuel windows' stops alternating right sides and four tyres
/// ("rights between"); those the rules allow.
std::vector<RacePlan> FixedPlans(const RaceRules& rules, const FallOff& fall_off);

}  // namespace hotlap::race
