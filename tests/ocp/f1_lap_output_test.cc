// What is reported of the F1 car's lap, on a hand-made solution of two nodes: the channels CSV,
// the summary lines, and the JSON with the peer's lap time on catalunya-fl only.

#include "hotlap/ocp/f1_lap_output.h"

#include <gtest/gtest.h>

#include "hotlap/common/csv.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

F1LapSolution ExampleF1Lap() {
  F1LapSolution s;
  s.distance = {0.0, 10.0};
  s.time = {0.0, 0.2};
  s.u = {50.0, 45.5};
  s.v = s.r = s.n = s.alpha = s.steer = {0.0, 0.1};
  s.throttle = {1.0, 0.5};
  for (int c = 0; c < 4; ++c) {
    s.kappa[c] = s.lambda[c] = s.fz[c] = s.fx[c] = s.fy[c] = {1.0, 2.0};
  }
  s.solve.status = SolveStatus::kConverged;
  s.solve.message = "Optimal Solution Found";
  s.solve.iterations = 47;
  s.solve.solve_seconds = 2.5;
  s.lap_time = 78.5;
  s.guess_lap_time = 90.0;
  s.variables = 100;
  s.constraints = 90;
  return s;
}

TEST(F1LapOutput, WritesTheChannels) {
  test::TempDir dir;
  vehicle::F1CarParams car;
  car.path = "cars/f1-2014/car.xml";
  const auto path = dir.path() / "optimal.csv";
  WriteF1LapCsv(path, ExampleF1Lap(), track::LoadTrack("darlington"), car);
  const CsvTable csv = ReadCsv(path);
  EXPECT_EQ(csv.columns.size(), 9u + 4u * 5u);
  EXPECT_EQ(csv.columns[9], "slip_ratio_fl");
  EXPECT_EQ(csv.columns.back(), "fy_rr_N");
  EXPECT_EQ(csv.Column("speed_mps"), (std::vector<double>{50.0, 45.5}));
  EXPECT_TRUE(test::Contains(test::ReadTextFile(path), "# car: cars/f1-2014/car.xml\n"));
}

TEST(F1LapOutput, SummaryLinesAndJson) {
  const F1LapSolution s = ExampleF1Lap();
  EXPECT_EQ(F1LapText(s),
            "Optimal Solution Found after 47 iterations in 2.50 s: lap 78.500 s (guess 90.000 s)\n"
            "  top speed 50.00 m/s, slowest 45.50 m/s; 100 variables, 90 constraints\n");
  nlohmann::json j = F1LapJson(s, "darlington", "f1-2014", 500);
  EXPECT_EQ(j["model"], "limebeer-2014-f1");
  EXPECT_EQ(j["mesh_points"], 500);
  EXPECT_EQ(j["lap_time_s"], 78.5);
  EXPECT_EQ(j["converged"], true);
  EXPECT_EQ(j["min_speed_mps"], 45.5);
  EXPECT_FALSE(j.contains("peer_lap_time_s"));
  j = F1LapJson(s, "catalunya-fl", "f1-2014", 500);
  EXPECT_EQ(j["peer_lap_time_s"], kF1PeerLapTime);
  EXPECT_EQ(j["lap_time_difference_percent"], 0.9114);
}

}  // namespace
}  // namespace hotlap::ocp
