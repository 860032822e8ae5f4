#include "hotlap/ident/unitire_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

using tyre::UniTireParams;

// A known temperature-dependent UniTire tyre (the shipped example's values, with a stronger
// temperature effect and curvature).
UniTireParams<double> Truth() {
  UniTireParams<double> p;
  p.nominal_load = 6000.0;
  p.cornering_stiffness_per_load = 20.0;
  p.cornering_stiffness_load_quad = -0.15;
  p.cornering_stiffness_load_lin = 0.70;
  p.cornering_stiffness_camber = 0.0;
  p.slip_stiffness_per_load = 25.0;
  p.slip_stiffness_load_quad = 0.0;
  p.slip_stiffness_load_lin = 0.30;
  p.friction_x = 1.05;
  p.friction_y = 1.0;
  p.friction_load_decay = 0.1;
  p.friction_sliding_ratio = 1.0;
  p.friction_peak_speed = 1.0;
  p.friction_speed_shape = 1.0;
  p.curvature_x = -0.2;
  p.curvature_y = -0.3;
  p.trail = 0.045;
  p.trail_load_exponent = 0.5;
  p.trail_offset = 0.01;
  p.trail_decay_lin = 0.6;
  p.trail_decay_quad = 0.2;
  p.stiffness_temperature = {1.0, 0.008, CelsiusToKelvin(20.0)};
  p.trail_temperature = {1.0, 0.004, CelsiusToKelvin(20.0)};
  p.friction_temperature = {1.0, 0.0, CelsiusToKelvin(20.0)};
  return p;
}

std::vector<double> Kelvin(std::vector<double> celsius) {
  for (double& t : celsius) t = CelsiusToKelvin(t);
  return celsius;
}

// The paper's protocol (001 §5): six temperatures, fit on 0, 10, 32, 43 degC, predict 18 and 53.
struct Protocol {
  std::vector<double> temps = Kelvin({0, 10, 18, 32, 43, 53});
  std::vector<double> fit_temps = Kelvin({0, 10, 32, 43});
  std::vector<double> loads = {2000, 4000, 6000, 8000, 10000, 12000};  // 001 Table 1
  std::vector<double> slip_angles;
  Protocol() {
    for (int deg = -12; deg <= 12; ++deg) slip_angles.push_back(DegToRad(deg));
  }
};

TEST(UniTireFitTest, SynthesisIsSeededAndNoisy) {
  const Protocol pr;
  const auto a = SynthesizeRigData(Truth(), pr.temps, pr.loads, pr.slip_angles, 0.01, 7);
  const auto b = SynthesizeRigData(Truth(), pr.temps, pr.loads, pr.slip_angles, 0.01, 7);
  const auto c = SynthesizeRigData(Truth(), pr.temps, pr.loads, pr.slip_angles, 0.0, 7);
  ASSERT_EQ(a.size(), 6u * 6u * 25u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].fy, b[i].fy);
    EXPECT_EQ(a[i].speed, kRigSpeed);
  }
  // Noiseless data: the truth reproduces it exactly; 1% noise: RMS near 1% of each curve's peak.
  for (const UniTireTempMetrics& m : EvaluateUniTire(Truth(), c, pr.fit_temps, 1.5)) {
    EXPECT_LT(m.fy_rms_N, 1e-9);
    EXPECT_LT(m.mz_rms_Nm, 1e-9);
  }
  for (const UniTireTempMetrics& m : EvaluateUniTire(Truth(), a, pr.fit_temps, 1.5)) {
    EXPECT_GT(m.fy_rms_rel_peak, 0.003);
    EXPECT_LT(m.fy_rms_rel_peak, 0.012);
  }
}

