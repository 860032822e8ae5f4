#pragma once
/// @file
/// Synthetic "measured" logs: the QSS lap simulation (qss_lap.h) of a car with chosen (true)
/// parameters over N laps of a road, resampled to a logging rate, its tyre and brake models
/// replayed over exactly those samples, and sensors applied to what a logger would record
/// (docs/fitting.md, "hotlap synth"):
/// - temperatures (tread, carcass, disc, calliper): a first-order lag (synth_sensor.h), then
///   Gaussian noise;
/// - wear: the modelled tread depth lost plus Gaussian noise;
/// - rolling radius: from the load through the contact-length law (000:14) and the chord of the
///   unloaded circle, r_r = sqrt(r0^2 - (c_l / 2)^2) (the inverse of spec section 6's
///   c_l = 2 sqrt(r0^2 - r_r^2)), plus Gaussian noise;
/// - inputs (speeds, forces, slips, ambient and track temperatures) are written exactly: the log
///   studies the thermal parameters, not errors in the inputs.
/// The noise is seeded (the same log for the same seed on every platform).
///
/// Optionally the truth itself is stochastic (SynthOptions::process_noise): the model plus a
/// random walk per state, the process noise `hotlap observe` assumes (docs/observer.md), so the
/// log is exactly the data whose statistics the observer's bands claim. Without it the truth is
/// the deterministic replay and the log is the same as before the option existed.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/replay.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// Continuous white noise added to each true state's derivative (a random walk on top of the
/// model), as the observer's process noise (observe/observer_config.h): intensities q, so over a
/// sample interval dt the state gets sqrt(q dt) N(0, 1) added after the model's step, and its
/// standard deviation grows as sqrt(q) per sqrt(s) where the model does not pull it back.
struct SynthProcessNoise {
  double tread_temp_K2_per_s = 0.0;
  double carcass_temp_K2_per_s = 0.0;
  double wear_mm2_per_s = 0.0;
  double disc_temp_K2_per_s = 0.0;
  double calliper_temp_K2_per_s = 0.0;
};

/// The seed of the process noise's own stream, derived from SynthOptions::seed so that the sensor
/// noise of a log is the same with and without process noise.
constexpr uint64_t ProcessNoiseSeed(uint64_t seed) { return seed ^ 0x9E3779B97F4A7C15ULL; }
/// The seed of the TPMS channels' own noise stream, so that adding them leaves the other
/// channels' noise as it was.
constexpr uint64_t TpmsNoiseSeed(uint64_t seed) { return seed ^ 0xC2B2AE3D27D4EB4FULL; }

/// The tyre-pressure monitoring sensors of a synthetic log: the inflation pressure (gauge) and the
/// gas temperature of each tyre that has a gas node, read through a first-order lag with noise.
struct SynthTpms {
  bool enabled = true;
  double pressure_noise_kPa = 0.35;  ///< assumed: a TPMS's scatter, about 0.05 psi
  double temp_noise_K = 0.5;         ///< assumed
  double lag_s = 2.0;                ///< assumed: a valve-stem sensor in the gas
};

struct SynthOptions {
  int laps = 1;
  double rate_hz = 50.0;         ///< logging rate
  double temp_noise_K = 0.5;     ///< standard deviation of every temperature sensor
  double sensor_lag_s = 0.2;     ///< time constant of every temperature sensor
  double wear_noise_mm = 1e-4;   ///< standard deviation of the wear channel
  double radius_noise_m = 1e-4;  ///< standard deviation of the rolling radius
  /// The truth's models: the paper's (the default: what the fits identify and the observer
  /// tracks), or the car's own (its gas-and-rim tyres and bulk discs; no process noise).
  bool paper_models = true;
  /// pressure_<c>_kPa and gas_temp_<c>_C of the tyres whose truth has a gas node (the car's own
  /// models; noise from TpmsNoiseSeed).
  SynthTpms tpms;
  uint64_t seed = 1;
  double ambient_temp = 298.15;               ///< K
  double track_temp = 313.15;                 ///< K
  std::optional<ReplayInitialState> initial;  ///< default: the car's initial_state, no wear
  double max_step_s = 0.02;                   ///< RK4 sub-step of the replay
  /// A stochastic truth: the model with this random-walk process noise (seeded by
  /// ProcessNoiseSeed(seed)). Empty: the deterministic model.
  std::optional<SynthProcessNoise> process_noise;
};

/// A synthetic log: columns in the canonical units of the telemetry format, and the truth.
struct SynthLog {
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  ///< [column][row]
  ReplayInputs inputs;                      ///< what was written as inputs, SI
  /// Sensor-noise-free, lag-free histories at the samples (with process noise if asked for; then
  /// without heat flows).
  ReplayResult truth;
  double lap_time_s = 0.0;
};

/// Runs the lap(s) and the sensors. The truth is the paper's models (vehicle::PaperModelsOf), which
/// the fits identify and the observer tracks: a gas-and-rim tyre or a bulk disc runs as its paper
/// part. InputError for bad options (laps < 1, rate <= 0, negative
/// noise, lag or process noise) and for a car without vehicle sections; RunQssLap's errors
/// otherwise.
SynthLog SynthesizeLog(const vehicle::Car& car, std::span<const RoadPoint> road,
                       const SynthOptions& options);

/// The model over `inputs` with random-walk process noise: every sample interval integrated as
/// replay does (sampled_inputs.h, RK4 sub-steps no longer than max_step_s, split at kinks), then
/// sqrt(q dt) N(0, 1) added to each state, drawn from GaussianNoise(seed) corner by corner (fl,
/// fr, rl, rr), interval by interval, in the order tread, carcass, wear, then disc, calliper.
/// With all intensities zero it is RunReplay's result to rounding on the paper's models, which it
/// runs whatever the car's (vehicle::PaperModelsOf). NumericalError if a
/// temperature leaves [0 K, 3000 K].
ReplayResult RunStochasticReplay(const vehicle::Car& car, const ReplayInputs& inputs,
                                 const ReplayInitialState& initial, double max_step_s,
                                 const SynthProcessNoise& noise, uint64_t seed);

/// Writes the log as CSV atomically (common/csv.h), with `extra_metadata` after its own lines.
void WriteSynthLog(const std::filesystem::path& path, const SynthLog& log,
                   const std::vector<std::pair<std::string, std::string>>& extra_metadata = {});

}  // namespace hotlap::sim
