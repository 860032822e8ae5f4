// The tyre fit on synthetic logs: a tyre that never slides leaves p1 undetermined (and says so),
// bad data (gaps, outliers, a dead channel) does not break it, an unmodelled sensor lag is
// flagged, and wear measured as one total fits wp1 only.

#include "hotlap/ident/tyre_thermal_fit.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "fit_test_util.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/synth_sensor.h"

namespace hotlap::ident {
namespace {

constexpr Corner kCorner = Corner::kRearRight;

bool AnyContains(const std::vector<std::string>& texts, const std::string& part) {
  for (const std::string& t : texts) {
    if (t.find(part) != std::string::npos) return true;
  }
  return false;
}

class TyreThermalFitTest : public ::testing::Test {
 protected:
  // The car's rr tyre x 1.5 (p1..p5, wp1, wp2), one lap of the oval, `edit` applied to the
  // columns before writing, read back as the command reads it.
  TyreCornerData Data(double lag_s, const std::function<void(sim::SynthLog&)>& edit = {}) {
    truth_ = test::Gen7Car();
    auto& p = truth_.tyres[CornerIndex(kCorner)].params;
    for (double* v : {&p.p1, &p.p2, &p.p3, &p.p4, &p.p5, &p.wear_coeff, &p.wear_exponent}) {
      *v *= 1.5;
    }
    sim::SynthOptions o;
    o.sensor_lag_s = lag_s;
    log_ = sim::SynthesizeLog(truth_, test::OvalRoad(), o);
    if (edit) edit(log_);
    sim::WriteSynthLog(dir_.path() / "log.csv", log_);
    telemetry_ = std::make_unique<Telemetry>(Telemetry::Read(dir_.path() / "log.csv"));
    inputs_ = sim::ReplayInputsFromTelemetry(*telemetry_, {});
    TyreCornerData d;
    d.samples = CornerSamplesOf(inputs_, kCorner);
    d.tread = ReadLoggedChannel(*telemetry_, "tread_temp", kCorner, 223.15, 573.15, 0.01);
    d.carcass = ReadLoggedChannel(*telemetry_, "carcass_temp", kCorner, 223.15, 573.15, 0.01);
    d.wear = ReadLoggedChannel(*telemetry_, "wear", kCorner, -1.0, 50.0, 1e-9);
    d.weights = TrapezoidWeights(inputs_.time);
    d.fallback_tread_temp = d.fallback_carcass_temp = 333.15;
    return d;
  }
  std::vector<double>& Column(const std::string& name) {
    for (size_t i = 0; i < log_.columns.size(); ++i) {
      if (log_.columns[i] == name) return log_.values[i];
    }
    throw std::runtime_error("no column " + name);
  }
  const tyre::TyreFile& Car() {
    static const vehicle::Car car = test::Gen7Car();
    return car.tyre(kCorner);
  }
  double Truth(int i) const {
    const auto& p = truth_.tyre(kCorner).params;
    const double v[] = {p.p1, p.p2, p.p3, p.p4, p.p5, p.wear_coeff, p.wear_exponent};
    return v[i];
  }

