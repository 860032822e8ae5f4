// The brake fit: from starting values far from the truth, gamma and xi come back within their
// intervals; the twelve convection entries are reported for P = L L' consistently with the L
// written to the file; a dead calliper sensor is excluded with a warning.

#include "hotlap/ident/brake_thermal_fit.h"

#include <cmath>

#include <gtest/gtest.h>

#include "fit_test_util.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay_io.h"

namespace hotlap::ident {
namespace {

constexpr Corner kCorner = Corner::kFrontRight;

class BrakeThermalFitTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    truth_ = new vehicle::Car(test::Gen7Car());
    auto& p = truth_->brakes[CornerIndex(kCorner)].params;
    p.heat_partition = 0.8;
    p.mass_participation = 0.15;
    sim::SynthOptions o;
    o.sensor_lag_s = 0.0;
    log_ = new sim::SynthLog(sim::SynthesizeLog(*truth_, test::OvalRoad(), o));
  }
  static void TearDownTestSuite() {
    delete log_;
    delete truth_;
  }
  BrakeCornerData Data(bool dead_calliper) {
    sim::SynthLog log = *log_;
    if (dead_calliper) {
      for (size_t i = 0; i < log.columns.size(); ++i) {
        if (log.columns[i] == "calliper_temp_fr_C")
          std::fill(log.values[i].begin(), log.values[i].end(), 0.0);
      }
    }
    sim::WriteSynthLog(dir_.path() / "log.csv", log);
    telemetry_ = std::make_unique<Telemetry>(Telemetry::Read(dir_.path() / "log.csv"));
    inputs_ = sim::ReplayInputsFromTelemetry(*telemetry_, {});
    BrakeCornerData d;
    d.samples = BrakeSamplesOf(inputs_, kCorner);
    d.disc = ReadLoggedChannel(*telemetry_, "disc_temp", kCorner, 223.15, 1773.15, 0.01);
    d.calliper = ReadLoggedChannel(*telemetry_, "calliper_temp", kCorner, 223.15, 1773.15, 0.01);
    d.weights = TrapezoidWeights(inputs_.time);
    d.fallback_disc_temp = d.fallback_calliper_temp = 350.0;
    return d;
  }

  static vehicle::Car* truth_;
  static sim::SynthLog* log_;
  test::TempDir dir_;
  std::unique_ptr<Telemetry> telemetry_;
  sim::ReplayInputs inputs_;
};

vehicle::Car* BrakeThermalFitTest::truth_ = nullptr;
sim::SynthLog* BrakeThermalFitTest::log_ = nullptr;

TEST_F(BrakeThermalFitTest, RecoversGammaAndXiFromFarAndReportsP) {
  brake::BrakeFile start = test::Gen7Car().brake(kCorner);
  start.params.heat_partition = 0.3;      // truth 0.8
  start.params.mass_participation = 0.6;  // truth 0.15
  const BrakeFitResult r = FitBrakeCorner(start, Data(false), LogFitOptions{});
  ASSERT_TRUE(r.fit && r.cholesky_fit);
  const double truth[2] = {0.8, 0.15};
  for (int i = 0; i < 2; ++i) {
    const ParameterEstimate& e = r.fit->estimates[i];
    EXPECT_TRUE(e.well_determined) << i;
    EXPECT_NEAR(e.value, truth[i], 0.005 * truth[i]) << i;  // measured: 0.03% off
    EXPECT_GE(truth[i], e.ci_low - 0.5 * e.std_error) << i;
    EXPECT_LE(truth[i], e.ci_high + 0.5 * e.std_error) << i;
  }
  ASSERT_EQ(r.fit->parameters.size(), 16u);
  EXPECT_EQ(r.fit->parameters[2].key, "disc_convection_P11_W_per_K");
  EXPECT_EQ(r.cholesky_fit->parameters[2].key, "disc_convection_cholesky_sqrtW_per_K.l11");
  // The reported P is L L' of the L written.
  const auto& l = r.params.disc_convection;
  EXPECT_NEAR(r.fit->estimates[2].value, l.l11 * l.l11, 1e-9);
  EXPECT_NEAR(r.fit->estimates[6].value, l.l31 * l.l21 + l.l32 * l.l22, 1e-9);
  EXPECT_NEAR(r.fit->estimates[7].value, l.l31 * l.l31 + l.l32 * l.l32 + l.l33 * l.l33, 1e-9);
  for (const ChannelStats& ch : r.fit->channels) EXPECT_NEAR(ch.rms, 0.5, 0.06) << ch.name;
  EXPECT_EQ(BrakeParameterKeys().size(), 14u);
  EXPECT_EQ(BrakeParameterKeys()[13], "calliper_convection_cholesky_sqrtW_per_K.l33");
}

// A disc sensor with a 0.2 s lag fitted as if it had none: the residuals follow one another
// (white sensor noise would give about 0), and the fit says so; with the lag modelled it does not.
TEST_F(BrakeThermalFitTest, AModelThatMissesTheLagIsSaidToMissSomething) {
  sim::SynthOptions o;
  o.sensor_lag_s = 0.2;
  sim::WriteSynthLog(dir_.path() / "lagged.csv", sim::SynthesizeLog(*truth_, test::OvalRoad(), o));
  const Telemetry log = Telemetry::Read(dir_.path() / "lagged.csv");
  const sim::ReplayInputs in = sim::ReplayInputsFromTelemetry(log, {});
  BrakeCornerData d;
  d.samples = BrakeSamplesOf(in, kCorner);
  d.disc = ReadLoggedChannel(log, "disc_temp", kCorner, 223.15, 1773.15, 0.01);
  d.calliper = ReadLoggedChannel(log, "calliper_temp", kCorner, 223.15, 1773.15, 0.01);
  d.weights = TrapezoidWeights(in.time);
  const auto misses = [](const BrakeFitResult& r) {
    for (const std::string& w : r.warnings) {
      if (w.find("disc_temp: the residuals follow one another") != std::string::npos) return true;
    }
    return false;
  };
  const BrakeFitResult unmodelled = FitBrakeCorner(truth_->brake(kCorner), d, LogFitOptions{});
  ASSERT_TRUE(unmodelled.fit);
  EXPECT_GT(unmodelled.fit->channels[0].autocorrelation, 0.9);
  EXPECT_TRUE(misses(unmodelled)) << ::testing::PrintToString(unmodelled.warnings);
  LogFitOptions with_lag;
  with_lag.sensor_lag_s = 0.2;
  const BrakeFitResult modelled = FitBrakeCorner(truth_->brake(kCorner), d, with_lag);
  ASSERT_TRUE(modelled.fit);
  EXPECT_FALSE(misses(modelled)) << ::testing::PrintToString(modelled.warnings);
}

TEST_F(BrakeThermalFitTest, DeadCalliperSensorIsExcludedWithAWarning) {
  const BrakeCornerData d = Data(true);
  EXPECT_FALSE(d.calliper.usable);  // 0 degC read as 273.15 K everywhere: stuck
  const BrakeFitResult r = FitBrakeCorner(test::Gen7Car().brake(kCorner), d, LogFitOptions{});
  ASSERT_TRUE(r.fit);
  bool warned = false;
  for (const std::string& w : r.warnings) {
    warned |= w.find("calliper_temp_fr_C: excluded from the fit") != std::string::npos;
  }
  EXPECT_TRUE(warned) << ::testing::PrintToString(r.warnings);
  EXPECT_EQ(r.fit->channels[1].samples, 0);
  EXPECT_NEAR(r.fit->channels[0].rms, 0.5, 0.06);
}

}  // namespace
}  // namespace hotlap::ident
