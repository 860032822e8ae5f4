#include "hotlap/race/race_run.h"

#include <chrono>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/sim/replay.h"

namespace hotlap::race {

CautionModel ParseCautions(const std::string& text, std::string_view option) {
  if (text == "record") return SouthernFiveHundredCautions();
  if (text == "off") return CautionModel::Off();
  CautionModel m = SouthernFiveHundredCautions();
  try {
    size_t used = 0;
    m.rate_per_lap = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw InputError(fmt::format("{} '{}': a rate per lap, 'record' or 'off'", option, text));
  }
  if (!(m.rate_per_lap >= 0.0 && m.rate_per_lap <= 1.0)) {
    throw InputError(fmt::format("{} {}: a caution rate must be in [0, 1] per lap", option, text));
  }
  return m;
}

std::vector<int> ParseStageEnds(const std::string& text, int laps, std::string_view option) {
  if (laps <= 0) throw InputError(fmt::format("race rules: laps {} must be > 0", laps));
  std::vector<int> ends;
  for (int l : sim::ParseLapList(text, laps, option)) ends.push_back(l + 1);
  return ends;
}

RaceRun RunRace(const vehicle::Car& car, double track_length_m,
                std::span<const sim::RoadPoint> road, const RaceRunOptions& o) {
  CheckRaceRules(o.rules);
  if (o.races < 0 || o.races > 1000000) {
    throw InputError(fmt::format("Monte Carlo races {} must be in [0, 1000000]", o.races));
  }
  if (!(o.cautions.rate_per_lap >= 0.0 && o.cautions.rate_per_lap <= 1.0)) {
    throw InputError(
        fmt::format("caution rate {:g} per lap must be in [0, 1]", o.cautions.rate_per_lap));
  }
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
  if (o.races > 0) {
    // Every plan on the same races: the optimal first, then the fixed plans.
    std::vector<std::vector<double>> times(1 + run.fixed.size());
    run.monte_carlo.push_back(
        SimulatePlan(o.rules, run.fall_off, run.plan.stops, o.cautions, o.races, &times[0]));
    size_t best = 0;
    for (size_t i = 0; i < run.fixed.size(); ++i) {
      run.monte_carlo.push_back(SimulatePlan(o.rules, run.fall_off, run.fixed[i].stops, o.cautions,
                                             o.races, &times[i + 1]));
      if (best == 0 || run.monte_carlo[i + 1].mean_time_s < run.monte_carlo[best].mean_time_s) {
        best = i + 1;
      }
    }
    if (best > 0) run.gain_under_cautions = GainOver(times[0], times[best]);
  }
  run.fall_off_seconds = std::chrono::duration<double>(curves - started).count();
  run.plan_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - curves).count();
  return run;
}

}  // namespace hotlap::race
