#pragma once
/// @file
/// Cautions by Monte Carlo (docs/race.md): a plan raced many times with cautions drawn at random
/// (a per-lap rate from the public counts) and at each stage end, each a few slow laps behind the
/// pace car that burn less fuel and wear nothing, with cheap stops but pit road closed on the lap
/// the caution comes out, and a green stop that a caution catches costing a lap.

#include <cstdint>
#include <vector>

#include "hotlap/race/race_plan.h"

namespace hotlap::race {

struct CautionModel {
  double rate_per_lap = 0.0;   ///< chance a green lap brings out a caution (0: none at random)
  bool stage_cautions = true;  ///< a caution after each stage end
  int length_laps = 6;         ///< laps behind the pace car
  double lap_time_s = 65.0;    ///< a lap behind the pace car
  double fuel_share = 0.4;     ///< of a green lap's burn
  uint64_t seed = 1;

  /// No cautions at all: the race the deterministic plan assumes.
  static CautionModel Off();
};

/// The Southern 500's record (../shared/data/facts/run-and-race.md): 2023, 8 cautions for 51 laps
/// with two of them the stage ends: 6 at random over 316 green laps, about 6 laps each.
CautionModel SouthernFiveHundredCautions();

struct MonteCarloResult {
  int races = 0;
  double mean_time_s = 0.0;
  double standard_error_s = 0.0;       ///< of the mean
  double mean_cautions = 0.0;          ///< per race, the stage ends' included
  std::vector<int> caution_histogram;  ///< races with k cautions at index k
};

/// One race of `plan`'s stops (a fixed plan: its stops on their laps; one due on the lap a caution
/// comes out is made a lap later) under cautions drawn from `model` with `draw` (the race's own
/// stream); its time, s. `caution_starts` (if given) gets the first lap of each caution.
double RaceUnderCautions(const RaceRules& rules, const FallOff& fall_off,
                         const std::vector<PitStop>& stops, const CautionModel& model,
                         uint64_t stream, std::vector<int>* caution_starts = nullptr);

/// `races` races of the plan, stream i for race i (each race's time in `times` if given). With
/// CautionModel::Off() every race is the plan's deterministic time (EvaluatePlan) exactly.
/// InputError for races < 1 or a rate outside [0, 1].
MonteCarloResult SimulatePlan(const RaceRules& rules, const FallOff& fall_off,
                              const std::vector<PitStop>& stops, const CautionModel& model,
                              int races, std::vector<double>* times = nullptr);

/// What plan a gains over plan b race by race, from their times in the same races (SimulatePlan's
/// `times`, the same streams): the mean and standard error of b - a, free of the races' common
/// spread. InputError unless both have the same, non-zero number of races.
MonteCarloResult GainOver(const std::vector<double>& a_times, const std::vector<double>& b_times);

}  // namespace hotlap::race
