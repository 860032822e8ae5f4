// The observer's line reader and writer, the noise file and the fit-residual noise, the
// consistency monitor's chi-square bounds and disagreement timing.

#include "hotlap/observe/stream_io.h"

#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/observe/consistency.h"
#include "hotlap/observe/observer_config.h"
#include "test_util.h"

namespace hotlap::observe {
namespace {

std::string Header() {
  std::string h = "time_s,speed_kph";
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    const std::string n(c);
    h += ",fx_" + n + "_kN,fy_" + n + "_N,fz_" + n + "_N,slip_angle_" + n + "_deg,slip_ratio_" + n +
         ",tread_temp_" + n + "_C,disc_temp_" + n + "_C,carcass_temp_" + n + "_C";
  }
  return h;
}

// One line: time, speed 180 kph, then per corner fx (kN), fy, fz, slip angle (deg), slip
// ratio, tread, disc, carcass; `fl_fx` and `fl_disc` as given (empty for a blank cell).
std::string Line(const std::string& time, const std::string& fl_fx, const std::string& fl_disc) {
  std::string l = time + ",180";
  for (int c = 0; c < 4; ++c) {
    l += "," + (c == 0 ? fl_fx : std::string("-1")) + ",2000,5000,2,-0.01,80," +
         (c == 0 ? fl_disc : std::string("400")) + ",77";
  }
  return l;
}

TEST(StreamIoTest, ReadsOneSampleALineInSiHoldingInputsAndMarkingDropouts) {
  std::istringstream in("# track: darlington\n" + Header() + "\n" + Line("0", "-2", "500") +
                        "\n\n" + Line("0.01", "", "") + "\n");
  TelemetryLineReader reader(in, "test.csv", {300.0, 320.0});
  const std::optional<ObserverSample> a = reader.Next();
  ASSERT_TRUE(a);
  EXPECT_EQ(reader.line(), 3);
  EXPECT_EQ(reader.metadata().at(0).first, "track");
  EXPECT_NEAR(a->inputs[0].speed, 50.0, 1e-12);  // 180 kph
  EXPECT_NEAR(a->inputs[0].fx, -2000.0, 1e-9);
  EXPECT_NEAR(a->inputs[1].slip_angle, 2.0 * M_PI / 180.0, 1e-12);
  EXPECT_NEAR(a->readings[0].disc_temp, CelsiusToKelvin(500.0), 1e-9);
  EXPECT_NEAR(a->readings[3].tread_temp, CelsiusToKelvin(80.0), 1e-9);
  EXPECT_TRUE(std::isnan(a->readings[0].calliper_temp));  // no such column
  EXPECT_EQ(a->ambient_temp, 300.0);                      // not logged: the default
  const std::optional<ObserverSample> b = reader.Next();
  ASSERT_TRUE(b);
  EXPECT_EQ(reader.line(), 5);                        // the blank line skipped
  EXPECT_NEAR(b->inputs[0].fx, -2000.0, 1e-9);        // empty input: held
  EXPECT_TRUE(std::isnan(b->readings[0].disc_temp));  // empty reading: a dropout
  EXPECT_FALSE(reader.Next());
}

// Values just outside their range are warned of once per column, as for a whole log: the lines
// of a wheel in the air in one warning with their count and first and last lines, and a locked
// wheel two lines later in its own (they were one warning a line, the first 20 only).
TEST(StreamIoTest, WarnsOncePerColumnOfTreatedValues) {
  std::string text = Header() + "\n";
  for (int k = 0; k < 30; ++k) {
    std::string line = Line(std::to_string(0.01 * k), "-2", "500");
    if (k >= 3 && k < 28) line.replace(line.find(",5000,"), 6, ",-100,");  // fz of fl
    if (k == 29) line.replace(line.rfind(",-0.01,"), 7, ",-1.02,");        // slip ratio of rr
    text += line + "\n";
  }
  std::istringstream in(text);
  TelemetryLineReader reader(in, "test.csv", {300.0, 320.0});
  while (reader.Next()) {
  }
  ASSERT_EQ(reader.warning_count(), 2);
  ASSERT_EQ(reader.warnings().size(), 2u);
  EXPECT_TRUE(test::Contains(reader.warnings()[0], "'fz_fl_N': 25 values")) << reader.warnings()[0];
  EXPECT_TRUE(test::Contains(reader.warnings()[0], "(lines 5-29)")) << reader.warnings()[0];
  EXPECT_TRUE(test::Contains(reader.warnings()[1], "'slip_ratio_rr': 1 value"))
      << reader.warnings()[1];
  EXPECT_TRUE(test::Contains(reader.warnings()[1], "(lines 31-31)")) << reader.warnings()[1];
}

// A brake_power column is the brake's input (the rear discs of a spool share the axle's power):
// the force the brake model takes gives it back at the line's speed; an empty cell holds it.
TEST(StreamIoTest, ABrakePowerColumnIsTheBrakesInput) {
  std::istringstream in(Header() + ",brake_power_rl_kW\n" + Line("0", "-2", "500") + ",30\n" +
                        Line("0.01", "-2", "500") + ",\n");
  TelemetryLineReader reader(in, "test.csv", {300.0, 320.0});
  const std::optional<ObserverSample> a = reader.Next();
  ASSERT_TRUE(a);
  EXPECT_NEAR(a->inputs[2].brake_fx, -30000.0 / 50.0, 1e-9);  // 30 kW at 180 kph
  EXPECT_NEAR(a->inputs[2].fx, -1000.0, 1e-9);                // the tyre's own, unchanged
  EXPECT_TRUE(std::isnan(a->inputs[0].brake_fx));             // no column: the brake sees fx
  const std::optional<ObserverSample> b = reader.Next();
  ASSERT_TRUE(b);
  EXPECT_NEAR(b->inputs[2].brake_fx, -600.0, 1e-9);  // empty: held
}

TEST(StreamIoTest, RefusesWhatItCannotRead) {
  const auto error = [](const std::string& text) {
    return test::InputErrorOf([&] {
      std::istringstream in(text);
      TelemetryLineReader reader(in, "s", {});
      while (reader.Next()) {
      }
    });
  };
  EXPECT_TRUE(test::Contains(error(""), "no header"));
  EXPECT_TRUE(test::Contains(error(Header() + "\n" + Line("0", "x", "1") + "\n"),
                             "s:2: column 'fx_fl_kN' (column 3): 'x' is not a number"));
  EXPECT_TRUE(test::Contains(error(Header() + "\n" + Line("0", "", "1") + "\n"),
                             "'fx_fl_kN' is empty and no earlier line"));
  EXPECT_TRUE(test::Contains(
      error(Header() + "\n" + Line("1", "1", "1") + "\n" + Line("1", "1", "1") + "\n"),
      "s:3: time 1 s does not increase"));
  EXPECT_TRUE(test::Contains(error(Header() + "\n1,2\n"), "s:2: 2 cells, the header has"));
  EXPECT_TRUE(test::Contains(error("time_s,speed_mps\n0,1\n"), "fx_fl"));
}

TEST(StreamIoTest, WriterWritesLinesAsTheyCome) {
  const test::TempDir dir;
  const std::string path = (dir.path() / "est.csv").string();
  LineCsvWriter w(path);
  w.WriteHeader({"time_s", "a"});
  EXPECT_EQ(test::ReadTextFile(path), "time_s,a\n");  // flushed: readable before the end
  w.WriteRow({0.5, std::nan("")});
  EXPECT_EQ(test::ReadTextFile(path), "time_s,a\n0.5,\n");
  w.WriteRow({1.0, 1.0 / 3.0});
  w.Close();
  EXPECT_EQ(test::ReadTextFile(path), "time_s,a\n0.5,\n1,0.333333333\n");
  EXPECT_TRUE(
      test::Contains(test::InputErrorOf([&] { LineCsvWriter((dir.path() / "no/x.csv").string()); }),
                     "cannot write"));
}

TEST(ObserverConfigTest, LoadsTheShippedFileStrictly) {
  const ObserverConfig c = LoadObserverConfig(test::SourcePath("data/observer/default.yaml"));
  EXPECT_EQ(c.name, "default");
  EXPECT_EQ(c.sensors[2].tread_temp, 0.5);
  EXPECT_FALSE(c.p5_scale.estimate);
  EXPECT_EQ(c.max_step_s, 0.02);
  const test::TempDir dir;
  const std::string text = test::ReadTextFile(test::SourcePath("data/observer/default.yaml"));
  const auto path =
      test::WriteTextFile(dir.path() / "bad.yaml",
                          test::ReplaceOnce(text, "tread_temp_sd_C: 0.5", "tread_temp_sd_C: -1"));
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { LoadObserverConfig(path); }),
                             "sensor_noise.tread_temp_sd_C"));
  const auto typo = test::WriteTextFile(dir.path() / "typo.yaml",
                                        test::ReplaceOnce(text, "window_s:", "window_secs:"));
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { LoadObserverConfig(typo); }), "window"));
}

