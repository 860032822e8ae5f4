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
  EXPECT_FALSE(test::Contains(html, "Set-up sensitivities"));  // not asked
}

TEST(WriteOptimalRunFiles, RanksTheSensitivitiesWithTheLimitsCost) {
  test::TempDir dir;
  const auto& all = CrewChiefParameters();
  SolvedLap free = testing::MakeExampleSolvedLap("no limit", 30.0);
  SolvedLap limited = testing::MakeExampleSolvedLap("discs <= 500 degC", 30.25, 500.0);
  // +1 psi right rear: -0.362 ms free, -0.300 ms limited; +10 kg: +40.67 and +41.67 ms.
  free.sensitivities = {{all[3], 303.4, 0.3034, -5.255e-5}, {all.back(), 1542.0, 1.542, 4.067e-3}};
  limited.sensitivities = {{all[3], 303.4, 0.3034, -0.3e-3 / all[3].typical_step},
                           {all.back(), 1542.0, 1.542, 4.167e-3}};
  const auto files = WriteOptimalRunFiles(dir.path(), {free, limited}, ExampleCar(),
                                          track::LoadTrack("darlington"), 30.0);
  const std::string html = test::ReadTextFile(files.back());
  const size_t mass = html.find("chassis mass"), rr = html.find("right-rear cold pressure");
  ASSERT_NE(mass, std::string::npos);
  ASSERT_NE(rr, std::string::npos);
  EXPECT_LT(mass, rr);  // ranked by the free lap's effect
  for (const char* part : {"Set-up sensitivities", "limit&#39;s cost, ms", "+40.670", "+41.670",
                           "+1.000", "-0.362", "-0.300", "+0.062", "303.4 kPa"}) {
    EXPECT_TRUE(test::Contains(html, part)) << part;
  }
}

}  // namespace
}  // namespace hotlap::ocp
