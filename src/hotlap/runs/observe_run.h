#pragma once
/// @file
/// The observer run as `hotlap observe` makes it: the noise file (and a fit's residual noise),
/// the sensor lags (the option, else the log's `# sensor_lag_s:` line, else the noise file's),
/// the samples from a log or a stream, the estimates written line by line as they come, and the
/// summary of what was seen (observe/observe_json.h). The command parses its options into
/// ObserveRunOptions, calls RunObserve with its hooks (the live page, the warnings on standard
/// error) and prints what it returns.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/observe/car_observer.h"
#include "hotlap/observe/observe_json.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::runs {

/// An observer run's options, in the units the command line takes (degC, s).
struct ObserveRunOptions {
  std::string telemetry;       ///< a log, or "-" for a stream on standard input
  std::string out;             ///< the estimates CSV, or "-" for standard output
  std::string channel_map;     ///< a MoTeC log's channel map
  std::optional<int> lap;      ///< observe only this lap
  std::string config;          ///< the noise file; "": data/observer/default.yaml
  std::string noise_from_fit;  ///< a fit's JSON summary whose residuals give the sensor noise
  bool p5_scale = false;       ///< also estimate a drifting factor on p5
  /// "paper" (the paper's two-mass tyres and lumped discs) or "car" (the car's own gas-and-rim
  /// tyres with their TPMS and surface-and-bulk discs; observe::ObservedModels).
  std::string models = "paper";
  /// Starting temperatures where the log has none, degC.
  std::optional<double> tread_C, carcass_C, disc_C, calliper_C;
  std::optional<double> sensor_lag_s;       ///< every sensor's time constant, s
  double ambient_C = 25.0, track_C = 40.0;  ///< where the log has no such column
};

/// What the caller is told as the run goes.
struct ObserveHooks {
  /// Once the estimates file is open and its header written, before the first row.
  std::function<void(const std::vector<std::string>& columns)> started;
  /// Each estimate row, after it is written.
  std::function<void(const std::vector<double>& row)> row;
  /// Each disagreement warning as it is raised.
  std::function<void(const observe::DisagreementWarning& warning)> warning;
};

/// A finished run: the observer after the last sample and the summary.
struct ObserveRun {
  std::unique_ptr<observe::CarObserver> observer;
  observe::ObserveSummary summary;
  long telemetry_warning_count = 0;  ///< all of them (summary.telemetry_warnings has 20 at most)
};

/// The noise model the options name, with --p5-scale and a fit's residual noise applied.
observe::ObserverConfig LoadObserveConfig(const ObserveRunOptions& options);

/// The sensors' lags into `config`: the option, else the log's `# sensor_lag_s:` line, else the
/// noise file's; returns where they came from. InputError (naming `source`) for a log line that is
/// not a time constant in [0, 60] s.
std::string ResolveSensorLag(const std::optional<double>& option,
                             const std::vector<std::pair<std::string, std::string>>& metadata,
                             const std::string& source, observe::ObserverConfig& config);

/// The TPMS sensors' lag into `config.car_models` (where it has that section): the log's `# tpms:`
/// line (hotlap synth's, ending "lag <s> s"), else the noise file's; returns where it came from
/// ("" without the section). InputError (naming `source`) for a line without a time constant in
/// (0, 60] s.
std::string ResolveTpmsLag(const std::vector<std::pair<std::string, std::string>>& metadata,
                           const std::string& source, observe::ObserverConfig& config);

/// Runs the observer over the whole input. Everything that can fail on input before the first
/// sample fails before the estimates file is opened (no file is left behind).
ObserveRun RunObserve(const vehicle::Car& car, const ObserveRunOptions& options,
                      const ObserveHooks& hooks);

}  // namespace hotlap::runs
