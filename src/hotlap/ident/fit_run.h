#pragma once
/// @file
/// A whole fit of a car to a log as `hotlap fit tyre|contact-length|brake` reports it: the
/// library's per-corner outcome (car_log_fit.h) with what the fit was given, and the short texts
/// of an estimate that the terminal table and the HTML report share. The JSON summary is
/// fit_run_json.h, the report fit_run_report.h.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/ident/car_log_fit.h"

namespace hotlap::ident {

/// A fit's outcome and what it was given.
struct FitRun {
  std::string command;  ///< "fit tyre", "fit contact-length" or "fit brake"
  std::string telemetry;
  std::string car_name, car_path;
  std::string out;
  std::vector<double> time;  ///< s, the log's
  std::vector<std::pair<std::string, std::string>> log_metadata;
  nlohmann::json options;  ///< the options that shape the result
  CarFitResult result;
  double elapsed_s = 0.0;
};

/// `v` to four significant digits; "inf", "-inf" or "n/a" where it is not finite.
std::string ShortNumber(double v);

/// The 95% interval of `e` in `p`'s display units, "[low, high]".
std::string IntervalText(const FitParameter& p, const ParameterEstimate& e);

/// The joint 95% interval of a model parameter, "[low, high]"; "" for a nuisance parameter (not
/// in the joint family).
std::string JointIntervalText(const FitParameter& p, const ParameterEstimate& e);

/// "undetermined", "at bound", "yes" (well determined) or "no".
std::string VerdictText(const ParameterEstimate& e);

/// The paper-style table `hotlap fit` prints: the log, then per corner the RMS errors, each
/// parameter with its standard error, intervals and verdict, and the values held; the time taken.
std::string FitRunText(const FitRun& run);

/// Every corner's warnings, each "CORNER: warning", in the corners' order.
std::vector<std::string> FitRunWarnings(const FitRun& run);

}  // namespace hotlap::ident
