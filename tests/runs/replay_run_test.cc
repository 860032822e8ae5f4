// The replay run both `hotlap replay` and `hotlap.replay` make: a step that is not positive named
// in the caller's spelling, a starting temperature in degC taken where the log has none, the
// channels written with the run's metadata (overrides only when there are some), and the text
// the command prints.

#include "hotlap/runs/replay_run.h"

#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::runs {
namespace {

class ReplayRunTest : public ::testing::Test {
 protected:
  const Telemetry log_ = Telemetry::Read(test::SourcePath("data/telemetry/darlington_example.csv"));
  const vehicle::Car car_ = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
};

TEST_F(ReplayRunTest, AStepThatIsNotPositiveIsNamedInTheCallersSpelling) {
  EXPECT_EQ(
      test::InputErrorOf([&] { RunReplay(car_, log_, {.max_step_s = 0.0}, NameStyle::kPython); }),
      "max_step_s 0 must be > 0");
  EXPECT_EQ(test::InputErrorOf(
                [&] { RunReplay(car_, log_, {.max_step_s = -1.0}, NameStyle::kCommandLine); }),
            "--max-step-s -1 must be > 0");
}

TEST_F(ReplayRunTest, HeatFlowsAddColumnsAndTheChannelsCarryTheRunsMetadata) {
  const ReplayRun plain = RunReplay(car_, log_, {}, NameStyle::kPython);
  const ReplayRun flows = RunReplay(car_, log_, {.heat_flows = true}, NameStyle::kPython);
  EXPECT_EQ(flows.columns.names.size(), plain.columns.names.size() + 4 * 7);
  EXPECT_EQ(plain.result.time.size(), log_.size());
  test::TempDir dir;
  WriteReplayChannels(dir.path() / "r.csv", plain, log_, car_);
  const std::string csv = test::ReadTextFile(dir.path() / "r.csv");
  EXPECT_TRUE(test::Contains(csv, "# telemetry: " + log_.path().string()));
  EXPECT_FALSE(test::Contains(csv, "# overrides:"));
  const vehicle::Car heavy = vehicle::LoadCar(test::Gen7Dir() / "car.yaml",
                                              vehicle::ParseCarOverrides({"chassis.mass_kg=1600"}));
  WriteReplayChannels(dir.path() / "h.csv", plain, log_, heavy);
  EXPECT_TRUE(test::Contains(test::ReadTextFile(dir.path() / "h.csv"),
                             "# overrides: chassis.mass_kg=1600"));
  const std::string text = ReplayRunText(plain, log_, car_);
  EXPECT_TRUE(test::Contains(text, "(1451 samples, 29.00 s of log) with car 'gen7'"));
  EXPECT_TRUE(test::Contains(text, "tread degC pk/mean/end"));
}

}  // namespace
}  // namespace hotlap::runs
