#pragma once
/// @file
/// What `hotlap synth` reports of a synthetic log: each corner's peaks and wear of the truth, and
/// the JSON summary of `hotlap synth --json` (docs/json-output.md).

#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/sim/synth.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// One corner of the truth (sensor-noise-free, lag-free) over the whole log.
struct SynthCornerSummary {
  double peak_tread_temp_K = 0.0;
  double peak_disc_temp_K = 0.0;
  double wear_mm = 0.0;  ///< at the end of the log
};

/// Each corner's summary, by CornerIndex.
std::array<SynthCornerSummary, 4> SummarizeSynthCorners(const SynthLog& log);

/// Where a synthetic log came from, as the summary names it.
struct SynthRunInfo {
  std::string track;               ///< the track's name
  std::string params;              ///< the parameter file the truth used ("" for the car's own)
  std::string out;                 ///< the log written
  std::string process_noise_file;  ///< the observer file of the process noise ("" for none)
};

/// The summary: command, car (name and overrides), params, track, out, laps, samples,
/// duration_s, lap_time_s, rate_hz, noise_C, lag_s, seed, per corner peak_tread_temp_C,
/// peak_disc_temp_C and wear_mm; with process noise, its file and variances per second.
nlohmann::json SynthJson(const SynthLog& log, const SynthOptions& options, const vehicle::Car& car,
                         const SynthRunInfo& info);

}  // namespace hotlap::sim
