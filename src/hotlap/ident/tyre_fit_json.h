#pragma once
/// @file
/// The JSON summaries of `hotlap tyre fit --json` (docs/json-output.md): a UniTire fit with its
/// fitted and held-out temperatures, and a Magic Formula fit with its coefficients, metrics and
/// plausibility check.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/ident/mf_fit.h"
#include "hotlap/ident/unitire_fit.h"

namespace hotlap::ident {

/// A temperature's metrics: temp_C, samples, fy_rms_N, fy_peak_N, fy_rms_rel_peak, mz_rms_Nm and,
/// where measured, fx_rms_N.
nlohmann::json UniTireMetricsJson(const UniTireTempMetrics& m);

/// The metrics' temperature, degC, rounded to 1e-9 degC (so that 0 degC reads 0, not -1.7e-13).
double MetricsTempC(const UniTireTempMetrics& m);

/// Whether `m` is at one of `predict_temps_C` (within `tolerance_K`): a held-out temperature.
bool IsPredictTemp(const UniTireTempMetrics& m, const std::vector<double>& predict_temps_C,
                   double tolerance_K);

/// command, model "unitire", data, out, converged, iterations, fitted_parameters, and the fitted
/// (`fit`) and held-out (`predict`) temperatures' metrics.
nlohmann::json UniTireFitJson(const UniTireFitResult& fit, const std::string& data,
                              const std::string& out, const std::vector<double>& predict_temps_C,
                              double tolerance_K);

/// passed, the load and slip ranges checked, lateral_sign, peak_mu_y_min/max, failures,
/// at_bounds.
nlohmann::json PlausibilityJson(const MagicFormulaPlausibility& c);

/// command, model "mf", data, out, converged, iterations, coefficients (each fitted one's value),
/// metrics (per channel and load), plausibility, warnings.
nlohmann::json MagicFormulaFitJson(const MagicFormulaFitResult& fit, const std::string& data,
                                   const std::string& out);

}  // namespace hotlap::ident