// The optional sensor_lag section: zero without it (the shipped file), read strictly with it.
TEST(ObserverConfigTest, ReadsAnOptionalSensorLagSection) {
  const std::string text = test::ReadTextFile(test::SourcePath("data/observer/default.yaml"));
  const ObserverConfig plain = LoadObserverConfig(test::SourcePath("data/observer/default.yaml"));
  EXPECT_EQ(plain.sensor_lag.tread_temp, 0.0);
  EXPECT_EQ(plain.sensor_lag.calliper_temp, 0.0);
  const test::TempDir dir;
  const std::string lag =
      "sensor_lag:\n  tread_temp_tau_s: 0.2\n  disc_temp_tau_s: 0.3\n  calliper_temp_tau_s: 1.5\n";
  const ObserverConfig c =
      LoadObserverConfig(test::WriteTextFile(dir.path() / "lag.yaml", text + lag));
  EXPECT_EQ(c.sensor_lag.tread_temp, 0.2);
  EXPECT_EQ(c.sensor_lag.disc_temp, 0.3);
  EXPECT_EQ(c.sensor_lag.calliper_temp, 1.5);
  const auto negative =
      test::WriteTextFile(dir.path() / "neg.yaml", text + test::ReplaceOnce(lag, "0.3", "-0.3"));
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { LoadObserverConfig(negative); }),
                             "sensor_lag.disc_temp_tau_s"));
  const auto missing = test::WriteTextFile(dir.path() / "missing.yaml",
                                           text + "sensor_lag:\n  tread_temp_tau_s: 0.2\n");
  EXPECT_TRUE(
      test::Contains(test::InputErrorOf([&] { LoadObserverConfig(missing); }), "disc_temp_tau_s"));
}

