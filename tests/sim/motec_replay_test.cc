// A MoTeC i2 CSV export replays to the same result as the hotlap CSV of the same numbers
// (tests/data/motec/make_fixture.py writes both).

#include <filesystem>

#include <gtest/gtest.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/telemetry.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

ColumnSet Replay(const Telemetry& log) {
  const vehicle::Car car = vehicle::LoadCar(ResolveCarFile("gen7"));
  const InitialTemperatureOverrides overrides;
  const ReplayResult result = RunReplay(car, ReplayInputsFromTelemetry(log, overrides),
                                        InitialStateFor(log, car, overrides), ReplayOptions{});
  return ReplayResultColumns(result, false);
}

TEST(MotecReplayTest, SameResultAsTheEquivalentHotlapCsv) {
  const ColumnSet motec =
      Replay(Telemetry::Read(test::SourcePath("tests/data/motec/darlington_i2.csv")));
  const ColumnSet csv =
      Replay(Telemetry::Read(test::SourcePath("tests/data/motec/darlington_i2_equivalent.csv")));
  ASSERT_EQ(motec.names, csv.names);
  ASSERT_EQ(motec.values.size(), csv.values.size());
  for (size_t c = 0; c < csv.values.size(); ++c) {
    EXPECT_EQ(motec.values[c], csv.values[c]) << csv.names[c];
  }
  // The starting disc temperature came from the logged Brake Temp channels (350 degC).
  EXPECT_DOUBLE_EQ(csv.values[5].front(), 350.0) << csv.names[5];
}

TEST(MotecReplayTest, OneLapReplays) {
  const Telemetry lap =
      Telemetry::Read(test::SourcePath("tests/data/motec/darlington_i2.csv"), "time", {.lap = 2});
  const ColumnSet result = Replay(lap);
  EXPECT_EQ(result.values[0].size(), 97u);
  EXPECT_NEAR(result.values[0].front(), 9.7, 1e-12);
}

}  // namespace
}  // namespace hotlap::sim
