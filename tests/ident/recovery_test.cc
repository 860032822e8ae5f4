// The acceptance test of the fitting issue: a log synthesized from parameters 50% away from the
// car's (gen7) defaults, with 0.5 degC sensor noise (and the default 0.2 s sensor lag, modelled
// by the fit), gives back every tyre, wear and brake parameter inside its reported joint 95%
// interval (the intervals that hold every parameter of a report at once with 95% probability),
// within 5% wherever the fit says it is well determined, with RMS residuals near the noise level.
// One lap of a small oval at 50 Hz keeps it cheap (docs/validation/fitting.md, "Recovery").

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "fit_test_util.h"
#include "hotlap/ident/brake_thermal_fit.h"
#include "hotlap/ident/contact_length_fit.h"
#include "hotlap/ident/tyre_thermal_fit.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay_io.h"

namespace hotlap::ident {
namespace {

// How the recovered parameters compare with the truth.
struct Recovery {
  int checked = 0;  // model parameters
  int misses = 0;   // truths outside the reported 95% interval (printed, for the record)
};

// Checks one fit against the truth (model parameters only). A 95% interval misses the truth one
// time in twenty by design, and the parameters of one fit are correlated (wp1 and wp2, p3 and p4,
// the convection entries), so they miss together: "every truth inside its 95% interval" cannot
// be asked of one log. What every truth must lie inside is its reported joint interval: the
// fits are told how many parameters the report holds together (28 tyre and wear, 56 brake, 8
// contact length, as `hotlap fit` does), and those intervals hold all of them at once with 95%
// probability (Bonferroni). Also:
//  - every parameter the fit calls well determined within 5% of its truth;
//  - the caller bounds the share of truths outside their single 95% intervals (printed) loosely,
//    to catch intervals that are far too narrow. Seven seeds of this log gave 15 of 196 tyre and
//    wear truths and 4 of 392 brake truths outside their 95% intervals (docs/fitting.md).
Recovery ExpectRecovered(const FitResult& fit, const std::map<std::string, double>& truth,
                         const std::string& where) {
  Recovery out;
  for (size_t i = 0; i < fit.parameters.size(); ++i) {
    const FitParameter& p = fit.parameters[i];
    if (p.role != ParameterRole::kModel) continue;
    const ParameterEstimate& e = fit.estimates[i];
    const double t = truth.at(p.key);
    const bool inside = t >= e.ci_low && t <= e.ci_high;
    if (!inside) {
      ++out.misses;
      std::printf(
          "outside its 95%% interval: %s %s: truth %.6g, fitted %.6g +/- %.3g (%.2f std "
          "errors)\n",
          where.c_str(), p.key.c_str(), t, e.value, e.std_error,
          std::abs(t - e.value) / e.std_error);
    }
    EXPECT_TRUE(t >= e.joint_low && t <= e.joint_high)
        << where << " " << p.key << ": truth " << t << " outside its joint 95% interval ["
        << e.joint_low << ", " << e.joint_high << "]";
    EXPECT_LE(e.joint_low, e.ci_low) << where << " " << p.key;
    EXPECT_GE(e.joint_high, e.ci_high) << where << " " << p.key;
    if (e.well_determined) {
      EXPECT_LE(std::abs(e.value - t), 0.05 * std::abs(t)) << where << " " << p.key;
    }
    ++out.checked;
  }
  return out;
}

class RecoveryTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    car_ = new vehicle::Car(test::Gen7Car());
    truth_ = new vehicle::Car(*car_);
    for (auto& t : truth_->tyres) {
      auto& p = t.params;
      for (double* v : {&p.p1, &p.p2, &p.p3, &p.p4, &p.p5, &p.wear_coeff, &p.wear_exponent}) {
        *v *= 1.5;
      }
      p.contact_length_coeff *= 0.5;
      p.contact_length_exponent *= 1.05;
    }
    for (auto& b : truth_->brakes) {
      auto& p = b.params;
      p.heat_partition *= 0.5;  // x 1.5 would leave [0, 1]
      p.mass_participation *= 1.5;
      for (auto* l : {&p.disc_convection, &p.calliper_convection}) {
        for (double* v : {&l->l11, &l->l21, &l->l22, &l->l31, &l->l32, &l->l33}) *v *= 1.5;
      }
    }
    sim::SynthOptions o;  // 1 lap, 50 Hz, 0.5 degC, 0.2 s lag, seed 1
    log_ = new sim::SynthLog(sim::SynthesizeLog(*truth_, test::OvalRoad(), o));
    test::TempDir dir;
    sim::WriteSynthLog(dir.path() / "log.csv", *log_);
    telemetry_ = new Telemetry(Telemetry::Read(dir.path() / "log.csv"));
    inputs_ = new sim::ReplayInputs(sim::ReplayInputsFromTelemetry(*telemetry_, {}));
  }
  static void TearDownTestSuite() {
    delete inputs_;
    delete telemetry_;
    delete log_;
    delete truth_;
    delete car_;
  }
  // The fits of one report: `family` model parameters over the four corners.
  static LogFitOptions Options(int family) {
    LogFitOptions o;
    o.sensor_lag_s = 0.2;
    o.solver.joint_family_size = family;
    return o;
  }
  static std::map<std::string, double> TyreTruth(Corner c) {
    const auto& p = truth_->tyre(c).params;
    return {{"p1", p.p1},
            {"p2_J_per_kgN", p.p2},
            {"p3_J_per_kgN", p.p3},
            {"p4_J_per_kgN", p.p4},
            {"p5_W_per_m2K", p.p5},
            {"wp1_mm_per_s", p.wear_coeff},
            {"wp2", p.wear_exponent},
            {"p_cp1", p.contact_length_coeff},
            {"p_cp2", p.contact_length_exponent}};
  }
  static std::map<std::string, double> BrakeTruth(Corner c) {
    const auto& b = truth_->brake(c).params;
    std::map<std::string, double> t = {{"heat_partition", b.heat_partition},
                                       {"mass_participation", b.mass_participation}};
    const char* names[] = {"P11", "P21", "P22", "P31", "P32", "P33"};
    for (const auto& [prefix, l] :
         {std::pair{"disc", b.disc_convection}, std::pair{"calliper", b.calliper_convection}}) {
      const double p[] = {l.l11 * l.l11,
                          l.l21 * l.l11,
                          l.l21 * l.l21 + l.l22 * l.l22,
                          l.l31 * l.l11,
                          l.l31 * l.l21 + l.l32 * l.l22,
                          l.l31 * l.l31 + l.l32 * l.l32 + l.l33 * l.l33};
      for (int e = 0; e < 6; ++e)
        t[fmt::format("{}_convection_{}_W_per_K", prefix, names[e])] = p[e];
    }
    return t;
  }

