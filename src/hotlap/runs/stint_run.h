#pragma once
/// @file
/// The stint run's options as `hotlap stint` and Python's `hotlap.stint` give them: the stint's
/// laps, wear scale, fuel and disc limit on top of the optimal lap's run options, checked and
/// made into the library's (ocp/stint.h); and the fingerprint of the car's and track's files
/// that the command's checkpoints carry.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/ocp/optimal_run.h"
#include "hotlap/ocp/stint.h"
#include "hotlap/runs/option_name.h"

namespace hotlap::runs {

/// A stint run's options, in the units the command line and Python take (degC, kg, g/kWh).
struct StintRunOptions {
  int laps = 3;
  double wear_scale = 1.0;
  double fuel_kg = 40.0;
  std::optional<double> bsfc_g_per_kWh;  ///< the engine's fuel use; the library's by default
  std::optional<double> disc_limit_C;    ///< front discs at most this on every lap
  /// Each lap's solve (mesh, thermal start, temperatures, threads, iterations).
  ocp::OptimalRunOptions run = [] {
    ocp::OptimalRunOptions o;
    o.step_m = ocp::StintOptions::kStintStepM;
    return o;
  }();
  std::filesystem::path checkpoint_dir;  ///< empty: no checkpoints
  int checkpoint_every = 10;             ///< Ipopt iterations between checkpoints
  std::string checkpoint_key;            ///< what else the checkpoints' fingerprint holds
};

/// InputError unless 0 <= threads <= 256 (0: one per core), named in `style`.
void CheckThreads(int threads, NameStyle style);

/// The library's stint options from the run's (InputError for a disc limit outside (0, 1500)
/// degC, named in `style`).
ocp::StintOptions MakeStintOptions(const StintRunOptions& options, NameStyle style);

/// The bytes of every file of the car's folder (tyres, brakes, .tir) and of the track file, and
/// the --set overrides, as the checkpoints' key: a checkpoint of another car or track is not
/// resumed.
std::string StintCheckpointKey(const std::filesystem::path& car_file,
                               const std::filesystem::path& track_file,
                               const std::vector<std::string>& overrides);

}  // namespace hotlap::runs
