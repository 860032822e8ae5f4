// The files of an optimal-lap run on hand-made laps: a lap's CSV (channels and metadata), the
// single run's and the comparison's files and page; a missing folder is an InputError.

#include "hotlap/ocp/optimal_run_output.h"

#include <gtest/gtest.h>

#include "hotlap/common/csv.h"
#include "hotlap/track/track_io.h"
#include "ocp/solved_lap_example.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

namespace fs = std::filesystem;

vehicle::Car ExampleCar() {
  vehicle::Car car;
  car.name = "gen7";
  car.path = "cars/gen7/car.yaml";
  return car;
}

TEST(WriteSolvedLapCsv, WritesTheChannelsAndTheLimit) {
  test::TempDir dir;
  const track::Track track = track::LoadTrack("darlington");
  const auto path = dir.path() / "lap.csv";
  WriteSolvedLapCsv(path, testing::MakeExampleSolvedLap("x", 30.0, 500.0), track, ExampleCar());
  const CsvTable csv = ReadCsv(path);
  EXPECT_EQ(csv.columns[0], "distance_m");
  EXPECT_EQ(csv.Column("speed_mps"), (std::vector<double>{70.0, 60.0, 70.0}));
  EXPECT_NEAR(csv.Column("disc_temp_fl_C")[1], 480.0, 1e-9);
  const std::string text = test::ReadTextFile(path);
  EXPECT_TRUE(test::Contains(text, "# front_disc_limit_C: 500\n"));
  EXPECT_TRUE(test::Contains(text, "# status: Optimal Solution Found\n"));
  EXPECT_TRUE(test::Contains(text, "# car: cars/gen7/car.yaml\n"));
  WriteSolvedLapCsv(path, testing::MakeExampleSolvedLap("x", 30.0), track, ExampleCar());
  EXPECT_TRUE(test::Contains(test::ReadTextFile(path), "# front_disc_limit_C: none\n"));
  EXPECT_TRUE(test::Contains(test::InputErrorOf([&] {
                               WriteSolvedLapCsv(dir.path() / "no" / "lap.csv",
                                                 testing::MakeExampleSolvedLap("x", 30.0), track,
                                                 ExampleCar());
                             }),
                             "lap.csv"));
}

TEST(WriteOptimalRunFiles, OneLapOrTheComparison) {
  test::TempDir dir;
  const track::Track track = track::LoadTrack("darlington");
  const auto one =
      WriteOptimalRunFiles(dir.path() / "one", {testing::MakeExampleSolvedLap("optimal lap", 30.0)},
                           ExampleCar(), track, 30.0);
  EXPECT_EQ(one, (std::vector<fs::path>{dir.path() / "one" / "optimal.csv",
                                        dir.path() / "one" / "optimal.html"}));
  const auto two =
      WriteOptimalRunFiles(dir.path() / "two",
                           {testing::MakeExampleSolvedLap("no limit", 30.0),
                            testing::MakeExampleSolvedLap("discs <= 500 degC", 30.25, 500.0)},
                           ExampleCar(), track, 30.0);
  ASSERT_EQ(two.size(), 3u);
  EXPECT_EQ(two[0].filename(), "unconstrained.csv");
  EXPECT_EQ(two[1].filename(), "constrained.csv");
  EXPECT_EQ(two[2].filename(), "compare.html");
  const std::string html = test::ReadTextFile(two[2]);
  for (const char* part :
       {"hotlap optimal lap: gen7 on darlington", "30 m, trapezoidal", "no limit",
        "discs &lt;= 500 degC", "30.250", "42 / 1.2 s", "Front tread temperature", "Wear"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }
}

}  // namespace
}  // namespace hotlap::ocp
