#include "hotlap/sim/synth_json.h"

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

// A two-sample log whose truth has known peaks and wear at each corner.
SynthLog ExampleLog() {
  SynthLog log;
  log.inputs.time = {0.0, 0.02, 0.04};
  log.lap_time_s = 31.25;
  for (int i = 0; i < 4; ++i) {
    CornerHistory& h = log.truth.corners[i];
    h.tread_temp = {CelsiusToKelvin(80.0), CelsiusToKelvin(90.0 + i), CelsiusToKelvin(85.0)};
    h.disc_temp = {CelsiusToKelvin(400.0 + 10 * i), CelsiusToKelvin(300.0), CelsiusToKelvin(350.0)};
    h.wear = {0.0, 0.001 * (i + 1), 0.002 * (i + 1)};
  }
  return log;
}

TEST(SynthJsonTest, CornersArePeaksOfTheTruthAndWearAtTheEnd) {
  const auto corners = SummarizeSynthCorners(ExampleLog());
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(corners[i].peak_tread_temp_K, CelsiusToKelvin(90.0 + i));
    EXPECT_DOUBLE_EQ(corners[i].peak_disc_temp_K, CelsiusToKelvin(400.0 + 10 * i));
    EXPECT_DOUBLE_EQ(corners[i].wear_mm, 0.002 * (i + 1));
  }
}

TEST(SynthJsonTest, SummaryHasTheOptionsAndTheCorners) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  SynthOptions o;
  o.laps = 2;
  o.rate_hz = 50.0;
  o.temp_noise_K = 0.3;
  o.sensor_lag_s = 0.1;
  o.seed = 7;
  nlohmann::json j = SynthJson(ExampleLog(), o, car, {"darlington", "p.yaml", "log.csv", ""});
  EXPECT_EQ(j["command"], "synth");
  EXPECT_EQ(j["car"], car.name);
  EXPECT_EQ(j["track"], "darlington");
  EXPECT_EQ(j["params"], "p.yaml");
  EXPECT_EQ(j["out"], "log.csv");
  EXPECT_EQ(j["laps"], 2);
  EXPECT_EQ(j["samples"], 3);
  EXPECT_DOUBLE_EQ(j["duration_s"].get<double>(), 0.04);
  EXPECT_DOUBLE_EQ(j["lap_time_s"].get<double>(), 31.25);
  EXPECT_DOUBLE_EQ(j["noise_C"].get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(j["lag_s"].get<double>(), 0.1);
  EXPECT_EQ(j["seed"], 7);
  EXPECT_DOUBLE_EQ(j["corners"]["rr"]["peak_tread_temp_C"].get<double>(), 93.0);
  EXPECT_DOUBLE_EQ(j["corners"]["fr"]["peak_disc_temp_C"].get<double>(), 410.0);
  EXPECT_DOUBLE_EQ(j["corners"]["rl"]["wear_mm"].get<double>(), 0.006);
  EXPECT_FALSE(j.contains("process_noise"));
  o.process_noise = SynthProcessNoise{0.01, 0.001, 1e-9, 0.1, 0.01};
  j = SynthJson(ExampleLog(), o, car, {"darlington", "", "log.csv", "noise.yaml"});
  EXPECT_EQ(j["process_noise"]["file"], "noise.yaml");
  EXPECT_DOUBLE_EQ(j["process_noise"]["tread_temp_K2_per_s"].get<double>(), 0.01);
  EXPECT_DOUBLE_EQ(j["process_noise"]["disc_temp_K2_per_s"].get<double>(), 0.1);
}

}  // namespace
}  // namespace hotlap::sim
