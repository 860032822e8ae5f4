// What `hotlap abs` writes of an event, on a hand-made one: the channels CSV (header, units,
// metadata, an empty ABS state without ABS) and the summary rows.

#include "hotlap/abs/abs_output.h"

#include <cmath>

#include <gtest/gtest.h>

#include "abs/abs_example.h"
#include "hotlap/common/csv.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

TEST(WriteAbsCsv, WritesTheChannelsInTheirUnits) {
  test::TempDir dir;
  const auto path = dir.path() / "abs.csv";
  AbsEvent event = testing::MakeExampleAbsEvent();
  AbsRunResult run = testing::MakeExampleAbsRun();
  run.history.state[0] = -1;  // no controller state at this sample
  WriteAbsCsv(path, testing::MakeExampleAbsConfig(), event, run);
  const CsvTable csv = ReadCsv(path);
  ASSERT_EQ(csv.columns.size(), 17u);
  EXPECT_EQ(csv.columns.front(), "time_s");
  EXPECT_EQ(csv.columns.back(), "calliper_temp_C");
  EXPECT_EQ(csv.Column("pressure_MPa"), (std::vector<double>{0.0, 3.0, 2.5}));
  EXPECT_EQ(csv.Column("wheel_speed_mps"), (std::vector<double>{20.0, 15.0, 17.0}));
  EXPECT_EQ(csv.Column("wheel_locked"), (std::vector<double>{0.0, 0.0, 1.0}));
  EXPECT_TRUE(std::isnan(csv.Column("abs_state")[0]));
  EXPECT_EQ(csv.Column("abs_state")[1], 4.0);
  EXPECT_NEAR(csv.Column("disc_temp_C")[2], 103.0, 1e-9);
  EXPECT_TRUE(test::Contains(test::ReadTextFile(path), "# config: abs/example.yaml\n"));
  EXPECT_TRUE(test::Contains(test::ReadTextFile(path), "# abs: on\n"));
}

TEST(WriteAbsCsv, AMissingFolderIsAnInputError) {
  test::TempDir dir;
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] {
                               WriteAbsCsv(
                                   dir.path() / "no" / "abs.csv", testing::MakeExampleAbsConfig(),
                                   testing::MakeExampleAbsEvent(), testing::MakeExampleAbsRun());
                             }),
                             "abs.csv"));
}

TEST(AbsSummaryRows, SayTheFiguresInWords) {
  const auto rows = AbsSummaryRows(testing::MakeExampleAbsMetrics(), true);
  ASSERT_EQ(rows.size(), 9u);
  EXPECT_EQ(rows[0],
            (std::pair<std::string, std::string>{"stopped", "yes, at 1.500 s after 15.123 m"}));
  EXPECT_EQ(rows[1].second, "3 (2.50 per second)");
  EXPECT_EQ(rows[2].second, "-");  // no window after the first cycle
  EXPECT_EQ(rows[6].second, "103.0 / 60.5 \u00b0C");
  EXPECT_EQ(rows[8].second, "900.0 + 90.0 + 10.0 J (closure error 1.23e-05)");
  EXPECT_EQ(AbsSummaryRows(testing::MakeExampleAbsMetrics(), false)[1].second, "no ABS");
}

}  // namespace
}  // namespace hotlap::sim
