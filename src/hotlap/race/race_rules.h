#pragma once
/// @file
/// The rules and numbers of a race that a strategy plays by: its length, stage ends, the fuel cell,
/// the tyre sets, the pit stop's cost (docs/race.md). SI units; laps counted from 1.

#include <vector>

namespace hotlap::race {

struct RaceRules {
  int laps = 0;                     ///< race length
  std::vector<int> stage_ends;      ///< laps after which a stage ends (a caution: cheap stops)
  double fuel_capacity_kg = 0.0;    ///< the fuel cell, full at the start
  double fuel_per_lap_kg = 0.0;     ///< burnt per green lap
  int tyre_sets = 0;                ///< sets for the race, the starting set included
  double pit_loss_s = 0.0;          ///< time a green-flag stop loses on pit road, service aside
  double caution_pit_loss_s = 0.0;  ///< the same at a stage end (the field is slow)
  double tyre_service_s = 0.0;      ///< four tyres changed
  /// Whether a stop may change the right-side tyres only (a set's right tyres; its left ones go
  /// on at a later four-tyre stop, so the sets the rules count are the right sides used).
  bool right_side_stops = false;
  double right_tyre_service_s = 0.0;  ///< the two right-side tyres changed
  double fuel_rate_kg_per_s = 0.0;    ///< how fast the can fills the cell

  /// Laps a full cell lasts (at least 1 for valid rules).
  int FuelWindow() const;
  /// The fuel aboard with `laps_left` laps of it, kg: the cell less what its laps since the fill
  /// burnt (the part of the cell under one lap's burn stays aboard).
  double FuelAboard(int laps_left) const;
  /// Whether lap `lap` ends a stage.
  bool EndsStage(int lap) const;
};

/// The Southern 500's (../shared/data/facts/run-and-race.md, docs/race.md): 367 laps, stages
/// ending at laps 115 and 230, 13 tyre sets (12 race sets and the qualifying set the car starts
/// on), four tyres at every stop; an 18 US gallon cell of 50.4 kg; the burn, the pit loss, the
/// fill rate and a right-side change's time (where right-side stops are allowed) assumed.
RaceRules SouthernFiveHundred();

/// InputError naming the first bad number (laps <= 0, a stage end outside the race or not
/// increasing, a cell smaller than one lap's burn, a negative pit loss or service, no tyre set).
void CheckRaceRules(const RaceRules& rules);

}  // namespace hotlap::race