  test::TempDir dir_;
  vehicle::Car truth_;
  sim::SynthLog log_;
  std::unique_ptr<Telemetry> telemetry_;
  sim::ReplayInputs inputs_;
};

// No slip at all: no sliding power, so nothing in the data depends on p1 (nor on the wear law).
TEST_F(TyreThermalFitTest, NoSlidingLeavesP1Undetermined) {
  TyreCornerData d = Data(0.0, [&](sim::SynthLog& log) {
    // Zero the slips, then make the "measured" temperatures those of the slip-free inputs.
    sim::ReplayInputs in = log.inputs;
    std::fill(in.corners[CornerIndex(kCorner)].slip_angle.begin(),
              in.corners[CornerIndex(kCorner)].slip_angle.end(), 0.0);
    std::fill(in.corners[CornerIndex(kCorner)].slip_ratio.begin(),
              in.corners[CornerIndex(kCorner)].slip_ratio.end(), 0.0);
    sim::ReplayInitialState initial;
    for (auto& t : initial.tyres) t = {333.15, 333.15, 0.0, 318.15};
    for (auto& b : initial.brakes) b = {423.15, 353.15, 393.15};
    const sim::ReplayResult r = sim::RunReplay(truth_, in, initial, {});
    sim::GaussianNoise noise(3);
    const auto& h = r.corners[CornerIndex(kCorner)];
    for (size_t k = 0; k < in.time.size(); ++k) {
      Column("slip_angle_rr_rad")[k] = 0.0;
      Column("slip_ratio_rr")[k] = 0.0;
      Column("tread_temp_rr_C")[k] = h.tread_temp[k] - 273.15 + 0.5 * noise.Next();
      Column("carcass_temp_rr_C")[k] = h.carcass_temp[k] - 273.15 + 0.5 * noise.Next();
      Column("wear_rr_mm")[k] = std::nan("");
    }
  });
  const TyreFitResult r = FitTyreCorner(Car(), d, LogFitOptions{});
  ASSERT_TRUE(r.thermal);
  const ParameterEstimate& p1 = r.thermal->estimates[0];
  EXPECT_TRUE(p1.undetermined);
  EXPECT_FALSE(p1.well_determined);
  EXPECT_TRUE(std::isinf(p1.std_error));
  EXPECT_EQ(p1.ci_low, 0.0);  // the bounds
  EXPECT_EQ(p1.ci_high, 1.0);
  EXPECT_TRUE(AnyContains(r.thermal->AllWarnings(), "p1 is undetermined"))
      << ::testing::PrintToString(r.thermal->AllWarnings());
  EXPECT_TRUE(r.thermal->estimates[4].well_determined);  // p5 still is
  EXPECT_FALSE(r.wear);                                  // an empty wear column: nothing to fit
  EXPECT_TRUE(AnyContains(r.warnings, "wear_rr_mm: excluded"))
      << ::testing::PrintToString(r.warnings);
}

// Gaps in the temperatures and the inputs, 2% of tread samples 40 degC off, and a carcass sensor
// stuck at one value: the carcass is excluded with a warning, the outliers are down-weighted, and
// p1 and p5 (which the tread alone determines) are still recovered.
TEST_F(TyreThermalFitTest, BadDataDoesNotBreakTheFit) {
  TyreCornerData d = Data(0.0, [&](sim::SynthLog& log) {
    std::vector<double>& tread = Column("tread_temp_rr_C");
    for (size_t k = 100; k < tread.size(); k += 300) {
      for (size_t j = k; j < k + 20 && j < tread.size(); ++j) tread[j] = std::nan("");  // gaps
    }
    for (size_t k = 7; k < tread.size(); k += 50) tread[k] += 40.0;  // outliers
    for (size_t k = 3; k < tread.size(); k += 97) Column("fy_rr_N")[k] = std::nan("");
    std::fill(Column("carcass_temp_rr_C").begin(), Column("carcass_temp_rr_C").end(), 61.5);
  });
  EXPECT_FALSE(d.carcass.usable);
  EXPECT_GT(d.tread.empty_cells, 60);
  const TyreFitResult r = FitTyreCorner(Car(), d, LogFitOptions{});
  ASSERT_TRUE(r.thermal);
  EXPECT_TRUE(
      AnyContains(r.warnings, "carcass_temp_rr_C: excluded from the fit: constant at 334.65"))
      << ::testing::PrintToString(r.warnings);
  EXPECT_TRUE(AnyContains(r.thermal->AllWarnings(), "were down-weighted as outliers"));
  EXPECT_EQ(r.thermal->channels[1].samples, 0);
  EXPECT_NEAR(r.thermal->channels[0].sigma, 0.5, 0.06);
  for (int i : {0, 4}) {
    const ParameterEstimate& e = r.thermal->estimates[i];
    // Recovered, not merely inside an interval that an undetermined parameter's bounds would
    // also satisfy: well determined, a finite error bar under 3% of the value, within 2% of the
    // truth (measured: p1 0.3% off with a 0.6% error bar, p5 0.6% off with 1.5%).
    EXPECT_TRUE(e.well_determined) << i;
    EXPECT_TRUE(std::isfinite(e.std_error)) << i;
    EXPECT_LT(e.std_error, 0.03 * std::abs(e.value)) << i;
    EXPECT_NEAR(e.value, Truth(i), 0.02 * std::abs(Truth(i))) << i;
    EXPECT_GE(Truth(i), e.ci_low) << i;
    EXPECT_LE(Truth(i), e.ci_high) << i;
  }
}

TEST_F(TyreThermalFitTest, UnmodelledSensorLagIsFlaggedAndModelledLagIsNot) {
  const TyreCornerData d = Data(0.2);
  const TyreFitResult unmodelled = FitTyreCorner(Car(), d, LogFitOptions{});
  EXPECT_TRUE(AnyContains(unmodelled.warnings, "tread_temp: the measurements trail the model"))
      << ::testing::PrintToString(unmodelled.warnings);
  // One Gauss-Newton step from the lag-free fit sees most of the 0.2 s.
  EXPECT_NEAR(unmodelled.thermal->channels[0].apparent_lag, 0.2, 0.07);
  LogFitOptions o;
  o.sensor_lag_s = 0.2;
  const TyreFitResult modelled = FitTyreCorner(Car(), d, o);
  EXPECT_FALSE(AnyContains(modelled.warnings, "--sensor-lag-s"))
      << ::testing::PrintToString(modelled.warnings);
  // Within three standard errors, each error finite and small enough to mean something (an
  // infinite error would pass any "within 3 sigma").
  for (const ChannelStats& ch : modelled.thermal->channels) {
    EXPECT_LT(ch.apparent_lag_std_error, 0.1) << ch.name;
    EXPECT_LT(std::abs(ch.apparent_lag), 3.0 * ch.apparent_lag_std_error) << ch.name;
  }
  const ParameterEstimate& p1 = modelled.thermal->estimates[0];
  EXPECT_TRUE(p1.well_determined);
  EXPECT_LT(p1.std_error, 0.01 * p1.value);
  EXPECT_NEAR(p1.value, Truth(0), 3.0 * p1.std_error);
}

// The paper's protocol: one wear figure for the whole log (per lap x laps), the initial states
// from the first samples.
TEST_F(TyreThermalFitTest, WearAsOneTotalFitsWp1AndHoldsWp2) {
  TyreCornerData d = Data(0.0);
  d.wear_total_mm = log_.truth.corners[CornerIndex(kCorner)].wear.back();
  d.wear_total_sd_mm = 0.001;
  LogFitOptions o;
  o.initial_state = InitialStateMode::kMeasured;
  const TyreFitResult r = FitTyreCorner(Car(), d, o);
  ASSERT_TRUE(r.thermal && r.wear);
  EXPECT_EQ(r.thermal->parameters.size(), 5u);  // no initial temperatures
  ASSERT_EQ(r.wear->parameters.size(), 1u);
  EXPECT_EQ(r.wear->parameters[0].key, "wp1_mm_per_s");
  EXPECT_EQ(r.params.wear_exponent, Car().params.wear_exponent);
  EXPECT_TRUE(AnyContains(r.warnings, "wp2 held"));
  // The predicted total matches the measured one.
  EXPECT_NEAR(r.wear_model.back(), *d.wear_total_mm, 1e-3 * *d.wear_total_mm);
}

TEST(TyreThermalFitKeysTest, KeysAreTheFileKeys) {
  EXPECT_EQ(TyreParameterKeys(),
            (std::vector<std::string>{"p1", "p2_J_per_kgN", "p3_J_per_kgN", "p4_J_per_kgN",
                                      "p5_W_per_m2K", "wp1_mm_per_s", "wp2"}));
}

}  // namespace
}  // namespace hotlap::ident
