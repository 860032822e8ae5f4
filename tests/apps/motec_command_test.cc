// A MoTeC i2 CSV export through the command line: `hotlap replay --telemetry EXPORT.csv --lap N`
// and `--channel-map FILE`; a lap that is not there is exit 2 naming the laps there are.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "apps/run_hotlap.h"
#include "hotlap/common/csv.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;

const fs::path kMotecI2Csv = hotlap::test::SourcePath("tests/data/motec/darlington_i2.csv");

TEST(MotecCommandTest, ReplaysOneLapOfAMotecExport) {
  const hotlap::test::TempDir tmp;
  const fs::path out = tmp.path() / "lap2.csv";
  const auto r = hotlap::test::RunHotlap(
      "replay --telemetry " + kMotecI2Csv.string() + " --lap 2 --out " + out.string(), tmp.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out, "MoTeC channels not mapped (kept): G Force Lat, Engine RPM"));
  const hotlap::CsvTable table = hotlap::ReadCsv(out);
  ASSERT_EQ(table.RowCount(), 97u);
  EXPECT_NEAR(table.Column("time_s").front(), 9.7, 1e-12);
  EXPECT_NEAR(table.Column("time_s").back(), 19.3, 1e-12);
  bool venue = false;
  for (const auto& [k, v] : table.metadata) venue = venue || (k == "Venue" && v == "Darlington");
  EXPECT_TRUE(venue);
}

TEST(MotecCommandTest, ALapThatIsNotThereIsExit2NamingTheLaps) {
  const hotlap::test::TempDir tmp;
  const fs::path out = tmp.path() / "out.csv";
  const auto r = hotlap::test::RunHotlap(
      "replay --telemetry " + kMotecI2Csv.string() + " --lap 7 --out " + out.string(), tmp.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(Contains(r.err, "lap 7: no such lap; the log has laps 1 to 3"));
  EXPECT_FALSE(fs::exists(out));
}

TEST(MotecCommandTest, AChannelMapWithoutTheLoadsNamesTheMissingChannel) {
  const hotlap::test::TempDir tmp;
  const fs::path map =
      hotlap::test::WriteTextFile(tmp.path() / "map.yaml", "channels:\n  Ground Speed: speed\n");
  const fs::path out = tmp.path() / "out.csv";
  const auto r =
      hotlap::test::RunHotlap("replay --telemetry " + kMotecI2Csv.string() + " --channel-map " +
                                  map.string() + " --out " + out.string(),
                              tmp.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(Contains(r.err, "missing column")) << r.err;
  EXPECT_TRUE(Contains(r.err, "map.yaml")) << r.err;
}

}  // namespace
