#pragma once
/// @file
/// The HTML report of `hotlap abs` (docs/abs.md, docs/reports.md): the run's histories and, with
/// --scenarios, the comparisons.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_run.h"
#include "hotlap/abs/abs_scenarios.h"

namespace hotlap::sim {

/// What the report shows.
struct AbsReportInputs {
  const AbsConfig* config = nullptr;
  const AbsEvent* event = nullptr;
  const AbsRunResult* run = nullptr;
  const AbsMetrics* metrics = nullptr;
  std::vector<std::pair<std::string, std::string>> summary;   ///< figure, value rows
  const std::vector<AbsComparisonRun>* comparison = nullptr;  ///< null without --scenarios
  const AbsStopSeries* series = nullptr;                      ///< null without --scenarios
  std::string csv;  ///< the channels file written beside it
};

/// Writes the report to `path` atomically.
void WriteAbsReport(const AbsReportInputs& in, const std::filesystem::path& path);

}  // namespace hotlap::sim
