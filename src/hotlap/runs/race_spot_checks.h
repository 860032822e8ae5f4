#pragma once
/// @file
/// The race's fall-off against optimal laps (docs/race.md, "QSS against the optimal lap"): at a
/// few ages of the set, the minimum-time lap from the state the fall-off's QSS laps reach there
/// (temperatures, pressures and wear), beside the QSS lap of that age. Says how far the strategy's
/// quasi-steady laps are from what a driver on the limit would do, in each lap and in the
/// fall-off between ages, which is what the plans use. `hotlap race --spot-checks` and Python's
/// `hotlap.race(spot_checks=...)` call these.

#include <functional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/race/fall_off.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::runs {

struct RaceSpotCheck {
  int age = 0;                      ///< laps on the set before this one (0: the out lap)
  double qss_lap_time_s = 0.0;      ///< the fall-off's lap at this age
  double optimal_lap_time_s = 0.0;  ///< the minimum-time lap from the same state
  /// The four tyres' time-mean tread temperature (K) and grip factor g(T) h(wear) over each lap:
  /// what the two laps make of the same start.
  double qss_tread_temp = 0.0, optimal_tread_temp = 0.0;
  double qss_grip = 0.0, optimal_grip = 0.0;
  bool converged = false;  ///< the optimal lap's solve
  int iterations = 0;      ///< its Ipopt iterations, coarse and fine (and of a failed start)
};

struct RaceSpotChecks {
  double step_m = 0.0;  ///< the optimal laps' mesh
  std::vector<RaceSpotCheck> checks;
  /// Between the first and the last age checked: the QSS laps' fall-off and the optimal laps'.
  double qss_fall_off_s = 0.0, optimal_fall_off_s = 0.0;
  double seconds = 0.0;  ///< wall time
};

/// Ages such as "2,30,59" (laps on the set, increasing, each in [0, fall_off_laps - 1]); empty
/// text: none. InputError naming `option` otherwise.
std::vector<int> ParseSpotCheckAges(const std::string& text, int fall_off_laps,
                                    std::string_view option);

/// The checks: the QSS laps from `qss.initial` on `road` (the fall-off's, so the states are its),
/// then at each age the optimal lap of `track` on a `step_m` mesh from the state there (its
/// ambient and track temperatures `qss`'s). `progress`, if given, is told of each solve.
RaceSpotChecks RunRaceSpotChecks(const vehicle::Car& car, const track::Track& track,
                                 std::span<const sim::RoadPoint> road, const sim::QssOptions& qss,
                                 const race::FallOff& fall_off, const std::vector<int>& ages,
                                 double step_m,
                                 const std::function<void(const std::string&)>& progress = {});

/// The checks as the JSON summary's `spot_checks` (docs/json-output.md).
nlohmann::json RaceSpotChecksJson(const RaceSpotChecks& checks);

/// The checks as the terminal's lines.
std::string RaceSpotChecksText(const RaceSpotChecks& checks);

}  // namespace hotlap::runs
