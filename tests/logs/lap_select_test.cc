#include "hotlap/logs/lap_select.h"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/logs/telemetry.h"
#include "test_util.h"

namespace hotlap {
namespace {

using test::Contains;
using test::InputErrorOf;

CsvTable LapTable(const std::vector<double>& laps) {
  CsvTable table;
  table.path = "log.csv";
  table.columns = {"time_s", "lap"};
  std::vector<double> time;
  for (size_t i = 0; i < laps.size(); ++i) {
    time.push_back(0.1 * static_cast<double>(i));
    table.line_numbers.push_back(static_cast<int>(i) + 2);
  }
  table.values = {time, laps};
  return table;
}

TEST(SelectLapTest, KeepsOneLapsRowsAndTheirLines) {
  CsvTable table = LapTable({1, 1, 2, 2, 2, 3});
  SelectLap(table, 2);
  ASSERT_EQ(table.RowCount(), 3u);
  EXPECT_DOUBLE_EQ(table.values[0][0], 0.2);
  EXPECT_EQ(table.line_numbers, (std::vector<int>{4, 5, 6}));
}

TEST(SelectLapTest, MissingLapListsTheLapsThereAre) {
  CsvTable contiguous = LapTable({1, 2, 3});
  EXPECT_TRUE(Contains(InputErrorOf([&] { SelectLap(contiguous, 7); }),
                       "log.csv: lap 7: no such lap; the log has laps 1 to 3"));
  CsvTable gaps = LapTable({1, 4, 9});
  EXPECT_TRUE(Contains(InputErrorOf([&] { SelectLap(gaps, 2); }), "the log has laps 1, 4, 9"));
  CsvTable one = LapTable({5, 5});
  EXPECT_TRUE(Contains(InputErrorOf([&] { SelectLap(one, 2); }), "the log has lap 5"));
}

// Lap numbers far apart, or beyond what a lap number can be, once overflowed the contiguity test
// (UBSan: signed overflow; the telemetry_csv fuzzer's finding, docs/reliability.md). Numbers
// beyond 1e9, NaN and infinities are not laps; the rest are listed exactly.
TEST(SelectLapTest, LapNumbersFarApartOrAbsurdAreListedOrLeftOut) {
  const double inf = std::numeric_limits<double>::infinity();
  CsvTable far = LapTable({-999999999.0, 5.0, 999999999.0, 5.0e10, -inf, NAN, 1e300});
  EXPECT_TRUE(Contains(InputErrorOf([&] { SelectLap(far, 2); }),
                       "the log has laps -999999999, 5, 999999999"));
  CsvTable none = LapTable({5.0e10, inf, NAN});
  EXPECT_TRUE(Contains(InputErrorOf([&] { SelectLap(none, 2); }), "the log has none"));
}

// What fuzz/telemetry_csv_fuzz found (tests/data/fuzz_regressions/telemetry_csv): each file, read
// for one lap as the fuzzer reads it, reaches the lap selection and is refused with an InputError
// naming it.
TEST(SelectLapTest, FuzzRegressionsAreInputErrors) {
  for (const auto& file : test::FuzzRegressions("telemetry_csv")) {
    TelemetryReadOptions options;
    options.lap = 2;
    const std::string message =
        InputErrorOf([&] { (void)Telemetry::Read(file, "distance", options); });
    EXPECT_TRUE(Contains(message, file.string())) << message;
    EXPECT_TRUE(Contains(message, "lap 2: no such lap")) << message;  // reached the selection
  }
}

}  // namespace
}  // namespace hotlap
