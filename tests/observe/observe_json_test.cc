// ObserveJson: the summary `hotlap observe --json` writes, from an observer run over part of the
// example log: the run's fields as given, four corners with their bands (and p5's only when it is
// estimated), the warnings in the order raised, a non-finite
// number as null.

#include "hotlap/observe/observe_json.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "hotlap/observe/observer_config.h"
#include "hotlap/observe/sample_source.h"
#include "test_util.h"

namespace hotlap::observe {
namespace {

CarObserver ObserveSome(const vehicle::Car& car, bool p5_scale, int samples) {
  ObserverConfig config = LoadObserverConfig(DefaultObserverConfigPath());
  config.p5_scale.estimate = p5_scale;
  CarObserver observer(car, config);
  SampleSource source(test::SourcePath("data/telemetry/darlington_example.csv").string(), {}, {});
  for (int i = 0; i < samples; ++i) observer.Step(*source.Next());
  return observer;
}

TEST(ObserveJson, TheRunTheCornersAndTheWarnings) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const CarObserver observer = ObserveSome(car, false, 200);
  ObserveSummary s;
  s.telemetry = "log.csv";
  s.out = "-";
  s.lap = 2;
  s.sensor_lag_from = "--sensor-lag-s";
  s.duration_s = std::numeric_limits<double>::quiet_NaN();
  s.warnings.push_back({.corner = Corner::kRearLeft,
                        .sensor = Sensor::kDisc,
                        .since_s = 1.0,
                        .time_s = 2.5,
                        .nis_average = 40.0,
                        .message = "m"});
  const nlohmann::json j = ObserveJson(observer, car, s);
  EXPECT_EQ(j["command"], "observe");
  EXPECT_EQ(j["telemetry"], "log.csv");
  EXPECT_EQ(j["lap"], 2);
  EXPECT_EQ(j["samples"], 200);
  EXPECT_TRUE(j["duration_s"].is_null());
  EXPECT_EQ(j["sensor_lag_from"], "--sensor-lag-s");
  ASSERT_EQ(j["corners"].size(), 4u);
  EXPECT_FALSE(j["corners"]["rr"].contains("p5_scale"));
  EXPECT_EQ(j["corners"]["fl"]["sensors"], SensorsJson(observer, Corner::kFrontLeft));
  EXPECT_EQ(j["consistent"], AllConsistent(observer));
  ASSERT_EQ(j["disagreements"].size(), 1u);
  EXPECT_EQ(j["disagreements"][0]["corner"], "rl");
  EXPECT_EQ(j["disagreements"][0]["sensor"], "disc_temp");
  EXPECT_EQ(j["disagreements"][0]["time_s"], 2.5);
}

TEST(ObserveJson, P5ScaleOnlyWhenEstimated) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  const nlohmann::json j = ObserveJson(ObserveSome(car, true, 50), car, {});
  EXPECT_TRUE(j["corners"]["fl"].contains("p5_scale"));
  EXPECT_TRUE(j["corners"]["fl"].contains("p5_scale_sd"));
  EXPECT_TRUE(j["lap"].is_null());
}

}  // namespace
}  // namespace hotlap::observe
