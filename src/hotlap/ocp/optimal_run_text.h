#pragma once
/// @file
/// What `hotlap optimise` and `hotlap lap --method ocp` print of their laps: each lap's summary
/// (times, speeds, thermal start, brake work, turns, per corner peaks) and what the disc limit
/// costs, as text of whole lines.

#include <optional>
#include <string>

#include "hotlap/ocp/disc_limit_comparison.h"

namespace hotlap::ocp {

/// `format` (one fmt field) of the value, or "-" where there is none.
std::string OptionalText(const std::optional<double>& v, const char* format);

/// One lap's summary, indented lines each ending in a newline; `thermal_start` is its mode's name.
std::string SolvedLapText(const SolvedLap& lap, const std::string& thermal_start);

/// The lap's set-up sensitivities ranked by the size of their typical step's effect ("+1 psi
/// right-rear cold pressure: -0.36 ms"), indented lines each ending in a newline; "" if none.
std::string SensitivitiesText(const SolvedLap& lap);

/// What the limit costs: the lap time and top speed without and with it, and each turn's lift and
/// brake points, lines each ending in a newline.
std::string DiscLimitCostText(const SolvedLap& free, const SolvedLap& limited);

}  // namespace hotlap::ocp
