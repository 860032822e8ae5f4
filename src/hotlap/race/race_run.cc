#include "hotlap/race/race_run.h"

#include <chrono>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/fnv1a.h"
#include "hotlap/race/fall_off_cache.h"
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

namespace {

// The sets the plan has used by the end of lap `lap`, the starting set included.
int SetsUsedBy(const RacePlan& plan, int lap) {
  int sets = 1;
  for (const PitStop& s : plan.stops) {
    if (s.lap < lap && s.service == Service::kFourTyresAndFuel) ++sets;
  }
  return sets;
}

// The policy, its races on the plans' streams and its gain over the best of them (`plan_times`:
// the optimal plan's races, then the fixed plans'; empty without a Monte Carlo).
PolicyRun RunPolicy(const RaceRun& run, const RaceRunOptions& o,
                    const std::vector<std::vector<double>>& plan_times) {
  const auto started = std::chrono::steady_clock::now();
  PolicyRun out;
  out.policy = SolvePolicy(o.rules, run.fall_off, o.cautions, o.policy_options);
  if (!plan_times.empty()) {
    std::vector<double> times;
    out.monte_carlo = SimulatePolicy(out.policy, run.fall_off, o.races, &times, &out.stats);
    size_t best = 0;
    for (size_t i = 1; i < run.monte_carlo.size(); ++i) {
      if (run.monte_carlo[i].mean_time_s < run.monte_carlo[best].mean_time_s) best = i;
    }
    out.best_plan = best == 0 ? run.plan.name : run.fixed[best - 1].name;
    out.gain_over_best_plan = GainOver(times, plan_times[best]);
  }
  const int window = o.rules.FuelWindow();
  for (int lap = 25; lap < o.rules.laps; lap += 25) {
    int from = -1;
    for (int age = 1; age <= std::min(window, out.policy.max_age) && age < lap; ++age) {
      if (CautionDecision(out.policy, lap, age, age, SetsUsedBy(run.plan, lap)) ==
          Decision::kFourTyresAndFuel) {
        from = age;
        break;
      }
    }
    out.caution_laps.push_back(lap);
    out.four_tyres_from_age.push_back(from);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

// The right-side stops the fall-off drives where the rules allow them: after a quarter, a half,
// three quarters and all of its laps on the set.
std::vector<int> RightStopsFor(const RaceRunOptions& o) {
  std::vector<int> after;
  if (!o.rules.right_side_stops) return after;
  for (int k = 1; k <= 4; ++k) {
    const int a = std::max(1, k * o.fall_off_laps / 4);
    if (after.empty() || a > after.back()) after.push_back(a);
  }
  return after;
}

// The cache's key: the car's files, the road's points, every setting the laps depend on.
std::string FallOffKey(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
                       const sim::QssOptions& qss, const RaceRunOptions& o,
                       const CautionLaps& caution) {
  uint64_t h = Fnv1a64("road");
  for (const sim::RoadPoint& p : road) {
    h = Fnv1a64(std::string_view(reinterpret_cast<const char*>(&p), sizeof p), h);
  }
  return fmt::format(
      "{} | road {:016x} {} | track {:.17g} m, ambient {:.17g} K, track {:.17g} K | laps {}, fuel "
      "{:.17g} kg | caution {} after {} at {:.17g} m/s | right-side stops after {}",
      CarFilesKey(car), h, road.size(), qss.track_length, qss.ambient_temp, qss.track_temp,
      o.fall_off_laps, o.reference_fuel_kg, caution.laps, caution.after_green_laps, caution.speed,
      fmt::join(RightStopsFor(o), ","));
}

// The run's fall-off and right-side stop check into the cache; where it cannot be written, a
// warning and no cache.
void WriteCache(const std::filesystem::path& file, const std::string& key, RaceRun& run) {
  try {
    WriteCachedFallOff(file, key, run.fall_off, run.side_check);
  } catch (const InputError& e) {
    run.cache_warning = e.what();
    run.fall_off_cache.clear();
  }
}

// The fall-off (and the right-side stop check) from the cache into the run, where it holds this
// key and the car's first lap still drives as it did (a change of the models the key cannot
// see); whether it did.
bool ReadCache(const vehicle::Car& car, std::span<const sim::RoadPoint> road,
               const sim::QssOptions& qss, const std::string& key, RaceRun* run) {
  std::optional<SideStopCheck> check;
  std::optional<FallOff> cached = ReadCachedFallOff(run->fall_off_cache, key, &check);
  if (!cached) return false;
  sim::QssOptions one = qss;
  one.laps = 1;
  if (sim::RunQssLap(car, road, one).laps[0].lap_time != cached->lap_time_s[0]) return false;
  run->fall_off = std::move(*cached);
  run->side_check = std::move(check);
  return true;
}

}  // namespace

sim::QssOptions FallOffQssOptions(const vehicle::Car& car, double track_length_m,
                                  const RaceRunOptions& o) {
  sim::QssOptions qss;
  qss.track_length = track_length_m;
  qss.ambient_temp = o.ambient_temp;
  qss.track_temp = o.track_temp;
  qss.initial = sim::CarStartState(car);  // a new set from the pit-out state
  return qss;
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
  if (o.policy) CheckPolicyOptions(o.policy_options);
  vehicle::RequireVehicle(car, "a race plan");
  const auto started = std::chrono::steady_clock::now();
  const sim::QssOptions qss = FallOffQssOptions(car, track_length_m, o);
  RaceRun run;
  run.rules = o.rules;
  // A caution as the Monte Carlo drives it, after a third of the laps (at most 20) on the set.
  CautionLaps caution;
  if (o.cautions.rate_per_lap > 0.0 || o.cautions.stage_cautions) {
    caution.laps = o.cautions.length_laps;
    caution.after_green_laps = std::min(20, o.fall_off_laps / 3);
    caution.speed = track_length_m / o.cautions.lap_time_s;
    if (caution.after_green_laps < 1 ||
        caution.after_green_laps + caution.laps + FallOff::kRestartLaps > o.fall_off_laps) {
      caution.speed = 0.0;  // too few laps for it: no restart penalty
    }
  }
  std::string key;
  if (!o.cache_dir.empty()) {
    key = FallOffKey(car, road, qss, o, caution);
    run.fall_off_cache = FallOffCacheFile(o.cache_dir, key);
    run.fall_off_from_cache = ReadCache(car, road, qss, key, &run);
  }
  const bool driven = !run.fall_off_from_cache;
  if (driven) {
    FallOffRuns runs{
        .caution = caution, .right_stops_after = RightStopsFor(o), .progress = o.progress};
    run.fall_off = FallOffFromQss(car, road, qss, o.fall_off_laps, o.reference_fuel_kg, runs);
  }
  const bool check = o.rules.right_side_stops && !run.side_check;  // (a cache may lack it)
  if (check) {
    // A right-side stop between two of the fall-off's, driven against the interpolation.
    const int before = std::max(1, (3 * o.fall_off_laps) / 8);
    if (o.progress) {
      o.progress(fmt::format(
          "a right-side stop after {} laps driven, against the fall-off's two-age lap times",
          before));
    }
    run.side_check = CheckRightSideStop(car, road, qss, run.fall_off, before, o.fall_off_laps);
  }
  if (!key.empty() && (driven || check)) WriteCache(run.fall_off_cache, key, run);
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
    if (o.policy) run.policy = RunPolicy(run, o, times);
  } else if (o.policy) {
    run.policy = RunPolicy(run, o, {});
  }
  run.fall_off_seconds = std::chrono::duration<double>(curves - started).count();
  run.plan_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - curves).count();
  return run;
}

}  // namespace hotlap::race
