#include "hotlap/race/race_rules.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::race {

int RaceRules::FuelWindow() const {
  return static_cast<int>(std::floor(fuel_capacity_kg / fuel_per_lap_kg + 1e-9));
}

double RaceRules::FuelAboard(int laps_left) const {
  return fuel_capacity_kg - (FuelWindow() - laps_left) * fuel_per_lap_kg;
}

bool RaceRules::EndsStage(int lap) const {
  return std::find(stage_ends.begin(), stage_ends.end(), lap) != stage_ends.end();
}

RaceRules SouthernFiveHundred() {
  RaceRules r;
  r.laps = 367;
  r.stage_ends = {115, 230};
  r.fuel_capacity_kg = 50.4;     // 18 US gal of E15 at 0.74 kg/L (the most cited cell; facts: L)
  r.fuel_per_lap_kg = 0.90;      // assumed: about 3.9 mpg over a 1.366 mi lap; a window of 56 laps
  r.tyre_sets = 13;              // Goodyear: 12 race sets and the qualifying set
  r.pit_loss_s = 33.0;           // assumed: the stop's pit-road time less the lap it replaces
  r.caution_pit_loss_s = 15.0;   // assumed: under caution the field laps slowly
  r.tyre_service_s = 11.8;       // the best crews' four-tyre averages, 2022 (facts: M)
  r.fuel_rate_kg_per_s = 4.5;    // assumed: a full cell in about 11 s, as long as the tyres
  r.right_side_stops = false;    // Goodyear: four tyres at every stop at Darlington
  r.right_tyre_service_s = 6.5;  // assumed: a little over half the four-tyre stop
  return r;
}

void CheckRaceRules(const RaceRules& r) {
  const auto fail = [](const std::string& what) { throw InputError("race rules: " + what); };
  if (r.laps <= 0) fail(fmt::format("laps {} must be > 0", r.laps));
  int previous = 0;
  for (int end : r.stage_ends) {
    if (end <= previous || end >= r.laps) {
      fail(fmt::format("stage end {} must be increasing and inside the race (1 to {})", end,
                       r.laps - 1));
    }
    previous = end;
  }
  if (!(r.fuel_per_lap_kg > 0.0))
    fail(fmt::format("fuel per lap {:g} kg must be > 0", r.fuel_per_lap_kg));
  if (!(r.fuel_capacity_kg >= r.fuel_per_lap_kg)) {
    fail(fmt::format("the fuel cell ({:g} kg) holds less than one lap's burn ({:g} kg)",
                     r.fuel_capacity_kg, r.fuel_per_lap_kg));
  }
  if (r.tyre_sets < 1) fail(fmt::format("tyre sets {} must be >= 1", r.tyre_sets));
  for (const auto& [value, name] :
       {std::pair{r.pit_loss_s, "pit loss"}, std::pair{r.caution_pit_loss_s, "caution pit loss"},
        std::pair{r.tyre_service_s, "tyre service"},
        std::pair{r.right_tyre_service_s, "right-side tyre service"}}) {
    if (!(value >= 0.0 && std::isfinite(value))) {
      fail(fmt::format("{} {:g} s must be finite and >= 0", name, value));
    }
  }
  if (!(r.fuel_rate_kg_per_s > 0.0)) {
    fail(fmt::format("fuel rate {:g} kg/s must be > 0", r.fuel_rate_kg_per_s));
  }
}

}  // namespace hotlap::race
