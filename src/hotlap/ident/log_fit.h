#pragma once
/// @file
/// What the tyre and brake fits over a log share: their options, how a logged temperature becomes
/// a fitted channel, the initial temperatures as nuisance parameters, seeded random starts, and
/// the sensor-lag diagnostic (docs/fitting.md).

#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fit_log.h"

namespace hotlap::ident {

/// Where a fit's integration starts.
enum class InitialStateMode {
  /// The initial temperatures are fitted with the parameters (nuisance parameters, started at a
  /// robust first value): noise on the first sample does not bias the answer.
  kFitted,
  /// From the first measured values, as the NASCAR paper (spec section 6).
  kMeasured,
};

/// Reads "fitted" or "measured"; InputError otherwise.
InitialStateMode ParseInitialStateMode(const std::string& text);

struct LogFitOptions {
  FitOptions solver;
  double max_step_s = 0.02;   ///< longest RK4 sub-step, s (as the replay)
  double sensor_lag_s = 0.0;  ///< first-order lag of the temperature sensors, modelled, s
  /// First-order lag of the TPMS sensors (pressure and gas temperature), modelled, s; assumed
  /// as hotlap synth's (a valve-stem sensor in the gas).
  double tpms_lag_s = 2.0;
  InitialStateMode initial_state = InitialStateMode::kFitted;
  int random_starts = 6;  ///< seeded random starts scored besides the guesses
  uint64_t seed = 1;
};

/// A logged temperature (K) as a fitted channel: trapezoid weights, a prior noise of 1 K and a
/// floor of 0.01 K on the estimated one. `display` is the name shown ("tread_temp").
MeasuredChannel TemperatureChannel(const LoggedChannel& logged, const std::vector<double>& weights);

/// The initial temperature of a state as a nuisance parameter, in K, shown in degC.
FitParameter InitialTemperatureParameter(const std::string& key, const std::string& label);

/// The value a state starts from: in kFitted mode the robust first value, in kMeasured mode the
/// first value (spec section 6); `fallback` (K) when the channel has none.
double StartingTemperature(const LoggedChannel& logged, std::span<const double> time,
                           InitialStateMode mode, double fallback);

/// A number drawn log-uniformly from [lo, hi] (both > 0).
double LogUniform(std::mt19937_64& rng, double lo, double hi);

/// Adds a warning for every channel whose residuals look like an unmodelled sensor lag (apparent
/// lag above 0.02 s and three of its standard errors).
/// `option` is the option the advice names (the TPMS channels': --tpms-lag-s).
void AddLagWarnings(const FitResult& fit, double modelled_lag_s, std::vector<std::string>* out,
                    std::string_view option = "--sensor-lag-s");

/// Adds a warning for every channel whose residuals follow one another (lag-one
/// autocorrelation above 0.9; white sensor noise gives about 0): the model misses something
/// there, and the intervals, which assume it does not, are too narrow.
void AddMisfitWarnings(const FitResult& fit, std::vector<std::string>* out);

}  // namespace hotlap::ident