  static vehicle::Car* car_;
  static vehicle::Car* truth_;
  static sim::SynthLog* log_;
  static Telemetry* telemetry_;
  static sim::ReplayInputs* inputs_;
};

vehicle::Car* RecoveryTest::car_ = nullptr;
vehicle::Car* RecoveryTest::truth_ = nullptr;
sim::SynthLog* RecoveryTest::log_ = nullptr;
Telemetry* RecoveryTest::telemetry_ = nullptr;
sim::ReplayInputs* RecoveryTest::inputs_ = nullptr;

TEST_F(RecoveryTest, TyreThermalAndWear) {
  const std::vector<double> weights = TrapezoidWeights(inputs_->time);
  int misses = 0, checked = 0;
  for (Corner c : kAllCorners) {
    // The thermal model uses the contact length, so it is fitted first (as a user would: fit
    // contact-length, then fit tyre with that car).
    tyre::TyreFile tyre = car_->tyre(c);
    const ContactLengthFitResult contact = FitContactLength(
        tyre, telemetry_->FilledChannel("fz", c),
        ReadLoggedChannel(*telemetry_, "rolling_radius", c, 0.05, 2.0, 1e-7), Options(8).solver);
    tyre.params.contact_length_coeff = contact.p_cp1;
    tyre.params.contact_length_exponent = contact.p_cp2;
    TyreCornerData d;
    d.samples = CornerSamplesOf(*inputs_, c);
    d.tread = ReadLoggedChannel(*telemetry_, "tread_temp", c, 223.15, 573.15, 0.01);
    d.carcass = ReadLoggedChannel(*telemetry_, "carcass_temp", c, 223.15, 573.15, 0.01);
    d.wear = ReadLoggedChannel(*telemetry_, "wear", c, -1.0, 50.0, 1e-9);
    d.weights = weights;
    const TyreFitResult r = FitTyreCorner(tyre, d, Options(28));
    ASSERT_TRUE(r.thermal && r.wear) << CornerName(c);
    const std::string where(CornerName(c));
    const Recovery thermal = ExpectRecovered(*r.thermal, TyreTruth(c), where);
    const Recovery wear = ExpectRecovered(*r.wear, TyreTruth(c), where);
    EXPECT_EQ(thermal.checked, 5);
    EXPECT_EQ(wear.checked, 2);
    misses += thermal.misses + wear.misses;
    checked += thermal.checked + wear.checked;
    // p1 and p5 are always well determined by a lap; RMS at the noise level.
    EXPECT_TRUE(r.thermal->estimates[0].well_determined) << where;
    for (const ChannelStats& ch : r.thermal->channels) {
      EXPECT_NEAR(ch.rms, 0.5, 0.06) << where << " " << ch.name;
    }
    EXPECT_NEAR(r.wear->channels[0].rms, 1e-4, 2e-5) << where;
    EXPECT_TRUE(r.thermal->converged && r.wear->converged) << where;
  }
  std::printf("%d of %d truths outside their 95%% intervals\n", misses, checked);
  EXPECT_LE(misses, 6) << "of " << checked;
}

