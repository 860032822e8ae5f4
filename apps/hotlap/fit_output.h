#pragma once
/// @file
/// What `hotlap fit tyre|contact-length|brake` print and draw in their report (docs/fitting.md,
/// docs/reports.md): the same per-corner outcome (ident/car_log_fit.h) for all three, so the
/// three commands share one output module; the JSON summary is fit_json.h.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/ident/car_log_fit.h"

namespace hotlap::app {

/// A whole fit command's outcome: the library's result and what the command was given.
struct FitRun {
  std::string command;  ///< "fit tyre", "fit contact-length" or "fit brake"
  std::string telemetry;
  std::string car_name, car_path;
  std::string out;
  std::vector<double> time;  ///< s, the log's
  std::vector<std::pair<std::string, std::string>> log_metadata;
  nlohmann::json options;  ///< the options that shape the result
  ident::CarFitResult result;
  double elapsed_s = 0.0;
};

/// Prints the paper-style table, the uncertainties and the warnings (warnings to stderr).
void PrintFitRun(const FitRun& run);

/// Writes DIR/index.html (tables, correlations, warnings, measured against modelled) and
/// DIR/channels.csv (measured, modelled and residual per channel). Creates DIR (its parent must
/// exist). Returns the two paths.
std::vector<std::filesystem::path> WriteFitReport(const FitRun& run,
                                                  const std::filesystem::path& dir);

}  // namespace hotlap::app
