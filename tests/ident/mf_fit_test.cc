#include "hotlap/ident/mf_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/magic_formula.h"
#include "hotlap/tyre/tir_file.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

using tyre::MagicFormulaParams;

MagicFormulaParams<double> Truth() {
  return tyre::LoadMagicFormula(
      test::SourcePath("tests/data/tir/mfeval/MagicFormula61_Parameters.tir"));
}

std::vector<double> Range(double from, double to, double step) {
  std::vector<double> v;
  for (double x = from; x <= to + 1e-9; x += step) v.push_back(x);
  return v;
}

std::vector<double> Degrees(std::vector<double> v) {
  for (double& x : v) x = DegToRad(x);
  return v;
}

tyre::TyreOperatingPoint<double> Point(double fz, double kappa, double alpha, double camber) {
  tyre::TyreOperatingPoint<double> op;
  op.fz = fz;
  op.slip_ratio = kappa;
  op.slip_angle = alpha;
  op.camber = camber;
  op.speed = 10.0;
  return op;
}

// Largest |fitted - truth| over pure-slip curves at a load and camber that were not in the data,
// relative to the truth's peak |F| on that curve.
double WorstPredictionError(const MagicFormulaParams<double>& fitted,
                            const MagicFormulaParams<double>& truth, double fz, double camber,
                            bool lateral) {
  double worst = 0.0, peak = 0.0;
  for (double x : lateral ? Range(-14.5, 14.5, 0.5) : Range(-0.29, 0.29, 0.01)) {
    const double kappa = lateral ? 0.0 : x;
    const double alpha = lateral ? DegToRad(x) : 0.0;
    const auto f = tyre::CalcMagicFormula(fitted, Point(fz, kappa, alpha, camber), {});
    const auto g = tyre::CalcMagicFormula(truth, Point(fz, kappa, alpha, camber), {});
    worst = std::max(worst, std::abs(lateral ? f.fy - g.fy : f.fx - g.fx));
    peak = std::max(peak, std::abs(lateral ? g.fy : g.fx));
  }
  return worst / peak;
}

// Rig data from a known MF 6.1 tyre (mfeval's example file) with 1% noise at three loads: the fit
// starts from generic coefficients, reproduces the data to the noise level, and predicts a load
// between the measured ones within 2% of the peak force.
TEST(MagicFormulaFitTest, RecoversPureSlipCurvesFromNoisyRigData) {
  const MagicFormulaParams<double> truth = Truth();
  const double fz0 = truth.FNOMIN;
  const std::vector<double> loads = {0.5 * fz0, fz0, 1.5 * fz0};
  const std::vector<double> cambers = {0.0};
  const auto samples =
      SynthesizeMagicFormulaRigData(truth, loads, cambers, Degrees(Range(-15, 15, 1)),
                                    Range(-0.3, 0.3, 0.02), 10.0, CelsiusToKelvin(40), 0.01, 7);
  const MagicFormulaFitResult fit = FitMagicFormula(samples, {});
  EXPECT_TRUE(fit.converged);
  EXPECT_EQ(fit.lateral_samples, 3 * 31 + 3);  // the longitudinal curves' kappa = 0 points too
  EXPECT_EQ(fit.longitudinal_samples, 3 * 31 + 3);
  ASSERT_EQ(fit.metrics.size(), 6u);
  for (const MagicFormulaFitMetrics& m : fit.metrics) {
    // Noise of 1% of the peak: the residual RMS is about that, never much more.
    EXPECT_LT(m.rms_rel_peak, 0.013) << m.channel << " at " << m.fz_N << " N";
    EXPECT_GT(m.rms_rel_peak, 0.006) << m.channel << " at " << m.fz_N << " N (overfitted?)";
  }
  // The start was generic, not the answer: its curves are far from the truth.
  EXPECT_GT(WorstPredictionError(fit.initial_guess, truth, fz0, 0.0, true), 0.05);
  for (double fz : {0.75 * fz0, 1.25 * fz0}) {
    EXPECT_LT(WorstPredictionError(fit.params, truth, fz, 0.0, true), 0.02) << fz;
    EXPECT_LT(WorstPredictionError(fit.params, truth, fz, 0.0, false), 0.02) << fz;
  }
  // Load-dependent terms are free with three loads.
  for (const char* name : {"PDY2", "PKY2", "PKY4", "PDX2", "PKX2", "PKX3"}) {
    EXPECT_NE(std::find(fit.fitted_coefficients.begin(), fit.fitted_coefficients.end(), name),
              fit.fitted_coefficients.end())
        << name;
  }
}