TEST_F(RecoveryTest, Brake) {
  const std::vector<double> weights = TrapezoidWeights(inputs_->time);
  int misses = 0;
  for (Corner c : kAllCorners) {
    BrakeCornerData d;
    d.samples = BrakeSamplesOf(*inputs_, c);
    d.disc = ReadLoggedChannel(*telemetry_, "disc_temp", c, 223.15, 1773.15, 0.01);
    d.calliper = ReadLoggedChannel(*telemetry_, "calliper_temp", c, 223.15, 1773.15, 0.01);
    d.weights = weights;
    const BrakeFitResult r = FitBrakeCorner(car_->brake(c), d, Options(56));
    ASSERT_TRUE(r.fit) << CornerName(c);
    const std::string where(CornerName(c));
    const Recovery brake = ExpectRecovered(*r.fit, BrakeTruth(c), where);
    EXPECT_EQ(brake.checked, 14);
    misses += brake.misses;
    // gamma and xi are always well determined; RMS at the noise level.
    EXPECT_TRUE(r.fit->estimates[0].well_determined) << where;
    EXPECT_TRUE(r.fit->estimates[1].well_determined) << where;
    for (const ChannelStats& ch : r.fit->channels) {
      EXPECT_NEAR(ch.rms, 0.5, 0.06) << where << " " << ch.name;
    }
  }
  std::printf("%d of 56 truths outside their 95%% intervals\n", misses);
  EXPECT_LE(misses, 8);
}

TEST_F(RecoveryTest, ContactLength) {
  for (Corner c : kAllCorners) {
    const LoggedChannel radius =
        ReadLoggedChannel(*telemetry_, "rolling_radius", c, 0.05, 2.0, 1e-7);
    const ContactLengthFitResult r = FitContactLength(
        car_->tyre(c), telemetry_->FilledChannel("fz", c), radius, Options(8).solver);
    ASSERT_TRUE(r.fit) << CornerName(c);
    const Recovery contact = ExpectRecovered(*r.fit, TyreTruth(c), std::string(CornerName(c)));
    EXPECT_EQ(contact.checked, 2);
    EXPECT_LE(contact.misses, 1);
    EXPECT_NEAR(r.fit->channels[0].rms, 1e-4, 1.5e-5) << CornerName(c);
  }
}

}  // namespace
}  // namespace hotlap::ident
