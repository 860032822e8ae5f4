// The QSS lap run both `hotlap lap` and `hotlap.qss_lap` make: options checked and named in the
// caller's spelling, the line chosen as asked, the starting temperatures given in degC taken in
// kelvin with the car's elsewhere, the laps run and written (lap.csv with its metadata, lap.html).

#include "hotlap/runs/lap_run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/runs/lap_text.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::runs {
namespace {

namespace fs = std::filesystem;

class LapRunTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    car_ = new vehicle::Car(vehicle::LoadCar(test::Gen7Dir() / "car.yaml",
                                             vehicle::ParseCarOverrides({"chassis.mass_kg=1600"})));
    track_ = new track::Track(track::LoadTrack("darlington"));
  }
  static void TearDownTestSuite() {
    delete track_;
    delete car_;
  }
  static vehicle::Car* car_;
  static track::Track* track_;
};

vehicle::Car* LapRunTest::car_ = nullptr;
track::Track* LapRunTest::track_ = nullptr;

TEST_F(LapRunTest, BadOptionsAreNamedInTheCallersSpelling) {
  LapRunOptions o;
  o.laps = 0;
  EXPECT_EQ(test::InputErrorOf([&] { PlanLap(*car_, *track_, o, NameStyle::kCommandLine); }),
            "--laps 0 must be in [1, 1000]");
  EXPECT_EQ(test::InputErrorOf([&] { PlanLap(*car_, *track_, o, NameStyle::kPython); }),
            "laps 0 must be in [1, 1000]");
  o = {};
  o.step_m = 0.0;
  EXPECT_EQ(test::InputErrorOf([&] { PlanLap(*car_, *track_, o, NameStyle::kPython); }),
            "step_m 0 must be > 0");
  o = {};
  o.line = "centre";
  o.caution_laps = "3";
  EXPECT_TRUE(test::Contains(
      test::InputErrorOf([&] { PlanLap(*car_, *track_, o, NameStyle::kCommandLine); }),
      "--caution-laps"));
}

TEST_F(LapRunTest, StartingTemperaturesInCelsiusReplaceTheCarsOnlyWhereGiven) {
  LapRunOptions o;
  o.line = "centre";
  o.step_m = 5.0;
  o.tread_C = 80.0;
  const LapPlan plan = PlanLap(*car_, *track_, o, NameStyle::kPython);
  for (const auto& tyre : plan.options.initial.tyres) {
    EXPECT_DOUBLE_EQ(tyre.tread_temp, 353.15);
  }
  const LapPlan car_start =
      PlanLap(*car_, *track_, {.line = "centre", .step_m = 5.0}, NameStyle::kPython);
  EXPECT_NE(car_start.options.initial.tyres[0].tread_temp, 353.15);
  EXPECT_EQ(plan.options.initial.tyres[0].carcass_temp,
            car_start.options.initial.tyres[0].carcass_temp);
}

TEST_F(LapRunTest, TheLineIsTheOneAsked) {
  const auto centre = SampleLapRoad(*track_, "centre", 5.0, 1.5);
  const auto racing = SampleLapRoad(*track_, "min-curvature", 5.0, 1.5);
  ASSERT_FALSE(centre.empty());
  ASSERT_FALSE(racing.empty());
  double largest_offset = 0.0;
  for (const auto& p : racing) largest_offset = std::max(largest_offset, std::abs(p.offset));
  for (const auto& p : centre) EXPECT_EQ(p.offset, 0.0);
  EXPECT_GT(largest_offset, 1.0);  // the racing line leaves the centre line
}

TEST_F(LapRunTest, RunWritesTheChannelsWithTheOverridesAndTheReport) {
  LapRunOptions o;
  o.line = "centre";
  o.step_m = 5.0;
  const LapPlan plan = PlanLap(*car_, *track_, o, NameStyle::kCommandLine);
  const LapRun run = RunLap(*car_, *track_, plan);
  ASSERT_EQ(run.stint.laps.size(), 1u);
  EXPECT_GT(run.stint.laps[0].lap_time_s, 20.0);
  test::TempDir dir;
  const LapFiles files = WriteLapFiles(dir.path() / "lap", run, o, *car_, *track_);
  EXPECT_EQ(files.csv, dir.path() / "lap" / "lap.csv");
  const std::string csv = test::ReadTextFile(files.csv);
  EXPECT_TRUE(test::Contains(csv, "# laps: 1"));
  EXPECT_TRUE(test::Contains(csv, "# overrides: chassis.mass_kg=1600"));
  EXPECT_TRUE(fs::exists(files.html));
  const std::string text = LapRunText(run, *car_, 1);
  EXPECT_TRUE(test::Contains(text, "braking zones:"));
  EXPECT_TRUE(test::Contains(text, "last lap means and energy audit:"));
  EXPECT_TRUE(test::Contains(LapRunHeader(*car_, *track_, o, plan), "centre line, "));
}

}  // namespace
}  // namespace hotlap::runs
