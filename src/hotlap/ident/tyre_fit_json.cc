#include "hotlap/ident/tyre_fit_json.h"

#include <algorithm>
#include <cmath>

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/magic_formula.h"

namespace hotlap::ident {

double MetricsTempC(const UniTireTempMetrics& m) {
  return std::round(KelvinToCelsius(m.temp) * 1e9) / 1e9 + 0.0;
}

nlohmann::json UniTireMetricsJson(const UniTireTempMetrics& m) {
  nlohmann::json j = {{"temp_C", RoundSignificant(MetricsTempC(m), 6)},
                      {"samples", m.samples},
                      {"fy_rms_N", RoundSignificant(m.fy_rms_N)},
                      {"fy_peak_N", RoundSignificant(m.fy_peak_N)},
                      {"fy_rms_rel_peak", RoundSignificant(m.fy_rms_rel_peak)},
                      {"mz_rms_Nm", RoundSignificant(m.mz_rms_Nm)}};
  if (m.fx_rms_N) j["fx_rms_N"] = RoundSignificant(*m.fx_rms_N);
  return j;
}

bool IsPredictTemp(const UniTireTempMetrics& m, const std::vector<double>& predict_temps_C,
                   double tolerance_K) {
  const double temp_C = MetricsTempC(m);
  return std::any_of(predict_temps_C.begin(), predict_temps_C.end(),
                     [&](double t) { return std::abs(t - temp_C) <= tolerance_K; });
}

nlohmann::json UniTireFitJson(const UniTireFitResult& fit, const std::string& data,
                              const std::string& out, const std::vector<double>& predict_temps_C,
                              double tolerance_K) {
  nlohmann::json fitted = nlohmann::json::array(), predicted = nlohmann::json::array();
  for (const UniTireTempMetrics& m : fit.metrics) {
    if (m.fitted) fitted.push_back(UniTireMetricsJson(m));
    if (IsPredictTemp(m, predict_temps_C, tolerance_K)) predicted.push_back(UniTireMetricsJson(m));
  }
  nlohmann::json params = nlohmann::json::array();
  for (const std::string& f : fit.fitted_fields) params.push_back(f);
  return {{"command", "tyre fit"},
          {"model", "unitire"},
          {"data", data},
          {"out", out},
          {"converged", fit.converged},
          {"iterations", fit.iterations},
          {"fitted_parameters", params},
          {"fit", fitted},
          {"predict", predicted}};
}

nlohmann::json PlausibilityJson(const MagicFormulaPlausibility& c) {
  return {{"passed", c.passed},
          {"fz_min_N", RoundSignificant(c.fz_min_N)},
          {"fz_max_N", RoundSignificant(c.fz_max_N)},
          {"slip_angle_max_rad", RoundSignificant(c.slip_angle_max_rad)},
          {"slip_ratio_max", RoundSignificant(c.slip_ratio_max)},
          {"lateral_sign", c.lateral_sign},
          {"peak_mu_y_min", RoundSignificant(c.peak_mu_y_min)},
          {"peak_mu_y_max", RoundSignificant(c.peak_mu_y_max)},
          {"failures", c.failures},
          {"at_bounds", c.at_bounds}};
}

nlohmann::json MagicFormulaFitJson(const MagicFormulaFitResult& fit, const std::string& data,
                                   const std::string& out) {
  nlohmann::json coefficients = nlohmann::json::object();
  for (const std::string& name : fit.fitted_coefficients) {
    if (const tyre::MagicFormulaParamInfo* info = tyre::FindMagicFormulaParam(name)) {
      coefficients[name] = RoundSignificant(fit.params.*info->field);
    }
  }
  nlohmann::json metrics = nlohmann::json::array();
  for (const MagicFormulaFitMetrics& m : fit.metrics) {
    metrics.push_back({{"channel", m.channel},
                       {"fz_N", RoundSignificant(m.fz_N)},
                       {"samples", m.samples},
                       {"rms_N", RoundSignificant(m.rms_N)},
                       {"peak_N", RoundSignificant(m.peak_N)},
                       {"rms_rel_peak", RoundSignificant(m.rms_rel_peak)}});
  }
  return {{"command", "tyre fit"},
          {"model", "mf"},
          {"data", data},
          {"out", out},
          {"converged", fit.converged},
          {"iterations", fit.iterations},
          {"coefficients", coefficients},
          {"metrics", metrics},
          {"plausibility", PlausibilityJson(fit.plausibility)},
          {"warnings", fit.warnings}};
}

}  // namespace hotlap::ident
