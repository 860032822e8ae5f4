#pragma once
/// @file
/// The noise model of the live observer (docs/observer.md): process noise, sensor noise, starting
/// uncertainty, the innovation gate and the consistency monitor's thresholds, read strictly from
/// YAML (`model: observer_noise`, the shipped default is DataDir()/observer/default.yaml), and
/// optionally the sensor noise taken from a fit's residuals (`hotlap fit --json`).

#include <array>
#include <filesystem>
#include <optional>
#include <string>

namespace hotlap::observe {

/// Continuous white-noise intensities of the state derivatives: over an interval dt the filter
/// adds q dt to the state's variance. Temperatures K^2/s, wear mm^2/s.
struct ProcessNoise {
  double tread_temp = 0.0;
  double carcass_temp = 0.0;
  double wear = 0.0;
  double disc_temp = 0.0;
  double calliper_temp = 0.0;
};

/// Standard deviations of the measured channels, K; one set per corner (CornerIndex).
struct SensorNoise {
  double tread_temp = 0.0;
  double disc_temp = 0.0;
  double calliper_temp = 0.0;
};

/// Standard deviations of the starting state (K, mm).
struct InitialSd {
  double tread_temp = 0.0;
  double carcass_temp = 0.0;
  double wear = 0.0;
  double disc_temp = 0.0;
  double calliper_temp = 0.0;
};

/// The optional slow parameter state: a factor s on p5 (000:20) per tyre, starting at 1 with
/// standard deviation initial_sd, and a random walk ds = sigma dW (variance sigma^2 dt per
/// interval dt).
struct P5Scale {
  bool estimate = false;
  double initial_sd = 0.1;
  double random_walk_per_sqrt_s = 0.0;  ///< sigma, 1/sqrt(s)
};

/// First-order lags of the temperature sensors, time constants in s (0: the reading is the state
/// itself). See sensor_lag.h.
struct SensorLag {
  double tread_temp = 0.0;
  double disc_temp = 0.0;
  double calliper_temp = 0.0;
};

/// What observing the car's own models needs beyond the paper's (`hotlap observe --models car`:
/// the gas-and-rim tyre with its rim and the surface-and-bulk disc, wheel_filter.h): the rim's and
/// the disc bulk's process noise and starting uncertainty, and the TPMS sensors' noise and lag.
struct CarModelsNoise {
  double rim_temp = 0.0;           ///< process noise, K^2/s
  double disc_bulk_temp = 0.0;     ///< process noise, K^2/s
  double rim_temp_sd = 0.0;        ///< starting sd, K
  double disc_bulk_temp_sd = 0.0;  ///< starting sd, K
  double pressure_sd = 0.0;        ///< TPMS pressure sd, Pa
  double gas_temp_sd = 0.0;        ///< TPMS gas temperature sd, K
  double tpms_lag_s = 0.0;         ///< the TPMS sensors' first-order time constant, s (> 0)
};

struct ObserverConfig {
  std::string name;
  std::filesystem::path path;  ///< the file it was read from (empty if built in code)
  ProcessNoise process;
  std::array<SensorNoise, 4> sensors;  ///< per corner (CornerIndex)
  InitialSd initial_sd;
  SensorLag sensor_lag;  ///< optional `sensor_lag` section; zero without it
  P5Scale p5_scale;
  /// The optional `car_models` section (needed to observe the car's own models).
  std::optional<CarModelsNoise> car_models;
  double gate_sigma = 5.0;        ///< readings with |innovation| > gate_sigma sqrt(S) are rejected
  double window_s = 2.0;          ///< time constant of the monitor's running mean NIS, s
  double disagree_nis = 9.0;      ///< running mean NIS above which model and car disagree
  double disagree_after_s = 5.0;  ///< a disagreement longer than this is warned about, s
  double max_step_s = 0.02;       ///< longest RK4 sub-step of the prediction, s
  /// Where the sensor noise came from: "PATH" or "PATH (sensor noise from FIT.json)".
  std::string source;
};

/// Reads an observer noise file strictly (common/yaml_reader.h): every key required, each in its
/// range; InputError naming the file, the key and the value otherwise.
ObserverConfig LoadObserverConfig(const std::filesystem::path& path);

/// The shipped default, DataDir()/observer/default.yaml.
std::filesystem::path DefaultObserverConfigPath();

/// Replaces the sensor noise of every corner the fit summary (`hotlap fit ... --json`, its
/// `corners.<c>.rms_tread_C`, `rms_disc_C`, `rms_calliper_C`) has a residual RMS for: the RMS of
/// model minus measured holds the sensor noise and the fitted model's error, so it is a
/// conservative sensor standard deviation. InputError if the file cannot be read or is not such
/// a summary; returns how many values were taken.
int ApplyFitResidualNoise(const std::filesystem::path& fit_json, ObserverConfig& config);

}  // namespace hotlap::observe
