#pragma once
/// @file
/// The outputs of `hotlap fe abs --ensemble N` (docs/fe-tyre.md, "ABS stop"): the HTML report
/// (each figure's mean, standard error and spread beside the lumped model's; the members'
/// histories as a band: their mean and their smallest and largest value at each time), one CSV
/// row of figures per member, and the summary lines the command prints.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/fe_abs_ensemble.h"

namespace hotlap::sim {

/// A lumped `hotlap abs` run of the same event, a column of the report's table.
struct LumpedAbsColumn {
  std::string label;  ///< e.g. "lumped, same ABS file", "lumped, own tuning"
  AbsMetrics metrics;
};

/// Writes the report to `path` (atomically), with the `lumped` runs of the same event beside the
/// ensemble (a column each) and `metadata` lines under the title. Throws InputError if the file
/// cannot be written, std::invalid_argument if the ensemble has no history.
void WriteFeAbsEnsembleReport(const std::filesystem::path& path, const FeAbsEnsembleResult& e,
                              const std::vector<LumpedAbsColumn>& lumped,
                              const std::vector<std::pair<std::string, std::string>>& metadata);

/// One row per member: its index, cycle count and figures (ListFeAbsFigures; empty where none).
void WriteFeAbsEnsembleCsv(const std::filesystem::path& path, const FeAbsEnsembleResult& e);

/// The ensemble's summary: one line per figure, "key: mean +- standard error (min .. max, n)".
std::vector<std::string> FeAbsEnsembleText(const FeAbsEnsembleResult& e);

}  // namespace hotlap::sim
