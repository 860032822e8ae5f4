// A solved lap kept in a file (ocp/lap_start_file.h): written and read back whole, refused when it
// is not one, and taken onto another mesh of the same track.

#include "hotlap/ocp/lap_start_file.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

// A lap of 3 nodes, one variable and one row of each kind per node or interval.
LapSolution TinySolution() {
  LapSolution s;
  s.layout = {3, 1, 1, 1, 1, 1, Collocation::kTrapezoid, {}};
  s.solve.status = SolveStatus::kConverged;
  s.solve.message = "converged";
  s.solve.x = {1.0, 2.0, 3.0};
  s.solve.z_lower = {0.0, 0.5, 0.0};
  s.solve.z_upper = {0.0, 0.0, 0.25};
  s.solve.lambda.assign(s.layout.rows(), 0.0);
  for (size_t i = 0; i < s.solve.lambda.size(); ++i) s.solve.lambda[i] = 0.1 * i;
  s.solve.iterations = 12;
  return s;
}

TEST(LapStartFileTest, WritesAndReadsBackEverything) {
  test::TempDir dir;
  const LapSolution s = TinySolution();
  const auto path = dir.path() / "lap.bin";
  WriteLapStart(path, s, 2198.0);
  const LapStart r = ReadLapStart(path);
  EXPECT_EQ(r.track_length_m, 2198.0);
  EXPECT_EQ(r.layout.nodes, 3);
  EXPECT_EQ(r.layout.rows(), s.layout.rows());
  EXPECT_EQ(r.solve.x, s.solve.x);
  EXPECT_EQ(r.solve.z_lower, s.solve.z_lower);
  EXPECT_EQ(r.solve.z_upper, s.solve.z_upper);
  EXPECT_EQ(r.solve.lambda, s.solve.lambda);
  EXPECT_EQ(r.solve.iterations, 12);
  EXPECT_EQ(r.solve.status, SolveStatus::kConverged);
}

// A lap on a non-uniform mesh keeps its nodes' distances.
TEST(LapStartFileTest, KeepsANonUniformMesh) {
  test::TempDir dir;
  LapSolution s = TinySolution();
  s.layout.mesh_m = {0.0, 500.0, 2198.0};
  const auto path = dir.path() / "lap.bin";
  WriteLapStart(path, s, 2198.0);
  const LapStart r = ReadLapStart(path);
  EXPECT_EQ(r.layout.mesh_m, s.layout.mesh_m);
  EXPECT_EQ(r.solve.x, s.solve.x);
  EXPECT_EQ(ReadLapStart(path).layout.nodes, 3);
}

TEST(LapStartFileTest, KeepsTheCollocationAndReadsTheFirstVersionAsTrapezoid) {
  test::TempDir dir;
  LapSolution s = TinySolution();
  s.layout.collocation = Collocation::kHermiteSimpson;
  const auto path = dir.path() / "lap.bin";
  WriteLapStart(path, s, 2198.0);
  EXPECT_EQ(ReadLapStart(path).layout.collocation, Collocation::kHermiteSimpson);
  // The first version ("hotlapL1", six layout numbers, no collocation): this file without its
  // seventh number.
  std::string bytes = test::ReadTextFile(path);
  ASSERT_EQ(bytes.substr(0, 8), "hotlapL2");
  bytes[7] = '1';
  bytes.erase(8 + 8 + 6 * 4, 4);
  const auto old = dir.path() / "old.bin";
  test::WriteTextFile(old, bytes);
  const LapStart r = ReadLapStart(old);
  EXPECT_EQ(r.layout.collocation, Collocation::kTrapezoid);
  EXPECT_EQ(r.layout.nodes, 3);
  EXPECT_EQ(r.solve.lambda, s.solve.lambda);
  // A collocation of neither kind: refused.
  bytes = test::ReadTextFile(path);
  bytes[8 + 8 + 6 * 4] = 2;
  test::WriteTextFile(old, bytes);
  EXPECT_PRED2(test::Contains, test::InputErrorOf([&] { ReadLapStart(old); }), "collocation");
}

TEST(LapStartFileTest, RefusesWhatIsNotASavedLap) {
  test::TempDir dir;
  const auto path = dir.path() / "lap.bin";
  LapSolution empty = TinySolution();
  empty.solve.x.clear();
  EXPECT_THROW(WriteLapStart(path, empty, 2198.0), InputError);
  EXPECT_FALSE(std::filesystem::exists(path));
  WriteLapStart(path, TinySolution(), 2198.0);
  const std::string bytes = test::ReadTextFile(path);
  const auto message = [&](const std::string& content) {
    const auto bad = dir.path() / "bad.bin";
    test::WriteTextFile(bad, content);
    return test::InputErrorOf([&] { ReadLapStart(bad); });
  };
  EXPECT_PRED2(test::Contains, message("distance_m,offset_m\n"), "is not a saved lap");
  EXPECT_PRED2(test::Contains, message(bytes.substr(0, bytes.size() - 3)), "bad.bin");
  // A layout that does not match the solve's sizes: nodes 3 -> 4.
  std::string other = bytes;
  other[16] = 4;
  EXPECT_PRED2(test::Contains, message(other), "do not agree with its layout");
  EXPECT_THROW(ReadLapStart(dir.path() / "missing.bin"), InputError);
}

TEST(LapStartFileTest, TakesTheLapOntoTheRequestedMesh) {
  const track::Track track = track::LoadTrack("darlington");
  LapStart start;
  start.track_length_m = track.length_m();
  const LapSolution s = TinySolution();
  start.layout = s.layout.WithNodes(LapNodeCount(track, 100.0));  // 23 nodes
  start.solve = s.solve;
  start.solve.x.assign(start.layout.variables(), 7.0);
  start.solve.z_lower.assign(start.layout.variables(), 0.0);
  start.solve.z_upper.assign(start.layout.variables(), 0.0);
  start.solve.lambda.assign(start.layout.rows(), 1.0);
  OptimalLapOptions o;
  o.step_m = 50.0;
  UseLapStart(start, track, o);
  EXPECT_EQ(o.start_point, std::vector<double>(LapNodeCount(track, 50.0), 7.0));
  EXPECT_EQ(o.ipopt.warm_lambda.size(),
            static_cast<size_t>(start.layout.WithNodes(LapNodeCount(track, 50.0)).rows()));
  start.track_length_m += 10.0;
  EXPECT_THROW(UseLapStart(start, track, o), InputError);
}

}  // namespace
}  // namespace hotlap::ocp
