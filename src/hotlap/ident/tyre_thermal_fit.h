#pragma once
/// @file
/// Fitting one corner's tyre thermal parameters p1..p5 to its measured tread and carcass
/// temperatures, then the wear law's wp1, wp2 to its measured wear (spec section 6, 000 §2.3),
/// with standard errors, intervals and correlations (channel_fit.h; docs/fitting.md).
///
/// Thermal stage: the states are integrated with RK4 over the logged inputs exactly as the replay
/// does, on Jets, so the residual Jacobian is exact; the residuals are the sampled temperature
/// errors with trapezoid weights (the integral of squared error of the paper). The initial
/// temperatures are fitted as nuisance parameters (or taken from the first samples, as the
/// paper). An optional first-order sensor lag is applied to the modelled temperatures before
/// they are compared. Starts: the car's values, an equation-error guess (the two heat balances
/// integrated over time are linear in p1..p5; bounded linear least squares on the smoothed
/// measurements) and seeded random draws; the best are refined.
///
/// Wear stage, at the fitted thermal parameters: against a logged wear channel (wp1, wp2 and the
/// wear at the first sample are fitted) or against a total (the per-lap wear of the paper times
/// the laps in the log: one number, so only wp1 is fitted and wp2 is held, with a warning). The
/// wear parameters' covariance adds the thermal parameters' uncertainty carried through the wear
/// prediction (delta method: G Cov(p) G', G = -(Jw'Jw)^-1 Jw' Jp).
///
/// Gas stage, where the tyre runs the gas-and-rim model and the log has the corner's TPMS
/// pressure and/or gas temperature: the carcass-gas, gas-rim and rim-air conductances (and the
/// rim's starting temperature, a nuisance parameter) to those channels through the TPMS lag. The
/// model is the car's own gas-and-rim tyre integrated with its brake as the replay does (the rim
/// takes the brake's heat), on the tyre file's p1..p5 (the paper-fitted values belong to the
/// paper's two masses; docs/fitting.md, "The gas path from TPMS"); the other gas-path parameters
/// are held at the file's values.

#include <optional>
#include <string>
#include <vector>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/ident/log_fit.h"
#include "hotlap/sim/sampled_inputs.h"
#include "hotlap/tyre/tyre_params_io.h"
#include "hotlap/tyre/tyre_thermal_fields.h"

namespace hotlap::ident {

/// One corner's data for the tyre fit.
struct TyreCornerData {
  sim::CornerSamples samples;
  LoggedChannel tread, carcass, wear;  ///< K, K, mm
  std::vector<double> weights;         ///< TrapezoidWeights(samples.time)
  /// Tread depth lost over the log, mm, and its standard deviation, when measured as a total.
  std::optional<double> wear_total_mm;
  double wear_total_sd_mm = 0.0;
  double fallback_tread_temp = 0.0;    ///< K, start when the tread channel is unusable
  double fallback_carcass_temp = 0.0;  ///< K, start when the carcass channel is unusable
  /// TPMS channels, for the gas stage: hot gauge pressure (Pa) and gas temperature (K).
  LoggedChannel pressure, gas_temp;
  /// The corner's brake, whose heat the rim takes in the gas stage (null: no brake heat).
  const brake::BrakeThermalParams<double>* brake = nullptr;
  sim::CornerSamples brake_samples;       ///< the brake's inputs (sim::BrakeSamplesOf)
  brake::BrakeState<double> brake_start;  ///< K, the brake's state at the first sample
  double fallback_rim_temp = 0.0;         ///< K, the rim's starting value before it is fitted
};

struct TyreFitResult {
  std::optional<FitResult> thermal;  ///< p1..p5 (then the initial temperatures if fitted)
  std::optional<FitResult> wear;     ///< wp1 (then wp2 and the initial wear, from a channel)
  /// The gas path's conductances (GasFitFields order), then the rim's starting temperature.
  std::optional<FitResult> gas;
  tyre::TyreThermalParams<double> params;  ///< the tyre's parameters with the fitted values
  std::vector<std::string> warnings;       ///< about the data and what was not fitted
  /// The fitted model at the samples (after the sensor lag for temperatures): K, K, mm.
  std::vector<double> tread_model, carcass_model, wear_model;
  /// The gas stage's model at the samples (after the TPMS lag): Pa gauge, K; empty without it.
  std::vector<double> pressure_model, gas_temp_model;
};

/// Fits one corner. Throws InputError if the data have no sample.
TyreFitResult FitTyreCorner(const tyre::TyreFile& tyre, const TyreCornerData& data,
                            const LogFitOptions& options);

/// The field table's entries of the seven parameters the fit frees (tyre_thermal_fields.h), in
/// TyreFitResult order: heat_generation's p1..p5, then wear's wp1, wp2.
const std::vector<const tyre::TyreThermalField*>& TyreFitFields();

/// The field table's entries of the gas path's conductances the gas stage frees: carcass-gas,
/// gas-rim, rim-air.
const std::vector<const tyre::TyreThermalField*>& GasFitFields();

/// The file keys of the seven fitted tyre parameters, in TyreFitResult order
/// ("p1" .. "p5_W_per_m2K", "wp1_mm_per_s", "wp2").
const std::vector<std::string>& TyreParameterKeys();

}  // namespace hotlap::ident
