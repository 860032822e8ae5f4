#pragma once
/// @file
/// What `hotlap optimise` and `hotlap lap --method ocp` print of their laps: each lap's summary
/// (times, speeds, thermal start, brake work, turns, per corner peaks) and what the disc limit
/// costs, as text of whole lines.

#include <optional>
#include <string>
#include <vector>

#include "hotlap/ocp/disc_limit_comparison.h"

namespace hotlap::ocp {

/// `format` (one fmt field) of the value, or "-" where there is none.
std::string OptionalText(const std::optional<double>& v, const char* format);

/// One lap's summary, indented lines each ending in a newline; `thermal_start` is its mode's name.
std::string SolvedLapText(const SolvedLap& lap, const std::string& thermal_start);

/// The lap's set-up sensitivities ranked by the size of their typical step's effect ("+1 psi
/// right-rear cold pressure: -0.36 ms"), indented lines each ending in a newline; "" if none.
std::string SensitivitiesText(const SolvedLap& lap);

/// The lap's set-up sensitivities, largest typical-step effect first (ties in their given order).
std::vector<const LapSensitivity*> RankedSensitivities(const SolvedLap& lap);

/// How each set-up step changes what the limit costs: the limited lap's typical-step effect minus
/// the free lap's, ranked by its size, one line per parameter both laps have ("+0.1 front-left
/// duct: -2.25 ms of the limit's cost"); "" unless both laps have sensitivities.
std::string LimitCostSensitivitiesText(const SolvedLap& free, const SolvedLap& limited);

/// A parameter's effect on both laps of the comparison (LimitCostSensitivities).
struct LimitCostSensitivity {
  const LapSensitivity* free = nullptr;
  const LapSensitivity* limited = nullptr;
  /// d(limited lap time - free lap time)/dp, s per unit of the parameter.
  double d_cost_per_unit() const {
    return limited->d_lap_time_per_unit - free->d_lap_time_per_unit;
  }
  double typical_cost_effect_s() const { return d_cost_per_unit() * free->parameter.typical_step; }
};

/// The parameters both laps have sensitivities for, ranked by the size of their typical step's
/// effect on the limit's cost; empty unless both laps have sensitivities.
std::vector<LimitCostSensitivity> LimitCostSensitivities(const SolvedLap& free,
                                                         const SolvedLap& limited);

/// What the limit costs: the lap time and top speed without and with it, and each turn's lift and
/// brake points, then (LimitCostSensitivitiesText) what each set-up step does to the cost where
/// both laps have sensitivities, lines each ending in a newline.
std::string DiscLimitCostText(const SolvedLap& free, const SolvedLap& limited);

}  // namespace hotlap::ocp
