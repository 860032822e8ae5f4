#pragma once
/// @file
/// The JSON summary of `hotlap fit tyre|contact-length|brake --json` (docs/json-output.md).

#include <nlohmann/json.hpp>

#include "fit_output.h"

namespace hotlap::app {

/// The JSON summary of a fit command's run.
nlohmann::json FitRunJson(const FitRun& run);

}  // namespace hotlap::app
