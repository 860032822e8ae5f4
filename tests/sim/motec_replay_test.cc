// A MoTeC i2 CSV export replays to the same result as the hotlap CSV of the same numbers
// (tests/data/motec/make_fixture.py writes both); so does the .ld log of them, within the
// precision the .ld stores them at; one lap of each (beacons, .ldx) replays too.

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "hotlap/common/data_path.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/vehicle/car.h"
#include "motec_ld_fixture.h"
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

TEST(MotecLdReplayTest, SameResultAsTheEquivalentHotlapCsv) {
  const test::TempDir tmp;
  const Telemetry ld_log = Telemetry::Read(test::WriteDarlingtonLd(tmp.path()));
  const Telemetry csv_log =
      Telemetry::Read(test::SourcePath("tests/data/motec/darlington_i2_equivalent.csv"));
  ASSERT_EQ(ld_log.size(), csv_log.size());
  const ColumnSet ld = Replay(ld_log);
  const ColumnSet csv = Replay(csv_log);
  ASSERT_EQ(ld.names, csv.names);
  ASSERT_EQ(ld.values.size(), csv.values.size());
  // The forces are float32 (7 digits): temperatures agree to well under a millidegree, wear and
  // the rest to 1e-6 of their range.
  for (size_t c = 0; c < csv.values.size(); ++c) {
    ASSERT_EQ(ld.values[c].size(), csv.values[c].size()) << csv.names[c];
    double range = 0.0;
    for (double v : csv.values[c]) range = std::max(range, std::abs(v));
    for (size_t i = 0; i < csv.values[c].size(); ++i) {
      ASSERT_NEAR(ld.values[c][i], csv.values[c][i], 1e-6 * range + 1e-12)
          << csv.names[c] << " row " << i;
    }
  }
  // Not trivially equal: the .ld's forces are float32.
  EXPECT_NE(ld_log.Channel("fy", Corner::kFrontLeft), csv_log.Channel("fy", Corner::kFrontLeft));
}

TEST(MotecLdReplayTest, OneLapFromTheLdxReplays) {
  const test::TempDir tmp;
  const Telemetry lap = Telemetry::Read(test::WriteDarlingtonLd(tmp.path()), "time", {.lap = 2});
  const ColumnSet result = Replay(lap);
  // As the i2 export's lap 2: 9.7 s to 19.3 s, 97 samples.
  EXPECT_EQ(result.values[0].size(), 97u);
  EXPECT_NEAR(result.values[0].front(), 9.7, 1e-12);
}

}  // namespace
}  // namespace hotlap::sim
