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

struct SynthOptions {
  int laps = 1;
  double rate_hz = 50.0;         ///< logging rate
  double temp_noise_K = 0.5;     ///< standard deviation of every temperature sensor
  double sensor_lag_s = 0.2;     ///< time constant of every temperature sensor
  double wear_noise_mm = 1e-4;   ///< standard deviation of the wear channel
  double radius_noise_m = 1e-4;  ///< standard deviation of the rolling radius
  uint64_t seed = 1;
  double ambient_temp = 298.15;               ///< K
  double track_temp = 313.15;                 ///< K
  std::optional<ReplayInitialState> initial;  ///< default: the car's initial_state, no wear
  double max_step_s = 0.02;                   ///< RK4 sub-step of the replay
};

/// A synthetic log: columns in the canonical units of the telemetry format, and the truth.
struct SynthLog {
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  ///< [column][row]
  ReplayInputs inputs;                      ///< what was written as inputs, SI
  ReplayResult truth;                       ///< noise-free, lag-free histories at the samples
  double lap_time_s = 0.0;
};

/// Runs the lap(s) and the sensors. InputError for bad options (laps < 1, rate <= 0, negative
/// noise or lag) and for a car without vehicle sections; RunQssLap's errors otherwise.
SynthLog SynthesizeLog(const vehicle::Car& car, std::span<const RoadPoint> road,
                       const SynthOptions& options);

/// Writes the log as CSV atomically (common/csv.h), with `extra_metadata` after its own lines.
void WriteSynthLog(const std::filesystem::path& path, const SynthLog& log,
                   const std::vector<std::pair<std::string, std::string>>& extra_metadata = {});

}  // namespace hotlap::sim