TEST(ObserverConfigTest, TakesSensorNoiseFromAFitsResiduals) {
  const test::TempDir dir;
  const auto fit = test::WriteTextFile(
      dir.path() / "fit.json",
      R"({"command": "fit", "corners": {"fl": {"rms_tread_C": 0.8, "rms_disc_C": 2.5},
          "rr": {"rms_tread_C": 0.6}}})");
  ObserverConfig c = LoadObserverConfig(test::SourcePath("data/observer/default.yaml"));
  EXPECT_EQ(ApplyFitResidualNoise(fit, c), 3);
  EXPECT_EQ(c.sensors[0].tread_temp, 0.8);
  EXPECT_EQ(c.sensors[0].disc_temp, 2.5);
  EXPECT_EQ(c.sensors[0].calliper_temp, 0.5);
  EXPECT_EQ(c.sensors[1].tread_temp, 0.5);
  EXPECT_EQ(c.sensors[3].tread_temp, 0.6);
  EXPECT_TRUE(test::Contains(c.source, "sensor noise from"));
  const auto bad = test::WriteTextFile(dir.path() / "bad.json", R"({"lap_time_s": 1})");
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { ApplyFitResidualNoise(bad, c); }),
                             "not a fit summary"));
}

TEST(ConsistencyTest, MeanNisBoundsAreTheChiSquareQuantiles) {
  // chi-square(n) 2.5% and 97.5% quantiles / n, from tables.
  auto [lo, hi] = MeanNisBounds95(100);
  EXPECT_NEAR(lo, 74.2219 / 100, 0.003);
  EXPECT_NEAR(hi, 129.5612 / 100, 0.003);
  std::tie(lo, hi) = MeanNisBounds95(1000);
  EXPECT_NEAR(lo, 914.2572 / 1000, 0.0005);
  EXPECT_NEAR(hi, 1089.5309 / 1000, 0.0005);
  std::tie(lo, hi) = MeanNisBounds95(0);
  EXPECT_EQ(lo, 0.0);
  EXPECT_TRUE(std::isinf(hi));
}

TEST(ConsistencyTest, WarnsOnceWhenTheRunningMeanStaysHighLongerThanTheSetTime) {
  SensorMonitor m;
  int warnings = 0;
  double warned_at = -1.0;
  for (int k = 0; k <= 2000; ++k) {
    const double t = 0.01 * k;
    const double nis = t >= 5.0 && t < 15.0 ? 50.0 : 1.0;  // 10 s of trouble
    const std::optional<double> since = m.Record(t, nis, nis < 25.0, 1.0, 9.0, 3.0);
    if (since) {
      ++warnings;
      warned_at = t;
      EXPECT_GT(*since, 5.0);
      EXPECT_LT(*since, 5.5);
    }
  }
  EXPECT_EQ(warnings, 1);
  EXPECT_GT(warned_at, 8.0);
  EXPECT_LT(warned_at, 8.6);
  EXPECT_EQ(m.rejected, 1000);
  EXPECT_EQ(m.used, 1001);
  EXPECT_EQ(m.disagreements, 1);
  EXPECT_NEAR(m.MeanNis(), 1.0, 1e-12);
  EXPECT_GT(m.disagree_time_s, 9.0);
  // The used readings' mean NIS is 1, but half the readings were beyond the gate: not consistent
  // (a sensor offset from t = 5 s gave "consistent" before the rejections counted).
  EXPECT_TRUE(m.GateRejectsTooMany());
  EXPECT_FALSE(m.Consistent());
}

// A wild reading now and then (1 in 200) leaves a sensor consistent; 3 in 200 do not.
TEST(ConsistencyTest, AFewRejectedReadingsAreAllowedNotAStreak) {
  for (const int wild : {1, 3}) {
    SensorMonitor m;
    for (int k = 0; k < 200; ++k) {
      const bool rejected = k % 50 == 7 && k / 50 < wild;
      // NIS alternating 0.5 and 1.5: a mean of 1, inside the bounds.
      m.Record(0.1 * k, rejected ? 400.0 : (k % 2 == 0 ? 0.5 : 1.5), !rejected, 1.0, 9.0, 3.0);
    }
    EXPECT_EQ(m.rejected, wild);
    EXPECT_EQ(m.GateRejectsTooMany(), wild == 3) << wild;
    EXPECT_EQ(m.Consistent(), wild == 1) << wild;
  }
}

}  // namespace
}  // namespace hotlap::observe
