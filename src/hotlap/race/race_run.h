#pragma once
/// @file
/// The race run as `hotlap race` and Python's `hotlap.race` make it (docs/race.md): the fall-off
/// from the car's QSS laps on the given road, the optimal plan and the fixed plans.

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hotlap/race/cautions.h"
#include "hotlap/race/fall_off.h"
#include "hotlap/race/race_plan.h"
#include "hotlap/race/race_policy.h"
#include "hotlap/race/race_rules.h"
#include "hotlap/sim/qss_lap.h"

namespace hotlap::race {

struct RaceRunOptions {
  RaceRules rules = SouthernFiveHundred();
  int fall_off_laps = 60;           ///< QSS laps on a new set, 2 to 400
  double reference_fuel_kg = 25.0;  ///< the fuel the car's mass includes
  double ambient_temp = 298.15;     ///< K
  double track_temp = 313.15;       ///< K
  /// Cautions for the Monte Carlo races (the record's by default; CautionModel::Off() none).
  CautionModel cautions = SouthernFiveHundredCautions();
  int races = 10000;  ///< Monte Carlo races of each plan (0: none)
  /// The stochastic programme's policy under the cautions (race_policy.h) beside the plans.
  bool policy = true;
  PolicyOptions policy_options;
  /// Where the fall-off is cached (fall_off_cache.h), keyed by the car's files and overrides
  /// (CarFilesKey), the road and the settings; empty: no cache.
  std::filesystem::path cache_dir;
  /// Told the fall-off's progress, a line at a time; may be empty.
  std::function<void(const std::string&)> progress;
};

/// The policy's part of a race run.
struct PolicyRun {
  RacePolicy policy;
  MonteCarloResult monte_carlo;  ///< its races, the same cautions as the plans'
  PolicyRaceStats stats;         ///< of its races
  /// Under the same cautions, what the policy gains over the fixed or optimal plan of least mean
  /// time (mean_time_s is the gain); races 0 where there was no Monte Carlo.
  MonteCarloResult gain_over_best_plan;
  std::string best_plan;  ///< its name
  /// For a caution out on each of these laps, the youngest set (filled with fuel at the same
  /// stop, with the sets the optimal plan has used by then) the policy changes for four new
  /// tyres; -1 where it would not.
  std::vector<int> caution_laps;
  std::vector<int> four_tyres_from_age;
  double seconds = 0.0;  ///< wall time of the programme and its races
};

struct RaceRun {
  RaceRules rules;
  FallOff fall_off;
  RacePlan plan;
  std::vector<RacePlan> fixed;
  /// Each plan raced under the cautions: the optimal first, then the fixed plans in order.
  std::vector<MonteCarloResult> monte_carlo;
  /// Under the same cautions, what the optimal plan gains over the fixed plan of least mean time
  /// (mean_time_s is the gain); races 0 where there was no Monte Carlo.
  MonteCarloResult gain_under_cautions;
  std::optional<PolicyRun> policy;  ///< where RaceRunOptions::policy asked for it
  /// With right-side stops allowed: one driven in QSS laps against the fall-off's two-age times.
  std::optional<SideStopCheck> side_check;
  bool fall_off_from_cache = false;      ///< read from the cache, not driven
  std::filesystem::path fall_off_cache;  ///< the cache file read or written; empty: none
  std::string cache_warning;             ///< why the cache could not be written, if it could not
  double fall_off_seconds = 0.0;         ///< wall time of the QSS laps (or the cache's read)
  double plan_seconds = 0.0;             ///< wall time of the plans
};

/// The QSS options the fall-off's laps run with: from the car's pit-out state on new tyres, the
/// options' weather.
sim::QssOptions FallOffQssOptions(const vehicle::Car& car, double track_length_m,
                                  const RaceRunOptions& options);

/// The run. InputError for bad rules or options (before any lap is driven).
RaceRun RunRace(const vehicle::Car& car, double track_length_m,
                std::span<const sim::RoadPoint> road, const RaceRunOptions& options);

/// A caution model from its text: "record" (SouthernFiveHundredCautions), "off", or a rate per
/// green lap in [0, 1] with the record's length; InputError naming `option` otherwise.
CautionModel ParseCautions(const std::string& text, std::string_view option);

/// The stage ends of a list such as "115,230" (laps that end a stage, inside the race);
/// InputError naming `option` otherwise.
std::vector<int> ParseStageEnds(const std::string& text, int laps, std::string_view option);

}  // namespace hotlap::race
