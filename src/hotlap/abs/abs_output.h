#pragma once
/// @file
/// What `hotlap abs` writes and prints of one braking event (docs/abs.md): the channels as CSV
/// and the summary's figures in words. The JSON summary is abs_json.h, the HTML report
/// abs_report.h.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_run.h"
#include "hotlap/abs/abs_scenarios.h"

namespace hotlap::sim {

/// The channels CSV (docs/abs.md lists the columns), with the configuration, surface and ABS as
/// metadata; written atomically.
void WriteAbsCsv(const std::filesystem::path& path, const AbsConfig& config, const AbsEvent& event,
                 const AbsRunResult& run);

/// The summary as (figure, value) rows: the stop, control cycles, slip, lock, temperatures and
/// energies; `with_abs` false says "no ABS" for the cycles.
std::vector<std::pair<std::string, std::string>> AbsSummaryRows(const AbsMetrics& metrics,
                                                                bool with_abs);

/// The scenarios' lines as `hotlap abs --scenarios` prints them: each surface's stopping
/// distances with ABS and locked and their ratio (`comparison` in RunAbsComparison's pairs),
/// then the stop series' peak disc temperature.
std::vector<std::string> AbsScenarioLines(const std::vector<AbsComparisonRun>& comparison,
                                          const AbsStopSeries& series);

}  // namespace hotlap::sim