// With camber in the data, the camber terms are fitted and a camber between the measured ones is
// predicted.
TEST(MagicFormulaFitTest, FitsCamberWhenTheDataHaveIt) {
  const MagicFormulaParams<double> truth = Truth();
  const double fz0 = truth.FNOMIN;
  const std::vector<double> loads = {0.6 * fz0, fz0, 1.4 * fz0};
  const std::vector<double> cambers = Degrees({-4.0, 0.0, 4.0});
  const auto samples =
      SynthesizeMagicFormulaRigData(truth, loads, cambers, Degrees(Range(-15, 15, 1)),
                                    Range(-0.3, 0.3, 0.03), 10.0, CelsiusToKelvin(40), 0.005, 11);
  const MagicFormulaFitResult fit = FitMagicFormula(samples, {});
  for (const char* name : {"PDY3", "PKY6", "PVY3", "PDX3"}) {
    EXPECT_NE(std::find(fit.fitted_coefficients.begin(), fit.fitted_coefficients.end(), name),
              fit.fitted_coefficients.end())
        << name;
  }
  EXPECT_LT(WorstPredictionError(fit.params, truth, fz0, DegToRad(2.0), true), 0.03);
  EXPECT_LT(WorstPredictionError(fit.params, truth, 1.2 * fz0, DegToRad(-2.0), true), 0.03);
}

// One load: only what one load can identify is freed; the curve is still reproduced.
TEST(MagicFormulaFitTest, OneLoadFreesOnlyLoadFreeCoefficients) {
  const MagicFormulaParams<double> truth = Truth();
  const std::vector<double> loads = {truth.FNOMIN};
  const std::vector<double> cambers = {0.0};
  const auto samples =
      SynthesizeMagicFormulaRigData(truth, loads, cambers, Degrees(Range(-12, 12, 0.5)),
                                    Range(-0.2, 0.2, 0.01), 10.0, CelsiusToKelvin(40), 0.0, 1);
  const MagicFormulaFitResult fit = FitMagicFormula(samples, {});
  for (const char* name : {"PDY2", "PKY2", "PKY4", "PDX2", "PEY2"}) {
    EXPECT_EQ(std::find(fit.fitted_coefficients.begin(), fit.fitted_coefficients.end(), name),
              fit.fitted_coefficients.end())
        << name;
  }
  for (const MagicFormulaFitMetrics& m : fit.metrics) EXPECT_LT(m.rms_rel_peak, 0.01) << m.channel;
}

// The fitted coefficients survive the .tir writer and reader exactly.
TEST(MagicFormulaFitTest, FittedFileReadsBackToTheSameForces) {
  const MagicFormulaParams<double> truth = Truth();
  const std::vector<double> loads = {0.5 * truth.FNOMIN, truth.FNOMIN, 1.5 * truth.FNOMIN};
  const std::vector<double> cambers = {0.0};
  const auto samples =
      SynthesizeMagicFormulaRigData(truth, loads, cambers, Degrees(Range(-15, 15, 1.5)),
                                    Range(-0.3, 0.3, 0.03), 10.0, CelsiusToKelvin(40), 0.01, 3);
  const MagicFormulaFitResult fit = FitMagicFormula(samples, {});
  test::TempDir dir;
  const auto path = dir.path() / "fitted.tir";
  tyre::WriteTirFile(path, fit.params, "fitted in a test");
  const MagicFormulaParams<double> back = tyre::LoadMagicFormula(path);
  const auto op = Point(truth.FNOMIN, -0.05, DegToRad(4.0), 0.0);
  EXPECT_EQ(tyre::CalcMagicFormula(back, op, {}).fy, tyre::CalcMagicFormula(fit.params, op, {}).fy);
  EXPECT_EQ(tyre::CalcMagicFormula(back, op, {}).fx, tyre::CalcMagicFormula(fit.params, op, {}).fx);
  EXPECT_NE(test::ReadTextFile(path).find("! fitted in a test"), std::string::npos);
}

