#pragma once
/// @file
/// Fitting one corner's brake parameters (gamma, xi and the twelve Cholesky entries of the disc
/// and calliper convection polynomials) to its measured disc and calliper temperatures (spec
/// section 6, 000 §3.1), with standard errors, intervals and correlations (channel_fit.h;
/// docs/fitting.md).
///
/// As the tyre fit: the states are integrated over the logged inputs as the replay does, on Jets
/// (14 lanes, then 2 for the initial temperatures), the residuals are trapezoid-weighted
/// temperature errors, an optional sensor lag is modelled, and the initial temperatures are
/// fitted or taken from the first samples. Starts: the car's values, an equation-error guess (the
/// two heat balances integrated over time are linear in gamma, xi and the entries of P = L L';
/// bounded linear least squares, then P projected onto the positive semi-definite matrices and
/// factored) and seeded random draws.
///
/// Reporting: L is what the file stores and what is solved for (P stays positive semi-definite
/// with bounds only), but the uncertainty is reported for the entries of P: the model is linear
/// in them, so a valley of equally good fits (one lap rarely determines all six entries) is
/// straight in P and its linearised intervals hold, where in L it curves and they do not.

#include <array>
#include <string>
#include <vector>

#include "hotlap/brake/brake_params_io.h"
#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/ident/channel_fit.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/ident/log_fit.h"
#include "hotlap/sim/sampled_inputs.h"

namespace hotlap::ident {

/// One corner's data for the brake fit.
struct BrakeCornerData {
  sim::CornerSamples samples;
  LoggedChannel disc, calliper;         ///< K
  std::vector<double> weights;          ///< TrapezoidWeights(samples.time)
  double fallback_disc_temp = 0.0;      ///< K, start when the disc channel is unusable
  double fallback_calliper_temp = 0.0;  ///< K, start when the calliper channel is unusable
};

struct BrakeFitResult {
  /// The fit as solved: gamma, xi, the Cholesky entries of L (then the initial temperatures).
  std::optional<FitResult> cholesky_fit;
  /// The same reported for gamma, xi and the entries of P = L L' (the paper's twelve
  /// parameters; keys "disc_convection_P11_W_per_K" ...): what the intervals are given for.
  std::optional<FitResult> fit;
  brake::BrakeThermalParams<double> params;  ///< the brake's parameters with the fitted values
  std::vector<std::string> warnings;
  std::vector<double> disc_model, calliper_model;  ///< K at the samples (after the sensor lag)
};

/// Fits one corner. Throws InputError if the data have no sample.
BrakeFitResult FitBrakeCorner(const brake::BrakeFile& brake, const BrakeCornerData& data,
                              const LogFitOptions& options);

/// The field table's entries of the 14 parameters the fit frees (brake_thermal_fields.h), in fit
/// order: gamma, xi, the disc's Cholesky entries l11 .. l33, then the calliper's.
const std::vector<const brake::BrakeThermalField*>& BrakeFitFields();

/// The file keys of the 14 fitted brake parameters, in fit order: "heat_partition",
/// "mass_participation", "disc_convection_cholesky_sqrtW_per_K.l11" .. ".l33", then the same
/// for the calliper.
const std::vector<std::string>& BrakeParameterKeys();

/// The keys the fit reports the convection in ("disc_convection_P11_W_per_K" ..
/// "disc_convection_P33_W_per_K", then the same for the calliper), in ConvectionMatrixEntries
/// order.
const std::vector<std::string>& ConvectionMatrixKeys();

/// The entries P11, P21, P22, P31, P32, P33 (W/K) of P = L L' of a convection polynomial, whose
/// fields are the entries of L: the coordinates the brake fit reports in.
std::array<double, 6> ConvectionMatrixEntries(const brake::ConvectionPolynomial<double>& l);

}  // namespace hotlap::ident
