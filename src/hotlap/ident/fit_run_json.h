#pragma once
/// @file
/// The JSON summary of a fit of a car to a log (`hotlap fit tyre|contact-length|brake --json`,
/// docs/json-output.md).

#include <nlohmann/json.hpp>

#include "hotlap/ident/fit_run.h"

namespace hotlap::ident {

/// The summary: the command, inputs and options, then per corner the RMS errors, each model
/// parameter (value, standard error, 95% and joint intervals, verdict, truth where known), and
/// per fit its nuisance and held parameters, correlations, channel statistics and warnings.
/// Numbers are rounded to nine significant digits; non-finite ones are null.
nlohmann::json FitRunJson(const FitRun& run);

}  // namespace hotlap::ident
