#include "hotlap/ident/tyre_fit_json.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"

namespace hotlap::ident {
namespace {

UniTireTempMetrics Metrics(double temp_C, bool fitted, int samples) {
  UniTireTempMetrics m;
  m.temp = CelsiusToKelvin(temp_C);
  m.fitted = fitted;
  m.samples = samples;
  m.fy_rms_N = 12.5;
  m.fy_peak_N = 2500.0;
  m.fy_rms_rel_peak = 0.005;
  m.mz_rms_Nm = 1.25;
  return m;
}

// Each temperature goes to `fit` when fitted and to `predict` when within the tolerance of a
// held-out temperature; 0 degC is written as exactly 0.
TEST(TyreFitJsonTest, UniTireTemperaturesByRole) {
  UniTireFitResult fit;
  fit.converged = true;
  fit.iterations = 17;
  fit.fitted_fields = {"p1", "p2"};
  fit.metrics = {Metrics(0.0, true, 100), Metrics(18.4, false, 50), Metrics(43.0, true, 80),
                 Metrics(60.0, false, 10)};
  fit.metrics[3].fx_rms_N = 30.0;
  const nlohmann::json j = UniTireFitJson(fit, "rig.csv", "fit.yaml", {18.0, 60.0}, 1.5);
  EXPECT_EQ(j["model"], "unitire");
  EXPECT_EQ(j["iterations"], 17);
  EXPECT_EQ(j["fitted_parameters"], nlohmann::json({"p1", "p2"}));
  ASSERT_EQ(j["fit"].size(), 2u);
  EXPECT_EQ(j["fit"][0]["temp_C"].dump(), "0.0");  // exactly zero, not -1.7e-13
  EXPECT_EQ(j["fit"][1]["samples"], 80);
  ASSERT_EQ(j["predict"].size(), 2u);
  EXPECT_DOUBLE_EQ(j["predict"][0]["temp_C"].get<double>(), 18.4);
  EXPECT_FALSE(j["predict"][0].contains("fx_rms_N"));
  EXPECT_DOUBLE_EQ(j["predict"][1]["fx_rms_N"].get<double>(), 30.0);
  EXPECT_FALSE(IsPredictTemp(Metrics(20.0, false, 1), {18.0}, 1.5));
}

TEST(TyreFitJsonTest, MagicFormulaCoefficientsMetricsAndPlausibility) {
  MagicFormulaFitResult fit;
  fit.converged = false;
  fit.fitted_coefficients = {"PDY1", "PKY1"};
  fit.params.PDY1 = 1.25;
  fit.params.PKY1 = -20.5;
  fit.metrics.push_back({"fy", 4000.0, 30, 11.0, 5000.0, 0.0022});
  fit.plausibility.passed = false;
  fit.plausibility.failures = {"side force changes sign"};
  fit.warnings = {"few samples"};
  const nlohmann::json j = MagicFormulaFitJson(fit, "rig.csv", "fit.tir");
  EXPECT_EQ(j["model"], "mf");
  EXPECT_EQ(j["converged"], false);
  EXPECT_DOUBLE_EQ(j["coefficients"]["PDY1"].get<double>(), 1.25);
  EXPECT_DOUBLE_EQ(j["coefficients"]["PKY1"].get<double>(), -20.5);
  EXPECT_EQ(j["coefficients"].size(), 2u);
  EXPECT_EQ(j["metrics"][0]["channel"], "fy");
  EXPECT_EQ(j["metrics"][0]["samples"], 30);
  EXPECT_EQ(j["plausibility"]["passed"], false);
  EXPECT_EQ(j["plausibility"]["failures"][0], "side force changes sign");
  EXPECT_EQ(j["warnings"][0], "few samples");
}

}  // namespace
}  // namespace hotlap::ident
