#pragma once
/// @file
/// A plan's laps as the tyres and brakes see them: each lap's per-corner state taken from the
/// fall-off's laps at the corner's age on its tyres (FallOff::set_laps: the left tyres at the
/// left age, the right at the right age after right-side stops), and the runs between tyre
/// changes with their wear and hottest laps (docs/race.md, "Each run's temperatures and wear").

#include <array>
#include <vector>

#include "hotlap/race/fall_off.h"
#include "hotlap/race/race_plan.h"

namespace hotlap::race {

/// The state of every lap of the plan (lap k + 1 at index k), per corner. Past the fall-off's
/// table a corner's temperatures are its last lap's and its wear grows at the last ten laps'
/// rate. Empty if the fall-off kept no set laps.
std::vector<SetLap> PlanLapStates(const RacePlan& plan, const FallOff& fall_off);

/// One run between tyre changes (a fuel-only stop does not end one).
struct PlanRun {
  int first_lap = 0, last_lap = 0;              ///< 1-based, inclusive
  Service fitted = Service::kFourTyresAndFuel;  ///< what started it (the first: the starting set)
  std::array<double, 4> wear_mm{};              ///< each tyre's wear at the run's end
  std::array<double, 4> peak_tread_temp{};      ///< the hottest lap's time-mean tread, K
  std::array<double, 4> peak_carcass_temp{};    ///< K
  std::array<double, 4> peak_disc_temp{};       ///< K
  std::array<double, 4> end_pressure{};         ///< the last lap's mean hot gauge pressure, Pa
};

/// The runs of the plan, from its lap states (PlanLapStates).
std::vector<PlanRun> PlanRuns(const RacePlan& plan, const std::vector<SetLap>& laps);

}  // namespace hotlap::race