// With a base file, what the fit does not free is kept exactly as the base has it (camber terms
// for zero-camber data, PKY4 with one load, the aligning moment), and the curves still fit.
TEST(MagicFormulaFitTest, BaseCoefficientsTheFitDoesNotFreeAreKept) {
  const MagicFormulaParams<double> truth = Truth();
  const std::vector<double> loads = {truth.FNOMIN};
  const std::vector<double> cambers = {0.0};
  const auto samples =
      SynthesizeMagicFormulaRigData(truth, loads, cambers, Degrees(Range(-12, 12, 1)),
                                    Range(-0.2, 0.2, 0.02), 10.0, CelsiusToKelvin(40), 0.005, 2);
  MagicFormulaParams<double> base = tyre::LoadMagicFormula(test::Gen7Dir() / "tyres/left.tir");
  base.FNOMIN = truth.FNOMIN;
  MagicFormulaFitOptions options;
  options.base = base;
  const MagicFormulaFitResult fit = FitMagicFormula(samples, options);
  for (const char* name : {"PKY6", "PVY3", "PKY4", "PKY2", "PEY2", "PDX3"}) {
    EXPECT_EQ(std::find(fit.fitted_coefficients.begin(), fit.fitted_coefficients.end(), name),
              fit.fitted_coefficients.end())
        << name;
  }
  EXPECT_EQ(fit.params.PKY6, base.PKY6);
  EXPECT_EQ(fit.params.PVY3, base.PVY3);
  EXPECT_EQ(fit.params.PKY4, base.PKY4);
  EXPECT_EQ(fit.params.PKY2, base.PKY2);
  EXPECT_EQ(fit.params.QDZ1, base.QDZ1);
  EXPECT_EQ(fit.params.UNLOADED_RADIUS, base.UNLOADED_RADIUS);
  for (const MagicFormulaFitMetrics& m : fit.metrics) EXPECT_LT(m.rms_rel_peak, 0.01) << m.channel;
}

// A steady-state cornering run as a rig gives it: side slip only (no Fx), +80 N of Fy at zero
// slip at every load (the usual offset), 1.5% noise and a light load group (0.1 x the tyre's
// FNOMIN) where small slip angles give less force than the offset. The sign of the cornering
// stiffness comes from all the data, so the start and the fit keep ISO's negative Fy for
// positive alpha, and the fitted tyre passes the plausibility check over 0.1-2 x FNOMIN.
TEST(MagicFormulaFitTest, OffsetsNoiseAndALightLoadKeepTheIsoSign) {
  const MagicFormulaParams<double> truth = Truth();
  const double fz0 = truth.FNOMIN;
  const std::vector<double> loads = {0.1 * fz0, 0.4 * fz0, 0.8 * fz0, 1.2 * fz0};
  const std::vector<double> cambers = {0.0};
  std::vector<double> one_sided = {0.25, 0.5, 1.0};
  for (double a = 2.0; a <= 12.0; a += 1.0) one_sided.push_back(a);
  for (const std::vector<double>& alphas : {Degrees(one_sided), Degrees(Range(-12, 12, 0.5))}) {
    auto samples = SynthesizeMagicFormulaRigData(truth, loads, cambers, alphas, {}, 10.0,
                                                 CelsiusToKelvin(60), 0.015, 11);
    for (RigSample& s : samples) {
      s.fy += 80.0;
      s.fx.reset();
    }
    const MagicFormulaFitResult fit = FitMagicFormula(samples, {});
    const std::string what = fmt::format("{} slip angles", alphas.size());
    EXPECT_LT(fit.initial_guess.PKY1, 0.0) << what;
    EXPECT_LT(fit.params.PKY1, 0.0) << what;
    EXPECT_EQ(fit.plausibility.lateral_sign, -1.0) << what;
    EXPECT_TRUE(fit.plausibility.passed)
        << what << ": " << fmt::format("{}", fmt::join(fit.plausibility.failures, "; "));
    EXPECT_DOUBLE_EQ(fit.plausibility.fz_min_N, 0.1 * fit.params.FNOMIN);
    EXPECT_GT(fit.plausibility.peak_mu_y_min, 0.3) << what;
    // PKY4 atan(Fz / (PKY2 Fz0)) stays inside (0, pi) up to 2 x FNOMIN.
    EXPECT_LT(fit.params.PKY4 * std::atan(2.0 / (fit.params.PKY2 * fit.params.LFZO)), kPi) << what;
    // RMS per load group: four lateral groups, each near the noise level.
    ASSERT_EQ(fit.metrics.size(), 4u) << what;
    for (const MagicFormulaFitMetrics& m : fit.metrics) {
      EXPECT_EQ(m.channel, "fy");
      EXPECT_LT(m.rms_rel_peak, 0.08) << what << " at " << m.fz_N << " N";
    }
    for (double fz = 0.1 * fz0; fz <= 2.0 * fz0; fz += 0.1 * fz0) {
      const auto f = tyre::CalcMagicFormula(fit.params, Point(fz, 0.0, DegToRad(1.0), 0.0), {});
      EXPECT_LT(f.fy, 0.0) << what << " at " << fz << " N";
    }
  }
}

