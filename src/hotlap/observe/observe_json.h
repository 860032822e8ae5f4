#pragma once
/// @file
/// What `hotlap observe --json` writes (docs/json-output.md): the run (log, car, noise, sensor
/// lags and where they came from), each corner's last estimate with its 1-sigma bands and each
/// sensor's consistency, and the disagreement warnings raised.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/observe/car_observer.h"
#include "hotlap/observe/consistency.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::observe {

/// An observer run besides the observer itself: what was read, how, and what it raised.
struct ObserveSummary {
  std::string telemetry;        ///< the log as given ("-" for standard input)
  std::string out;              ///< the estimates file as given ("-" for standard output)
  std::optional<int> lap;       ///< the lap observed, if one was selected
  std::string sensor_lag_from;  ///< "--sensor-lag-s", "the log's sensor_lag_s" or the file
  std::string tpms_lag_from;    ///< "the log's tpms line" or the file ("" without car_models)
  double duration_s = 0.0;      ///< of log, from the first sample to the last
  double wall_time_s = 0.0;     ///< the run's
  std::vector<DisagreementWarning> warnings;    ///< in the order raised
  std::vector<std::string> telemetry_warnings;  ///< the reader's (at most 20 lines)
};

/// Each sensor monitor's figures of `c` that saw readings, {quantity: {...}}.
nlohmann::json SensorsJson(const CarObserver& observer, Corner c);

/// Whether every monitor with readings is consistent.
bool AllConsistent(const CarObserver& observer);

/// The whole summary as `hotlap observe --json` writes it.
nlohmann::json ObserveJson(const CarObserver& observer, const vehicle::Car& car,
                           const ObserveSummary& summary);

}  // namespace hotlap::observe
