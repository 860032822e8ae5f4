#pragma once
// A short race and a linear fall-off for the tests of the plan and the policy.

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <limits>
#include <vector>

#include "hotlap/common/error.h"
#include "hotlap/race/fall_off.h"
#include "hotlap/race/race_plan.h"
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

// Every plan of up to three stops, each of the given services, that the rules allow: the least
// time.
inline double BruteForce(const RaceRules& r, const FallOff& f,
                         std::initializer_list<Service> services = {Service::kFuelOnly,
                                                                    Service::kFourTyresAndFuel}) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<PitStop> stops;
  const std::function<void(int)> go = [&](int from) {
    try {
      best = std::min(best, EvaluatePlan(r, f, stops, "brute").race_time_s);
    } catch (const InputError&) {
    }
    if (stops.size() == 3) return;
    for (int lap = from; lap < r.laps; ++lap) {
      for (Service s : services) {
        stops.push_back({lap, s, 0.0});
        go(lap + 1);
        stops.pop_back();
      }
    }
  };
  go(1);
  return best;
}

}  // namespace hotlap::race::testing