TEST(UniTireFitTest, FitsFourTemperaturesAndPredictsTwo) {
  const auto start = std::chrono::steady_clock::now();
  const Protocol pr;
  const UniTireParams<double> truth = Truth();
  const std::vector<RigSample> samples =
      SynthesizeRigData(truth, pr.temps, pr.loads, pr.slip_angles, 0.01, 2025);
  UniTireFitOptions options;
  options.fit_temps = pr.fit_temps;
  // Conventions, not fitted values: the same Fz_n and T_ref as the truth so that the fitted
  // coefficients can be compared one by one.
  options.nominal_load = truth.nominal_load;
  options.reference_temp = truth.stiffness_temperature.reference_temp;

  const UniTireParams<double> guess = CalcUniTireInitialGuess(samples, options);
  // The default starting point is not the truth.
  EXPECT_GT(std::abs(guess.trail_offset - truth.trail_offset), 1e-3);
  EXPECT_GT(std::abs(guess.curvature_y - truth.curvature_y), 0.1);

  const UniTireFitResult r = FitUniTire(samples, options);
  std::cout << r.report << "\n";
  ASSERT_EQ(r.metrics.size(), 6u);
  int held_out = 0;
  for (const UniTireTempMetrics& m : r.metrics) {
    std::cout << (m.fitted ? "fit  " : "pred ") << KelvinToCelsius(m.temp) << " degC: fy_rms "
              << m.fy_rms_N << " N (" << 100 * m.fy_rms_rel_peak << "% of peak " << m.fy_peak_N
              << " N), mz_rms " << m.mz_rms_Nm << " N m\n";
    EXPECT_LT(m.fy_rms_rel_peak, 0.02) << KelvinToCelsius(m.temp);
    if (!m.fitted) {
      ++held_out;
      // Noise alone is at most 1% of a curve's peak; the prediction adds little to it.
      EXPECT_LT(m.fy_rms_rel_peak, 0.01) << KelvinToCelsius(m.temp);
    }
  }
  EXPECT_EQ(held_out, 2);

  // The parameters come back.
  const UniTireParams<double>& p = r.params;
  EXPECT_NEAR(p.stiffness_temperature.decay, 0.008, 0.0005);
  EXPECT_NEAR(p.trail_temperature.decay, 0.004, 0.001);
  EXPECT_NEAR(p.friction_y, 1.0, 0.02);
  EXPECT_NEAR(p.friction_load_decay, 0.1, 0.02);
  EXPECT_NEAR(p.curvature_y, -0.3, 0.1);
  EXPECT_NEAR(p.trail, 0.045, 0.002);
  for (double fz : pr.loads) {
    for (double t : pr.temps) {
      const double k_true = tyre::CalcUniTireCorneringStiffness(truth, fz, 0.0, t);
      const double k_fit = tyre::CalcUniTireCorneringStiffness(p, fz, 0.0, t);
      EXPECT_NEAR(k_fit / k_true, 1.0, 0.02) << fz << " N " << t << " K";
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "fit took " << seconds << " s, " << r.iterations << " iterations\n";
}

// With Fx measured in pure longitudinal slip, the longitudinal parameters are freed and found.
TEST(UniTireFitTest, FitsLongitudinalSlipWhenFxIsMeasured) {
  UniTireParams<double> truth = Truth();
  truth.slip_stiffness_load_quad = 0.05;
  truth.friction_x = 1.1;
  truth.curvature_x = 0.2;
  const std::vector<double> temps = Kelvin({0, 10, 32, 43});
  const std::vector<double> loads = {2000, 6000, 10000};
  std::vector<double> slip_angles;
  for (int deg = -12; deg <= 12; ++deg) slip_angles.push_back(DegToRad(deg));
  std::vector<RigSample> samples = SynthesizeRigData(truth, temps, loads, slip_angles, 0.01, 3);
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (double t : temps) {
    for (double fz : loads) {
      for (int k = -10; k <= 10; ++k) {
        RigSample s;
        s.slip_ratio = 0.02 * k;
        s.fz = fz;
        s.speed = kRigSpeed;
        s.tread_temp = t;
        tyre::TyreOperatingPoint<double> op;
        op.fz = fz;
        op.slip_ratio = s.slip_ratio;
        op.speed = s.speed;
        op.tread_temp = t;
        const tyre::TyreForces<double> f = tyre::CalcUniTireForces(truth, op);
        s.fx = f.fx + 0.01 * 1.1 * fz * normal(rng);
        s.fy = f.fy;
        s.mz = f.mz;
        samples.push_back(s);
      }
    }
  }
  UniTireFitOptions options;
  options.fit_temps = temps;
  options.nominal_load = truth.nominal_load;
  options.reference_temp = truth.stiffness_temperature.reference_temp;
  const UniTireFitResult r = FitUniTire(samples, options);
  EXPECT_TRUE(r.converged) << r.report;
  EXPECT_NE(std::find(r.fitted_fields.begin(), r.fitted_fields.end(), "friction_x"),
            r.fitted_fields.end());
  EXPECT_NEAR(r.params.friction_x, 1.1, 0.02);
  EXPECT_NEAR(r.params.curvature_x, 0.2, 0.1);
  for (double fz : loads) {
    const double k_true = tyre::CalcUniTireSlipStiffness(truth, fz, temps[1]);
    const double k_fit = tyre::CalcUniTireSlipStiffness(r.params, fz, temps[1]);
    EXPECT_NEAR(k_fit / k_true, 1.0, 0.03) << fz;
  }
  for (const UniTireTempMetrics& m : r.metrics) {
    ASSERT_TRUE(m.fx_rms_N.has_value());
    EXPECT_LT(*m.fx_rms_N, 0.015 * 1.1 * 10000.0);  // noise is 1% of mu_x Fz
  }
}

TEST(UniTireFitTest, RejectsUnusableInput) {
  const Protocol pr;
  const auto samples = SynthesizeRigData(Truth(), pr.temps, pr.loads, pr.slip_angles, 0.0, 1);
  UniTireFitOptions options;
  EXPECT_THROW(FitUniTire(samples, options), InputError);  // no fit temperatures
  options.fit_temps = {400.0};
  EXPECT_THROW(FitUniTire(samples, options), InputError);  // none at them
  std::vector<RigSample> bad(samples.begin(), samples.end());
  bad[3].fz = -1.0;
  options.fit_temps = pr.fit_temps;
  EXPECT_THROW(FitUniTire(bad, options), InputError);
}

TEST(RequireFitAndPredictTempsTest, EveryTemperatureInTheDataAndNoneInBothRoles) {
  std::vector<RigSample> samples(3);
  samples[0].tread_temp = CelsiusToKelvin(20.0);
  samples[1].tread_temp = CelsiusToKelvin(60.0);
  samples[2].tread_temp = CelsiusToKelvin(100.4);
  UniTireFitOptions o;
  o.temp_tolerance = 1.0;
  o.fit_temps = {CelsiusToKelvin(20.0), CelsiusToKelvin(100.0)};
  EXPECT_NO_THROW(RequireFitAndPredictTemps(samples, o, {CelsiusToKelvin(60.0)}, "rig.csv"));
  const auto message = [&](const std::vector<double>& predict) {
    return test::InputErrorOf([&] { RequireFitAndPredictTemps(samples, o, predict, "rig.csv"); });
  };
  // A predict temperature with no sample within 1 K: named with the file.
  EXPECT_PRED2(test::Contains, message({CelsiusToKelvin(40.0)}),
               "rig.csv: no rig sample within 1 K of 40 degC");
  // A predict temperature that is also a fit temperature.
  EXPECT_PRED2(test::Contains, message({CelsiusToKelvin(20.5)}), "both a fit and a predict");
  // A fit temperature with no sample.
  o.fit_temps.push_back(CelsiusToKelvin(80.0));
  EXPECT_PRED2(test::Contains, message({}), "of 80 degC");
}

}  // namespace
}  // namespace hotlap::ident
