#include "hotlap/race/race_run.h"

#include <chrono>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/sim/replay.h"

namespace hotlap::race {

std::vector<int> ParseStageEnds(const std::string& text, int laps, std::string_view option) {
  if (laps <= 0) throw InputError(fmt::format("race rules: laps {} must be > 0", laps));
  std::vector<int> ends;
  for (int l : sim::ParseLapList(text, laps, option)) ends.push_back(l + 1);
  return ends;
}

RaceRun RunRace(const vehicle::Car& car, double track_length_m,
                std::span<const sim::RoadPoint> road, const RaceRunOptions& o) {
  CheckRaceRules(o.rules);
  if (o.fall_off_laps < 2 || o.fall_off_laps > 400) {
    throw InputError(fmt::format("fall-off laps {} must be in [2, 400]", o.fall_off_laps));
  }
  vehicle::RequireVehicle(car, "a race plan");
  const auto started = std::chrono::steady_clock::now();
  sim::QssOptions qss;
  qss.track_length = track_length_m;
  qss.ambient_temp = o.ambient_temp;
  qss.track_temp = o.track_temp;
  qss.initial = sim::CarStartState(car);  // a new set from the pit-out state
  RaceRun run;
  run.rules = o.rules;
  run.fall_off = FallOffFromQss(car, road, qss, o.fall_off_laps, o.reference_fuel_kg);
  const auto curves = std::chrono::steady_clock::now();
  run.plan = OptimalPlan(o.rules, run.fall_off);
  run.fixed = FixedPlans(o.rules, run.fall_off);
  run.fall_off_seconds = std::chrono::duration<double>(curves - started).count();
  run.plan_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - curves).count();
  return run;
}

}  // namespace hotlap::race
