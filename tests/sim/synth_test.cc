// Synthetic logs: the documented columns, inputs written exactly, the truth behind the
// measurements (replaying the written inputs with the true parameters reproduces it), the sensor
// noise level and lag, the rolling radius from the contact-length law, determinism by seed; the
// stochastic truth (process noise): the model's mean, random-walk increments of the given
// intensity, the sensor noise unchanged.

#include "hotlap/sim/synth.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/logs/telemetry.h"
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
  // The truth runs the paper's models (synth.h).
  const vehicle::Car paper = vehicle::PaperModelsOf(*car_);
  const ReplayResult r = RunReplay(paper, log_->inputs, CarStartState(paper), {});
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

// With the car's own models as the truth, the TPMS channels: the gas's pressure and temperature
// through a 2 s lag with their noise, from a stream of their own (the other channels unchanged);
// with the paper's models (no gas) none.
TEST_F(SynthTest, TheCarsOwnModelsWriteTpmsChannelsFromANoiseStreamOfTheirOwn) {
  for (const std::string& c : log_->columns) {
    EXPECT_EQ(c.find("pressure_"), std::string::npos) << c;
    EXPECT_EQ(c.find("gas_temp_"), std::string::npos) << c;
  }
  SynthOptions o;
  o.laps = 2;
  o.rate_hz = 20.0;
  o.paper_models = false;
  const SynthLog with = SynthesizeLog(*car_, test::OvalRoad(), o);
  o.tpms.enabled = false;
  const SynthLog without = SynthesizeLog(*car_, test::OvalRoad(), o);
  ASSERT_EQ(with.columns.size(), without.columns.size() + 8);
  for (size_t i = 0; i < without.columns.size(); ++i) {
    EXPECT_EQ(with.columns[i], without.columns[i]);
    EXPECT_EQ(with.values[i], without.values[i]) << without.columns[i];
  }
  const std::vector<double>& p = Column(with, "pressure_fr_kPa");
  const std::vector<double>& truth = with.truth.corners[1].pressure;
  ASSERT_EQ(truth.size(), p.size());
  FirstOrderLag<double> lag(2.0);
  double sum2 = 0.0;
  for (size_t k = 0; k < p.size(); ++k) {
    const double e = p[k] - 1e-3 * lag.Next(with.inputs.time[k], truth[k]);
    sum2 += e * e;
  }
  EXPECT_NEAR(std::sqrt(sum2 / p.size()), 0.35, 0.04);
  // The right front's hot pressure above its cold set (48 psi at 25 degC) as its gas warms.
  EXPECT_GT(p.back(), 48 * 6.894757);
  EXPECT_GT(Column(with, "gas_temp_fr_C").back(), 40.0);
  // The paper's stochastic truth only.
  o.process_noise = SynthProcessNoise{};
  EXPECT_THROW(SynthesizeLog(*car_, test::OvalRoad(), o), InputError);
}

// The stochastic truth with zero intensities is the deterministic replay, interval by interval.
TEST_F(SynthTest, StochasticTruthWithoutNoiseIsTheReplay) {
  const vehicle::Car paper = vehicle::PaperModelsOf(*car_);
  const ReplayResult r =
      RunStochasticReplay(paper, log_->inputs, CarStartState(paper), 0.02, {}, 1);
  for (int c = 0; c < 4; ++c) {
    const CornerHistory& a = r.corners[c];
    const CornerHistory& b = log_->truth.corners[c];
    for (size_t k = 0; k < a.tread_temp.size(); k += 7) {
      EXPECT_NEAR(a.tread_temp[k], b.tread_temp[k], 1e-9) << c << " " << k;
      EXPECT_NEAR(a.carcass_temp[k], b.carcass_temp[k], 1e-9) << c << " " << k;
      EXPECT_NEAR(a.wear[k], b.wear[k], 1e-12) << c << " " << k;
      EXPECT_NEAR(a.disc_temp[k], b.disc_temp[k], 1e-9) << c << " " << k;
      EXPECT_NEAR(a.calliper_temp[k], b.calliper_temp[k], 1e-9) << c << " " << k;
      EXPECT_NEAR(a.grip_factor[k], b.grip_factor[k], 1e-9) << c << " " << k;
      EXPECT_EQ(a.brake_power[k], b.brake_power[k]) << c << " " << k;
    }
  }
}

