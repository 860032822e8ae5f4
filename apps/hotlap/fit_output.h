#pragma once
/// @file
/// What `hotlap fit tyre|contact-length|brake` print, write as JSON and draw in their report
/// (docs/fitting.md, docs/json-output.md, docs/reports.md): the same per-corner outcome for all
/// three, so the three commands share one output module.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/common/corner.h"
#include "hotlap/ident/channel_fit.h"

namespace hotlap::app {

/// One fit of a corner as reported: "thermal", "wear", "brake" or "contact length".
struct ReportedFit {
  std::string title;
  ident::FitResult fit;
  /// Parameters held at the car's value in this fit (key -> value), reported as held.
  std::map<std::string, double> held;
};

/// A measured channel and the fitted model's version of it, in display units, for the plots
/// and the channels CSV.
struct ChannelPair {
  std::string quantity;     ///< e.g. "tread_temp"
  std::string title;        ///< e.g. "Tread temperature"
  std::string unit;         ///< e.g. "\u00b0C"
  std::string column_unit;  ///< unit suffix of the CSV column, e.g. "C"
  std::vector<double> measured, model;
};

struct CornerOutcome {
  Corner corner = Corner::kFrontLeft;
  bool fitted = false;
  std::vector<ReportedFit> fits;
  std::vector<std::string> warnings;  ///< about the data and what was not fitted
  std::vector<ChannelPair> channels;
  /// RMS errors for the summary and JSON, by key (e.g. "rms_tread_C"), display units.
  std::vector<std::pair<std::string, double>> rms;
  /// Truth per parameter key (display units), when --truth was given.
  std::map<std::string, double> truth;
};

/// A whole fit command's outcome.
struct FitRun {
  std::string command;  ///< "fit tyre", "fit contact-length" or "fit brake"
  std::string telemetry;
  std::string car_name, car_path;
  std::string out;
  std::vector<double> time;  ///< s, the log's
  std::vector<std::pair<std::string, std::string>> log_metadata;
  nlohmann::json options;  ///< the options that shape the result
  std::vector<CornerOutcome> corners;
  double elapsed_s = 0.0;
  /// The parameters whose joint intervals hold together (FitOptions::joint_family_size).
  int joint_family_size = 1;
};

/// The JSON summary (docs/json-output.md).
nlohmann::json FitRunJson(const FitRun& run);

/// Prints the paper-style table, the uncertainties and the warnings (warnings to stderr).
void PrintFitRun(const FitRun& run);

/// Writes DIR/index.html (tables, correlations, warnings, measured against modelled) and
/// DIR/channels.csv (measured, modelled and residual per channel). Creates DIR (its parent must
/// exist). Returns the two paths.
std::vector<std::filesystem::path> WriteFitReport(const FitRun& run,
                                                  const std::filesystem::path& dir);

}  // namespace hotlap::app
