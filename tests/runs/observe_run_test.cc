// The observer run `hotlap observe` makes: the sensor lag from the option, else the log's line,
// else the noise file; the hooks told of the start, every row and every warning; the estimates
// file one line a sample; a log refused before its first sample leaves no file behind; and the
// summary text and JSON of what was seen.

#include "hotlap/runs/observe_run.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/observe/observe_json.h"
#include "hotlap/runs/observe_text.h"
#include "test_util.h"

namespace hotlap::runs {
namespace {

namespace fs = std::filesystem;

TEST(ResolveSensorLag, TheOptionThenTheLogsLineThenTheNoiseFile) {
  observe::ObserverConfig config;
  config.path = "noise.yaml";
  config.sensor_lag = {0.1, 0.2, 0.3};
  const std::vector<std::pair<std::string, std::string>> none, line = {{"sensor_lag_s", "0.4"}};
  observe::ObserverConfig c = config;
  EXPECT_EQ(ResolveSensorLag(std::nullopt, none, "log.csv", c), "noise.yaml");
  EXPECT_EQ(c.sensor_lag.disc_temp, 0.2);
  EXPECT_EQ(ResolveSensorLag(std::nullopt, line, "log.csv", c), "the log's sensor_lag_s");
  EXPECT_EQ(c.sensor_lag.calliper_temp, 0.4);
  EXPECT_EQ(ResolveSensorLag(0.7, line, "log.csv", c), "--sensor-lag-s");
  EXPECT_EQ(c.sensor_lag.tread_temp, 0.7);
  EXPECT_EQ(test::InputErrorOf([&] {
              ResolveSensorLag(std::nullopt, {{"sensor_lag_s", "61"}}, "L", c);
            }),
            "L: '# sensor_lag_s: 61' is not a time constant in [0, 60] s");
}

TEST(ResolveTpmsLag, TheLogsTpmsLineThenTheNoiseFile) {
  observe::ObserverConfig config;
  config.path = "noise.yaml";
  // Without a car_models section there is no TPMS to lag.
  EXPECT_EQ(ResolveTpmsLag({{"tpms", "lag 3 s"}}, "log.csv", config), "");
  config.car_models = observe::CarModelsNoise{.tpms_lag_s = 2.0};
  observe::ObserverConfig c = config;
  EXPECT_EQ(ResolveTpmsLag({{"sensor_lag_s", "0.4"}}, "log.csv", c), "noise.yaml");
  EXPECT_EQ(c.car_models->tpms_lag_s, 2.0);
  const std::string synth_line = "pressure noise 2 kPa, gas temperature noise 0.5 C, lag 3.5 s";
  EXPECT_EQ(ResolveTpmsLag({{"tpms", synth_line}}, "log.csv", c), "the log's tpms line");
  EXPECT_EQ(c.car_models->tpms_lag_s, 3.5);
  for (const std::string bad :
       {"lag 0 s", "lag 61 s", "lag s", "pressure noise 2 kPa", "lag x s"}) {
    EXPECT_EQ(
        test::InputErrorOf([&] {
          ResolveTpmsLag({{"tpms", bad}}, "L", c);
        }),
        "L: '# tpms: " + bad + "' does not end in 'lag <s> s' with a time constant in (0, 60] s")
        << bad;
  }
}

TEST(RunObserve, HooksSeeEveryRowAndTheFileHasOneLineASample) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  test::TempDir dir;
  ObserveRunOptions o;
  o.telemetry = test::SourcePath("data/telemetry/darlington_example.csv").string();
  o.out = (dir.path() / "est.csv").string();
  int started = 0, rows = 0, warnings = 0;
  size_t columns = 0;
  ObserveHooks hooks;
  hooks.started = [&](const std::vector<std::string>& c) {
    ++started;
    columns = c.size();
    EXPECT_TRUE(fs::exists(o.out));  // opened, header written
  };
  hooks.row = [&](const std::vector<double>& row) {
    ++rows;
    EXPECT_EQ(row.size(), columns);
  };
  hooks.warning = [&](const observe::DisagreementWarning&) { ++warnings; };
  const ObserveRun run = RunObserve(car, o, hooks);
  EXPECT_EQ(started, 1);
  EXPECT_EQ(rows, run.observer->samples());
  EXPECT_EQ(rows, 1451);
  EXPECT_EQ(warnings, static_cast<int>(run.summary.warnings.size()));
  EXPECT_NEAR(run.summary.duration_s, 29.0, 1e-9);
  const std::string csv = test::ReadTextFile(o.out);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), rows + 1);

  const nlohmann::json json = observe::ObserveJson(*run.observer, car, run.summary);
  EXPECT_EQ(json["samples"], 1451);
  EXPECT_EQ(json["out"], o.out);
  EXPECT_EQ(json["consistent"], observe::AllConsistent(*run.observer));
  EXPECT_EQ(json["corners"].size(), 4u);
  EXPECT_FALSE(json["corners"]["fl"].contains("p5_scale"));
  const std::string text = ObserveRunText(run, car);
  EXPECT_TRUE(test::Contains(text, "(1451 samples, 29.00 s of log) with car 'gen7'"));
  EXPECT_TRUE(test::Contains(text, "disagreement warning(s); wrote " + o.out));
}

TEST(RunObserve, ALogWithoutDataLeavesNoFileBehind) {
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  test::TempDir dir;
  ObserveRunOptions o;
  o.telemetry = test::WriteTextFile(dir.path() / "empty.csv", "time_s,speed_mps\n").string();
  o.out = (dir.path() / "est.csv").string();
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { RunObserve(car, o, {}); }),
                             "no data lines after the header"));
  EXPECT_FALSE(fs::exists(o.out));
  o.telemetry = "-";
  o.lap = 2;
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] { RunObserve(car, o, {}); }),
                             "--lap and --channel-map need a log file"));
  EXPECT_FALSE(fs::exists(o.out));
}

}  // namespace
}  // namespace hotlap::runs
