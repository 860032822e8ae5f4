#pragma once
/// @file
/// What `hotlap observe` prints of a finished run: the log, the sensor lags and where they came
/// from, each corner's last estimate with its 1-sigma bands, each sensor's consistency, and the
/// count of disagreement warnings.

#include <string>

#include "hotlap/runs/observe_run.h"

namespace hotlap::runs {

/// The summary lines (each ending in a newline).
std::string ObserveRunText(const ObserveRun& run, const vehicle::Car& car);

}  // namespace hotlap::runs