// The check fails, saying why, on hand-made implausible sets, and passes the real tyre.
TEST(MagicFormulaFitTest, PlausibilityCheckFailsOnImplausibleCoefficients) {
  const MagicFormulaParams<double> truth = Truth();
  const MagicFormulaPlausibility good = CheckMagicFormulaPlausibility(truth, DegToRad(15), 0.3);
  EXPECT_TRUE(good.passed) << fmt::format("{}", fmt::join(good.failures, "; "));
  EXPECT_GT(good.peak_mu_y_min, 0.5);

  MagicFormulaParams<double> wrong_sign = truth;
  wrong_sign.PKY1 = 28.3;  // ISO wants negative
  const MagicFormulaPlausibility a = CheckMagicFormulaPlausibility(wrong_sign, DegToRad(15));
  EXPECT_FALSE(a.passed);
  ASSERT_EQ(a.failures.size(), 1u);
  EXPECT_NE(a.failures[0].find("Fy stiffness"), std::string::npos) << a.failures[0];
  EXPECT_NE(a.failures[0].find("is not negative as the data's"), std::string::npos);

  MagicFormulaParams<double> past_pi = truth;  // the fit: PKY4 2.40 with PKY2 at 0.05
  past_pi.PKY4 = 2.4;
  past_pi.PKY2 = 0.05;
  const MagicFormulaPlausibility b = CheckMagicFormulaPlausibility(past_pi, DegToRad(15));
  EXPECT_FALSE(b.passed);
  ASSERT_EQ(b.failures.size(), 1u);
  EXPECT_NE(b.failures[0].find("PKY4 atan(Fz / (PKY2 Fz0)) = "), std::string::npos)
      << b.failures[0];
  EXPECT_NE(b.failures[0].find("outside (0, pi): the cornering stiffness changes sign"),
            std::string::npos);
}

TEST(MagicFormulaFitTest, WarnsAboutTemperaturesAndCombinedSamples) {
  const MagicFormulaParams<double> truth = Truth();
  const std::vector<double> loads = {truth.FNOMIN};
  const std::vector<double> cambers = {0.0};
  auto samples = SynthesizeMagicFormulaRigData(truth, loads, cambers, Degrees(Range(-10, 10, 1)),
                                               Range(-0.2, 0.2, 0.02), 10.0, 300.0, 0.0, 1);
  samples[3].tread_temp = 320.0;
  RigSample combined = samples[5];
  combined.slip_ratio = 0.05;
  combined.slip_angle = 0.05;
  samples.push_back(combined);
  const MagicFormulaFitResult fit = FitMagicFormula(samples, {});
  ASSERT_EQ(fit.warnings.size(), 2u);
  EXPECT_NE(fit.warnings[0].find("temperatures span 20.0 K"), std::string::npos);
  EXPECT_NE(fit.warnings[1].find("1 combined-slip samples"), std::string::npos);
}

TEST(MagicFormulaFitTest, RejectsUnusableInput) {
  std::vector<RigSample> combined_only(5);
  for (RigSample& s : combined_only) {
    s.fz = 4000.0;
    s.slip_ratio = 0.1;
    s.slip_angle = 0.05;
    s.speed = 10.0;
    s.tread_temp = 300.0;
  }
  EXPECT_THROW(FitMagicFormula(combined_only, {}), InputError);
  std::vector<RigSample> bad(1);
  bad[0].fz = 4000.0;
  bad[0].fy = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(FitMagicFormula(bad, {}), InputError);
  bad[0].fy = 0.0;
  bad[0].fz = -1.0;
  EXPECT_THROW(FitMagicFormula(bad, {}), InputError);
}

}  // namespace
}  // namespace hotlap::ident
