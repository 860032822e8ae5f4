// Synthetic logs: the documented columns, inputs written exactly, the truth behind the
// measurements (replaying the written inputs with the true parameters reproduces it), the sensor
// noise level and lag, the rolling radius from the contact-length law, determinism by seed.

#include "hotlap/sim/synth.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/telemetry.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/synth_sensor.h"
#include "ident/fit_test_util.h"

namespace hotlap::sim {
namespace {

const std::vector<double>& Column(const SynthLog& log, const std::string& name) {
  for (size_t i = 0; i < log.columns.size(); ++i) {
    if (log.columns[i] == name) return log.values[i];
  }
  throw std::runtime_error("no column " + name);
}

class SynthTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    car_ = new vehicle::Car(test::Gen7Car());
    SynthOptions o;
    o.laps = 2;
    o.rate_hz = 20.0;
    log_ = new SynthLog(SynthesizeLog(*car_, test::OvalRoad(), o));
  }
  static void TearDownTestSuite() {
    delete log_;
    delete car_;
  }
  static vehicle::Car* car_;
  static SynthLog* log_;
};
vehicle::Car* SynthTest::car_ = nullptr;
SynthLog* SynthTest::log_ = nullptr;

TEST_F(SynthTest, WritesTheSharedFormatWithEveryChannelAFitNeeds) {
  const test::TempDir dir;
  WriteSynthLog(dir.path() / "log.csv", *log_, {{"track", "oval"}});
  const Telemetry t = Telemetry::Read(dir.path() / "log.csv");
  for (Corner c : kAllCorners) {
    for (const char* q : {"speed", "fx", "fy", "fz", "slip_angle", "slip_ratio", "tread_temp",
                          "carcass_temp", "disc_temp", "calliper_temp", "wear", "rolling_radius"}) {
      EXPECT_TRUE(t.Has(q, c)) << q << " " << CornerName(c);
    }
  }
  for (const char* q : {"time", "distance", "speed", "ambient_temp", "track_temp"}) {
    EXPECT_TRUE(t.Has(q)) << q;
  }
  EXPECT_EQ(t.size(), log_->inputs.time.size());
  std::map<std::string, std::string> meta(t.metadata().begin(), t.metadata().end());
  EXPECT_EQ(meta["laps"], "2");
  EXPECT_EQ(meta["track"], "oval");
  EXPECT_EQ(meta["sensor_lag_s"], "0.2");
  EXPECT_NEAR(std::stod(meta["lap_time_s"]), log_->lap_time_s, 1e-5);
  // Two laps of about 25 s at 20 Hz.
  EXPECT_NEAR(t.index().back(), 2.0 * log_->lap_time_s, 0.05);
  EXPECT_NEAR(t.index()[1] - t.index()[0], 0.05, 1e-12);
  // Inputs are written exactly.
  EXPECT_EQ(t.Channel("fx", Corner::kRearRight), log_->inputs.corners[3].fx);
}

TEST_F(SynthTest, TruthIsTheReplayOfTheWrittenInputs) {
  ReplayInitialState initial;
  for (auto& s : initial.tyres) s = {car_->initial.tread_temp, car_->initial.carcass_temp, 0.0};
  for (auto& s : initial.brakes) s = {car_->initial.disc_temp, car_->initial.calliper_temp};
  const ReplayResult r = RunReplay(*car_, log_->inputs, initial, {});
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(r.corners[c].tread_temp, log_->truth.corners[c].tread_temp);
    EXPECT_EQ(r.corners[c].disc_temp, log_->truth.corners[c].disc_temp);
  }
}

TEST_F(SynthTest, SensorsAddLagThenNoiseOfTheGivenLevel) {
  const std::vector<double>& measured = Column(*log_, "tread_temp_fr_C");
  const std::vector<double>& truth = log_->truth.corners[1].tread_temp;
  FirstOrderLag<double> lag(0.2);
  double sum2 = 0.0;
  for (size_t k = 0; k < truth.size(); ++k) {
    const double e = measured[k] + 273.15 - lag.Next(log_->inputs.time[k], truth[k]);
    sum2 += e * e;
  }
  EXPECT_NEAR(std::sqrt(sum2 / truth.size()), 0.5, 0.04);
  // Wear: the truth plus 1e-4 mm noise, no lag.
  const std::vector<double>& wear = Column(*log_, "wear_rr_mm");
  double w2 = 0.0;
  for (size_t k = 0; k < wear.size(); ++k) {
    w2 += std::pow(wear[k] - log_->truth.corners[3].wear[k], 2);
  }
  EXPECT_NEAR(std::sqrt(w2 / wear.size()), 1e-4, 1e-5);
}

TEST_F(SynthTest, RollingRadiusFollowsTheContactLengthLaw) {
  const std::vector<double>& r = Column(*log_, "rolling_radius_rl_m");
  const auto& p = car_->tyre(Corner::kRearLeft).params;
  double sum2 = 0.0;
  for (size_t k = 0; k < r.size(); ++k) {
    const double cl = 2.0 * std::sqrt(p.unloaded_radius * p.unloaded_radius - r[k] * r[k]);
    const double law = tyre::CalcContactLength(p, log_->inputs.corners[2].fz[k]);
    const double half = 0.5 * law;
    sum2 += std::pow(r[k] - std::sqrt(p.unloaded_radius * p.unloaded_radius - half * half), 2);
    EXPECT_NEAR(cl, law, 0.01) << k;  // 0.1 mm of radius is a few mm of length
  }
  EXPECT_NEAR(std::sqrt(sum2 / r.size()), 1e-4, 1e-5);
}

TEST_F(SynthTest, SameSeedSameLogOtherSeedOtherNoise) {
  SynthOptions o;
  o.laps = 2;
  o.rate_hz = 20.0;
  const SynthLog again = SynthesizeLog(*car_, test::OvalRoad(), o);
  EXPECT_EQ(again.values, log_->values);
  o.seed = 2;
  const SynthLog other = SynthesizeLog(*car_, test::OvalRoad(), o);
  EXPECT_NE(Column(other, "tread_temp_fl_C"), Column(*log_, "tread_temp_fl_C"));
  EXPECT_EQ(Column(other, "fz_fl_N"), Column(*log_, "fz_fl_N"));
}

TEST(SynthOptionsTest, BadOptionsAreInputErrors) {
  const vehicle::Car car = test::Gen7Car();
  const auto road = test::OvalRoad();
  for (const auto& edit : std::vector<std::function<void(SynthOptions&)>>{
           [](SynthOptions& o) { o.laps = 0; }, [](SynthOptions& o) { o.rate_hz = 0.0; },
           [](SynthOptions& o) { o.temp_noise_K = -1.0; },
           [](SynthOptions& o) { o.sensor_lag_s = std::nan(""); }}) {
    SynthOptions o;
    edit(o);
    EXPECT_THROW(SynthesizeLog(car, road, o), InputError);
  }
}

}  // namespace
}  // namespace hotlap::sim
