#pragma once
/// @file
/// The synthetic-log run as `hotlap synth` makes it: the true parameters on the car, the lap
/// simulation's options from the command's units (degC, mm), the observer noise file whose
/// process noise makes the truth stochastic, the log, and the text the command prints.

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/sim/synth.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::runs {

/// A synth run's options, in the units the command line takes.
struct SynthRunOptions {
  std::string params;         ///< a parameter file of the true values; "": the car's
  std::string process_noise;  ///< an observer noise file, "default", or "" (a deterministic truth)
  int laps = 1;
  double rate_hz = 50.0, noise_C = 0.5, lag_s = 0.2, wear_noise_mm = 1e-4, radius_noise_mm = 0.1;
  sim::SynthTpms tpms;          ///< the TPMS channels (kPa, degC = K differences, s)
  std::string truth = "paper";  ///< the truth's models: "paper" or "car" (SynthOptions)
  double ambient_C = 25.0, track_C = 40.0, step_m = 1.0;
  uint64_t seed = 1;
};

/// A finished run: the log, the options it was made with, what the parameters and the process
/// noise were taken from.
struct SynthRun {
  sim::SynthLog log;
  sim::SynthOptions options;
  std::string params_name = "the car's";  ///< the parameter file's name
  std::string process_noise_file;         ///< the noise file used, or ""
};

/// Applies the true parameters to `car` and synthesizes the log round `track`'s centre line.
SynthRun RunSynth(vehicle::Car& car, const track::Track& track, const SynthRunOptions& options);

/// Writes the run's log to `out` (WriteSynthLog, atomically) with the track and the parameter
/// file as metadata.
void WriteSynthRunLog(const std::filesystem::path& out, const SynthRun& run,
                      const track::Track& track, const SynthRunOptions& options);

/// The run's summary (sim::SynthJson) for the log written to `out` ("" if none).
nlohmann::json SynthRunJson(const SynthRun& run, const vehicle::Car& car, const track::Track& track,
                            const SynthRunOptions& options, const std::string& out);

/// What `hotlap synth` prints of a run (before the files it wrote).
std::string SynthRunText(const SynthRun& run, const vehicle::Car& car, const track::Track& track);

}  // namespace hotlap::runs
