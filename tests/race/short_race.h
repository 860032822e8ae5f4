#pragma once
// A short race and a linear fall-off for the tests of the plan and the policy.

#include "hotlap/race/fall_off.h"
#include "hotlap/race/race_rules.h"

namespace hotlap::race::testing {

// A 60-lap race, 25 laps to a cell: at least two stops.
inline RaceRules ShortRace() {
  RaceRules r;
  r.laps = 60;
  r.stage_ends = {20, 40};
  r.fuel_per_lap_kg = 1.0;
  r.fuel_capacity_kg = 25.5;
  r.tyre_sets = 4;
  r.pit_loss_s = 30.0;
  r.caution_pit_loss_s = 12.0;
  r.tyre_service_s = 11.0;
  r.fuel_rate_kg_per_s = 2.5;
  return r;
}

// A cold out lap, then a set that loses `per_lap` s a lap; fuel weighs 0.03 s/kg.
inline FallOff Linear(double per_lap, int table = 30) {
  FallOff f;
  f.reference_fuel_kg = 12.0;
  f.fuel_s_per_kg = 0.03;
  for (int a = 0; a < table; ++a) f.lap_time_s.push_back(30.0 + (a == 0 ? 1.2 : 0.0) + per_lap * a);
  return f;
}

}  // namespace hotlap::race::testing
