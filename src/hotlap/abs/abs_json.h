#pragma once
/// @file
/// The JSON summary of `hotlap abs --json` (docs/abs.md): a braking event's figures and, with the
/// scenarios, the ABS-against-locked comparison and the series of stops.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_scenarios.h"

namespace hotlap::sim {

/// The figures of one event: the stop, cycles, slip, lock, temperatures (degC) and energies.
nlohmann::json AbsMetricsJson(const AbsMetrics& metrics);

/// The whole summary: AbsMetricsJson of the event, the configuration, surface, ABS, vehicle mode,
/// speed and duration, the output files, and with `comparison` and `series` (both or neither
/// null) the scenarios.
nlohmann::json AbsRunJson(const AbsConfig& config, const AbsEvent& event, const AbsMetrics& metrics,
                          const std::string& out_csv, const std::string& out_report,
                          const std::vector<AbsComparisonRun>* comparison = nullptr,
                          const AbsStopSeries* series = nullptr);

}  // namespace hotlap::sim
