// The stint run's options both `hotlap stint` and `hotlap.stint` give: threads and disc limits out
// of range named in the caller's spelling, the library's options made from the run's (the fuel
// use only where given), and a checkpoint key that changes with the car's files and overrides.

#include "hotlap/runs/stint_run.h"

#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::runs {
namespace {

namespace fs = std::filesystem;

TEST(StintRun, OutOfRangeOptionsAreNamedInTheCallersSpelling) {
  EXPECT_EQ(test::InputErrorOf([] { CheckThreads(300, NameStyle::kPython); }),
            "threads: 300 is not 0 to 256 (0: one per core)");
  EXPECT_EQ(test::InputErrorOf([] { CheckThreads(-1, NameStyle::kCommandLine); }),
            "--threads: -1 is not 0 to 256 (0: one per core)");
  StintRunOptions o;
  o.disc_limit_C = 1600.0;
  EXPECT_EQ(test::InputErrorOf([&] { MakeStintOptions(o, NameStyle::kCommandLine); }),
            "--disc-limit-C: 1600 degC is not in (0, 1500)");
  EXPECT_EQ(test::InputErrorOf([&] { MakeStintOptions(o, NameStyle::kPython); }),
            "disc_limit_C: 1600 degC is not in (0, 1500)");
}

TEST(StintRun, TheLibrarysOptionsFromTheRuns) {
  StintRunOptions o;
  o.laps = 4;
  o.wear_scale = 30.0;
  o.fuel_kg = 12.0;
  o.disc_limit_C = 500.0;
  o.checkpoint_dir = "ck";
  o.checkpoint_every = 7;
  const ocp::StintOptions defaults;
  const ocp::StintOptions s = MakeStintOptions(o, NameStyle::kPython);
  EXPECT_EQ(s.laps, 4);
  EXPECT_EQ(s.wear_scale, 30.0);
  EXPECT_EQ(s.fuel_kg, 12.0);
  EXPECT_EQ(s.bsfc_kg_per_J, defaults.bsfc_kg_per_J);  // not given: the library's
  ASSERT_TRUE(s.lap.front_disc_limit.has_value());
  EXPECT_DOUBLE_EQ(*s.lap.front_disc_limit, 773.15);
  EXPECT_EQ(s.checkpoint_dir, fs::path("ck"));
  EXPECT_EQ(s.checkpoint_every, 7);
  o.bsfc_g_per_kWh = 250.0;
  EXPECT_DOUBLE_EQ(MakeStintOptions(o, NameStyle::kPython).bsfc_kg_per_J, 0.25 / 3.6e6);
}

TEST(StintRun, TheCheckpointKeyFollowsTheFilesAndTheOverrides) {
  test::TempDir dir;
  const fs::path car = test::WriteTextFile(dir.path() / "car/car.yaml", "name: a\n");
  test::WriteTextFile(dir.path() / "car/tyres/t.yaml", "x: 1\n");
  const fs::path track = test::WriteTextFile(dir.path() / "track.yaml", "name: t\n");
  const std::string key = StintCheckpointKey(car, track, {});
  EXPECT_TRUE(test::Contains(key, " tyres/t.yaml "));
  EXPECT_TRUE(test::Contains(key, " track.yaml "));
  EXPECT_NE(StintCheckpointKey(car, track, {"chassis.mass_kg=1600"}), key);
  test::WriteTextFile(dir.path() / "car/tyres/t.yaml", "x: 2\n");
  EXPECT_NE(StintCheckpointKey(car, track, {}), key);
}

}  // namespace
}  // namespace hotlap::runs
