// The files of the FE tyre's steps on hand-made results: a step's history CSV (header, omega R
// from the loaded radius, energies) and the footprint pressure map as CSV and SVG.

#include "hotlap/fe/step_output.h"

#include <gtest/gtest.h>

#include "hotlap/common/csv.h"
#include "test_util.h"

namespace hotlap::fe {
namespace {

TEST(WriteFeHistoryCsv, WritesOneRowPerHistoryRow) {
  test::TempDir dir;
  FeConfig config;
  config.file = "fe/example.yaml";
  HistoryRow a, b;
  b.time_s = 0.01;
  b.spin_rad_per_s = 20.0;
  b.road_fz_N = 5000.0;
  b.energies.kinetic = 3.0;
  b.energies.external_work = 1.0;
  const auto path = dir.path() / "roll_history.csv";
  WriteFeHistoryCsv(path, "roll", config, {a, b}, 0.4);
  const CsvTable csv = ReadCsv(path);
  ASSERT_EQ(csv.columns.size(), 19u);
  EXPECT_EQ(csv.columns[5], "omega_R_mps");
  EXPECT_EQ(csv.columns.back(), "balance_error_J");
  EXPECT_EQ(csv.RowCount(), 2u);
  EXPECT_EQ(csv.Column("omega_R_mps")[1], 8.0);
  EXPECT_EQ(csv.Column("road_fz_N")[1], 5000.0);
  EXPECT_EQ(csv.Column("balance_error_J")[1], 2.0);
  EXPECT_EQ(csv.metadata, (std::vector<std::pair<std::string, std::string>>{
                              {"config", "fe/example.yaml"}, {"step", "roll"}}));
}

TEST(WriteFootprintPressure, WritesTheMapAsCsvAndSvg) {
  test::TempDir dir;
  FeConfig config;
  FootprintResult fp;
  fp.peak_pressure_Pa = 4e5;
  fp.contact = {{.x_m = 0.0, .y_m = 0.0, .force_N = 40.0, .pressure_Pa = 4e5},
                {.x_m = 0.01, .y_m = -0.02, .force_N = 20.0, .pressure_Pa = 2e5}};
  WriteFootprintPressure(dir.path(), config, fp);
  const CsvTable csv = ReadCsv(dir.path() / "footprint_pressure.csv");
  EXPECT_EQ(csv.columns, (std::vector<std::string>{"x_m", "y_m", "force_N", "pressure_Pa"}));
  EXPECT_EQ(csv.Column("pressure_Pa"), (std::vector<double>{4e5, 2e5}));
  const std::string svg = test::ReadTextFile(dir.path() / "footprint_pressure.svg");
  EXPECT_TRUE(test::Contains(svg, "contact pressure, peak 400 kPa"));
  EXPECT_TRUE(test::Contains(svg, "fill=\"rgb(255,0,0)\""));    // the peak
  EXPECT_TRUE(test::Contains(svg, "fill=\"rgb(127,0,127)\""));  // half of it
  EXPECT_TRUE(test::Contains(svg, "</svg>\n"));
}

TEST(WriteFootprintPressure, AMissingFolderIsAnInputError) {
  test::TempDir dir;
  EXPECT_TRUE(test::Contains(
      test::InputErrorOf([&] { WriteFootprintPressure(dir.path() / "no", FeConfig{}, {}); }),
      "footprint_pressure.csv"));
}

}  // namespace
}  // namespace hotlap::fe
