#pragma once
/// @file
/// The observer run over a synthetic log (sim/synth.h) whose truth is known, scored against that
/// truth: the acceptance measurement of docs/validation/observer.md ("Accuracy and consistency"),
/// shared by the tests and bench/observe_bench.cc.
///
/// The readings are the log's tread temperatures (its noise, no lag expected) and its disc
/// temperatures with seeded dropouts (a two-state Markov chain: `disc_dropout_fraction` of the
/// samples on average, in runs of mean length `dropout_mean_s`); carcass, wear and (by default)
/// calliper are never read. The observer starts `carcass_offset_K` away from the true carcass
/// temperature. The truth is the log's own (SynthLog::truth).
///
/// Make the log with process noise (sim::SynthOptions::process_noise, the observer's own
/// intensities) to measure consistency: then the truth is the stochastic process the filter
/// assumes, and its 1-sigma bands must hold the truth 68% of the time. Without process noise every
/// true state at time t is a function of the starting state alone, so the estimation error of one
/// corner is, after the first lap, one random draw (the error in the starting carcass
/// temperature) scaled over time: the fraction of time inside the band is then close to 0 or 1
/// per corner, not 68%, however right the filter is (and the filter, assuming a little model
/// error, is cautious there).

#include <array>
#include <cstdint>

#include "hotlap/observe/car_observer.h"
#include "hotlap/sim/synth.h"

namespace hotlap::observe {

struct SynthCheckOptions {
  double disc_dropout_fraction = 0.2;
  double dropout_mean_s = 0.5;
  bool read_calliper = false;
  double carcass_offset_K = 3.0;  ///< observer's starting carcass minus the truth's
  uint64_t seed = 7;              ///< of the dropouts
  /// Scoring starts here (s from the log's start): the first lap by default (set by the caller
  /// to the log's lap time).
  double score_from_s = 0.0;
};

/// Fraction of scored samples whose truth lies inside mean +- 1 sd, per state.
struct Coverage {
  double tread = 0.0, carcass = 0.0, wear = 0.0, disc = 0.0, calliper = 0.0;
};

struct SynthCheck {
  long samples = 0, scored = 0;
  std::array<double, 4> carcass_rms_K{};  ///< per corner, scored samples
  double carcass_rms_all_K = 0.0;         ///< all corners
  std::array<double, 4> wear_truth_mm{}, wear_estimate_mm{}, wear_sd_mm{};  ///< at the end
  double max_wear_rel_error = 0.0;  ///< max over corners of |estimate - truth| / truth
  Coverage coverage;                ///< all corners, scored samples
  /// Mean normalised estimation error squared (error^2 / variance) per state: 1 when the bands
  /// are as wide as the errors, below 1 when they are wider.
  Coverage nees;
  double disc_missing_fraction = 0.0;  ///< of the disc readings withheld
  /// Mean NIS per corner and sensor (NaN where unread) and whether all lie in their 95% bounds.
  std::array<std::array<double, kAllSensors.size()>, 4> mean_nis{};
  bool nis_consistent = true;
  int sensors = 0, sensors_consistent = 0;  ///< sensors read, and those within their bounds
  /// The mean NIS of every used reading of every sensor, and its 95% bounds.
  double pooled_mean_nis = 0.0;
  long nis_used = 0;  ///< the readings it is the mean of
  std::pair<double, double> pooled_nis_bounds95{0.0, 0.0};
  long rejected = 0;  ///< readings rejected by the gate, all sensors
  long warnings = 0;  ///< disagreement warnings
};

/// Runs the observer over `log` (from SynthesizeLog with `car`) and scores it.
SynthCheck CheckObserverOnSynth(const vehicle::Car& car, const sim::SynthLog& log,
                                const ObserverConfig& config, const SynthCheckOptions& options);

}  // namespace hotlap::observe
