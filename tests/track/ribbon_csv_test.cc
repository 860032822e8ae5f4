// WriteRibbonCsv on the shipped Darlington: one row per step up to the length, the documented
// columns and metadata; a missing folder is an InputError.

#include "hotlap/track/ribbon_csv.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/csv.h"
#include "test_util.h"

namespace hotlap::track {
namespace {

TEST(WriteRibbonCsv, WritesOneRowPerStepToTheLength) {
  test::TempDir dir;
  const TrackFile file = LoadTrackByName("darlington");
  const auto path = dir.path() / "ribbon.csv";
  WriteRibbonCsv(path, file, 50.0);
  const CsvTable csv = ReadCsv(path);
  ASSERT_EQ(csv.columns.size(), 13u);
  EXPECT_EQ(csv.columns.front(), "distance_m");
  EXPECT_EQ(csv.columns[9], "bank_deg");
  EXPECT_EQ(csv.columns.back(), "width_right_m");
  const std::vector<double>& s = csv.Column("distance_m");
  EXPECT_EQ(s.front(), 0.0);
  EXPECT_NEAR(s.back(), file.track.length_m(), 1e-9);
  EXPECT_LE(s[1] - s[0], 50.0);
  EXPECT_EQ(s.size(), static_cast<size_t>(std::ceil(file.track.length_m() / 50.0)) + 1);
  EXPECT_EQ(csv.metadata.front(), (std::pair<std::string, std::string>{"track", "darlington"}));
  EXPECT_EQ(csv.metadata[3], (std::pair<std::string, std::string>{"format", "segments"}));
  EXPECT_TRUE(test::Contains(
      test::InputErrorOf([&] { WriteRibbonCsv(dir.path() / "no" / "r.csv", file, 50.0); }),
      "r.csv"));
}

}  // namespace
}  // namespace hotlap::track