// With process noise, the truth minus the deterministic truth is a random walk the model barely
// pulls back over one 0.05 s interval: its increments have variance q dt per state (the model's
// own pull, dt / tau of the difference, is far below the noise at these intensities), the
// increments are uncorrelated, and the measured columns are the new truth plus the same sensor
// noise as without process noise.
TEST_F(SynthTest, ProcessNoiseIsARandomWalkOfTheGivenIntensity) {
  SynthOptions o;
  o.laps = 2;
  o.rate_hz = 20.0;
  o.process_noise = SynthProcessNoise{4e-2, 1e-2, 1e-8, 1e-1, 4e-2};
  const SynthLog noisy = SynthesizeLog(*car_, test::OvalRoad(), o);
  ASSERT_EQ(noisy.inputs.time, log_->inputs.time);
  EXPECT_EQ(Column(noisy, "fz_fl_N"), Column(*log_, "fz_fl_N"));
  const double dt = 0.05;
  const double q[5] = {4e-2, 1e-2, 1e-8, 1e-1, 4e-2};
  double var[5] = {}, lag1[5] = {};
  long count = 0;
  for (int c = 0; c < 4; ++c) {
    const CornerHistory& a = noisy.truth.corners[c];
    const CornerHistory& b = log_->truth.corners[c];
    const std::vector<double>* sa[5] = {&a.tread_temp, &a.carcass_temp, &a.wear, &a.disc_temp,
                                        &a.calliper_temp};
    const std::vector<double>* sb[5] = {&b.tread_temp, &b.carcass_temp, &b.wear, &b.disc_temp,
                                        &b.calliper_temp};
    for (size_t k = 2; k < a.tread_temp.size(); ++k) {
      for (int j = 0; j < 5; ++j) {
        const auto d = [&](size_t i) { return (*sa[j])[i] - (*sb[j])[i]; };
        const double inc = d(k) - d(k - 1), previous = d(k - 1) - d(k - 2);
        var[j] += inc * inc;
        lag1[j] += inc * previous;
      }
      ++count;
    }
  }
  ASSERT_GT(count, 3000);
  for (int j = 0; j < 5; ++j) {
    // About 4000 increments: the variance to within 3 x sqrt(2 / 4000) = 7%.
    EXPECT_NEAR(var[j] / count / (q[j] * dt), 1.0, 0.07) << j;
    EXPECT_NEAR(lag1[j] / var[j], 0.0, 0.06) << j;  // uncorrelated: 3 / sqrt(4000) = 0.05
  }
  // The truth moved by far more than rounding, and the readings follow the new truth.
  double moved = 0.0, sensor2 = 0.0;
  const std::vector<double>& tread = Column(noisy, "tread_temp_rl_C");
  FirstOrderLag<double> lag(0.2);
  for (size_t k = 0; k < tread.size(); ++k) {
    moved = std::max(moved, std::abs(noisy.truth.corners[2].tread_temp[k] -
                                     log_->truth.corners[2].tread_temp[k]));
    const double e =
        tread[k] + 273.15 - lag.Next(noisy.inputs.time[k], noisy.truth.corners[2].tread_temp[k]);
    sensor2 += e * e;
  }
  EXPECT_GT(moved, 0.3);
  EXPECT_NEAR(std::sqrt(sensor2 / tread.size()), 0.5, 0.04);
  // Same seed, same log; the sensor noise stream is that of the log without process noise (the
  // process noise has its own), so the wear channel's noise is unchanged.
  const SynthLog again = SynthesizeLog(*car_, test::OvalRoad(), o);
  EXPECT_EQ(again.values, noisy.values);
  const std::vector<double>& wear = Column(noisy, "wear_fl_mm");
  const std::vector<double>& wear0 = Column(*log_, "wear_fl_mm");
  for (size_t k = 0; k < wear.size(); k += 11) {
    EXPECT_NEAR(wear[k] - noisy.truth.corners[0].wear[k], wear0[k] - log_->truth.corners[0].wear[k],
                1e-15)
        << k;
  }
  std::map<std::string, std::string> meta(noisy.metadata.begin(), noisy.metadata.end());
  EXPECT_NE(meta["process_noise"].find("tread 0.04 K^2/s"), std::string::npos)
      << meta["process_noise"];
  std::map<std::string, std::string> meta0(log_->metadata.begin(), log_->metadata.end());
  EXPECT_EQ(meta0.count("process_noise"), 0u);
}

TEST(SynthOptionsTest, BadOptionsAreInputErrors) {
  const vehicle::Car car = test::Gen7Car();
  const auto road = test::OvalRoad();
  for (const auto& edit : std::vector<std::function<void(SynthOptions&)>>{
           [](SynthOptions& o) { o.laps = 0; }, [](SynthOptions& o) { o.rate_hz = 0.0; },
           [](SynthOptions& o) { o.temp_noise_K = -1.0; },
           [](SynthOptions& o) { o.sensor_lag_s = std::nan(""); },
           [](SynthOptions& o) {
             o.process_noise = SynthProcessNoise{-1e-3, 0, 0, 0, 0};
           },
           [](SynthOptions& o) {
             o.process_noise = SynthProcessNoise{0, 0, 0, std::nan(""), 0};
           },
           [](SynthOptions& o) { o.tpms.pressure_noise_kPa = -0.1; },
           [](SynthOptions& o) { o.tpms.lag_s = std::nan(""); }}) {
    SynthOptions o;
    edit(o);
    EXPECT_THROW(SynthesizeLog(car, road, o), InputError);
  }
}

}  // namespace
}  // namespace hotlap::sim
