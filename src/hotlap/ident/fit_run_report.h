#pragma once
/// @file
/// The report of a fit of a car to a log (`hotlap fit ... --report DIR`, docs/fitting.md,
/// docs/reports.md): an HTML page of tables, correlations, warnings and the measured against the
/// modelled channels, and those channels as CSV.

#include <filesystem>
#include <vector>

#include "hotlap/ident/fit_run.h"

namespace hotlap::ident {

/// Writes DIR/index.html (tables, correlations, warnings, measured against modelled) and
/// DIR/channels.csv (measured, modelled and residual per channel), each atomically. Creates DIR
/// (its parent must exist; InputError otherwise). Returns the two paths.
std::vector<std::filesystem::path> WriteFitReport(const FitRun& run,
                                                  const std::filesystem::path& dir);

}  // namespace hotlap::ident
