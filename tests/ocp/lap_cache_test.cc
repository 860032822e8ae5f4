// The lap cache (ocp/lap_cache.h) and a run's use of it (OptimalRunOptions::lap_cache_dir): laps
// kept by their family and coordinates, the nearest found by the scaled distance, the same inputs
// at distance 0, other families and unreadable entries left out; a solve that starts from its
// cached neighbour and keeps its own lap.

#include "hotlap/ocp/lap_cache.h"

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/ocp/lap_sensitivities.h"
#include "hotlap/ocp/lap_start_file.h"
#include "hotlap/ocp/optimal_run.h"
#include "hotlap/track/track_io.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

namespace fs = std::filesystem;

// Keeps an empty "lap" under `key` (the cache never reads it here).
void Keep(const fs::path& dir, const CachedLapKey& key, const std::string& name) {
  const fs::path saved = test::WriteTextFile(dir / ("." + name + ".lap"), "");
  KeepCachedLap(dir, key, name, saved, 30.0, 10);
}

TEST(LapCacheTest, FindsTheNearestOfItsFamilyInOrder) {
  test::TempDir dir;
  const std::string family = "car a\ntrack b";
  Keep(dir.path(), {family, {{"share", 0.58}, {"duct", 1.0}}}, "near");
  Keep(dir.path(), {family, {{"share", 0.55}, {"duct", 1.2}}}, "far");
  Keep(dir.path(), {"car a\ntrack c", {{"share", 0.60}, {"duct", 1.1}}}, "other track");
  Keep(dir.path(), {family, {{"share", 0.60}}}, "other keys");
  test::WriteTextFile(dir.path() / "0000000000000000.json", "{not json");
  const CachedLapKey key{family, {{"share", 0.60}, {"duct", 1.1}}};
  const std::map<std::string, double> scales = {{"share", 0.1}, {"duct", 0.4}};
  const std::vector<CachedLap> found = NearestCachedLaps(dir.path(), key, scales, 5);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].name, "near");
  EXPECT_EQ(found[1].name, "far");
  // sqrt((0.02 / 0.1)^2 + (0.1 / 0.4)^2), by hand.
  EXPECT_NEAR(found[0].distance, std::sqrt(0.04 + 0.0625), 1e-12);
  EXPECT_EQ(found[0].lap.extension(), ".lap");
  EXPECT_TRUE(fs::exists(found[0].lap));
  EXPECT_EQ(NearestCachedLaps(dir.path(), key, scales, 1).size(), 1u);
  // The same inputs: their own lap at distance 0; its lap file gone: no longer a start.
  Keep(dir.path(), key, "same");
  const std::vector<CachedLap> same = NearestCachedLaps(dir.path(), key, scales, 1);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].name, "same");
  EXPECT_EQ(same[0].distance, 0.0);
  EXPECT_EQ(same[0].lap.stem().string(), CachedLapHash(key));
  fs::remove(same[0].lap);
  EXPECT_EQ(NearestCachedLaps(dir.path(), key, scales, 1)[0].name, "near");
  // Without a scale the value's size (at least 1).
  EXPECT_NEAR(CoordinateDistance({{"x", 3.0}}, {{"x", 1.0}}, {}), 2.0 / 3.0, 1e-15);
  EXPECT_NE(CachedLapHash(key), CachedLapHash({family, {{"share", 0.61}, {"duct", 1.1}}}));
  EXPECT_TRUE(NearestCachedLaps(dir.path() / "none", key, scales, 2).empty());
}

TEST(LapCacheTest, ARunsKeyIsItsCarsFilesAndItsValues) {
  const track::Track track = track::LoadTrack("darlington");
  test::TempDir dir;
  fs::copy(test::Gen7Dir(), dir.path() / "gen7", fs::copy_options::recursive);
  const fs::path file = dir.path() / "gen7/car.yaml";
  OptimalRunOptions o;
  o.disc_limit_C = 500.0;
  const CachedLapKey key =
      LapCacheKeyOf(vehicle::LoadCar(file, {{"brake_system.front_share", 0.62}}), track, o);
  EXPECT_EQ(key.coordinates.at("brake_system.front_share"), 0.62);
  EXPECT_EQ(key.coordinates.at("disc_limit_C"), 500.0);
  EXPECT_EQ(key.coordinates.at("ambient_temp_C"), 25.0);
  EXPECT_EQ(key.coordinates.at("chassis.mass_kg"), 1542.0);  // the car's own
  EXPECT_EQ(key.coordinates.at("brakes.fl.duct_factor"), 1.0);
  EXPECT_EQ(key.coordinates.size(), CrewChiefParameters().size() + 3);
  // Another mesh, another file of the car's: another family.
  OptimalRunOptions finer = o;
  finer.step_m = 1.5;
  EXPECT_NE(LapCacheKeyOf(vehicle::LoadCar(file), track, finer).family, key.family);
  test::WriteTextFile(dir.path() / "gen7/notes.txt", "changed\n");
  EXPECT_NE(LapCacheKeyOf(vehicle::LoadCar(file), track, o).family, key.family);
  EXPECT_THROW(LapCacheKeyOf(vehicle::Car{}, track, o), InputError);
}

// A solve keeps its lap; a neighbouring set-up starts from it, the same inputs find their own.
TEST(LapCacheTest, ASolveStartsFromItsNeighbourAndKeepsItsLap) {
  const track::Track track = track::LoadTrack("darlington");
  const fs::path file = test::Gen7Dir() / "car.yaml";
  test::TempDir dir;
  OptimalRunOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.disc_limit_C = 500.0;
  o.lap_cache_dir = (dir.path() / "laps").string();
  const OptimalRuns first = SolveOptimalRuns(vehicle::LoadCar(file), track, o);
  ASSERT_TRUE(first.laps[0].run.solution.solve.ok());
  EXPECT_EQ(first.laps[0].warm_start_from, "");
  EXPECT_EQ(first.laps[0].run.started_from, "the QSS guess");
  const vehicle::Car other = vehicle::LoadCar(file, {{"brake_system.front_share", 0.62}});
  const OptimalRuns second = SolveOptimalRuns(other, track, o);
  const SolvedLap& lap = second.laps[0];
  ASSERT_TRUE(lap.run.solution.solve.ok());
  EXPECT_EQ(lap.warm_start_from, "gen7");
  EXPECT_NEAR(lap.warm_start_distance, 0.02 / 0.01, 1e-9);  // two crew-chief steps of balance
  EXPECT_EQ(lap.run.started_from, "the saved lap");
  EXPECT_LT(lap.run.solution.solve.iterations, first.laps[0].run.solution.solve.iterations / 2);
  const OptimalRuns again = SolveOptimalRuns(other, track, o);
  EXPECT_EQ(again.laps[0].warm_start_from, "gen7 brake_system.front_share=0.62");
  EXPECT_EQ(again.laps[0].warm_start_distance, 0.0);
  EXPECT_LE(again.laps[0].run.solution.solve.iterations, 10);
  // Not for the comparison.
  OptimalRunOptions compare = o;
  compare.disc_limit_C.reset();
  compare.compare_disc_limit_C = 500.0;
  EXPECT_THROW(SolveOptimalRuns(other, track, compare), InputError);
}

// A cached lap that does not fit this programme (another build of the same version: another
// layout) is a failed start, not an error: the solve goes on from its default start.
TEST(LapCacheTest, ACachedLapThatDoesNotFitIsNoStart) {
  const track::Track track = track::LoadTrack("darlington");
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  test::TempDir dir;
  OptimalRunOptions o;
  o.step_m = 30.0;
  o.coarse_step_m = 0.0;
  o.lap_cache_dir = dir.path().string();
  LapSolution tiny;  // one variable a node
  tiny.layout = {3, 1, 1, 1, 1, 1, Collocation::kTrapezoid, {}};
  tiny.solve.status = SolveStatus::kConverged;
  tiny.solve.x.assign(3, 1.0);
  tiny.solve.z_lower.assign(3, 0.0);
  tiny.solve.z_upper.assign(3, 0.0);
  tiny.solve.lambda.assign(tiny.layout.rows(), 0.0);
  WriteLapStart(dir.path() / ".tiny.lap", tiny, track.length_m());
  KeepCachedLap(dir.path(), LapCacheKeyOf(car, track, o), "tiny", dir.path() / ".tiny.lap", 30.0,
                1);
  const OptimalRuns runs = SolveOptimalRuns(car, track, o);
  const SolvedLap& lap = runs.laps[0];
  ASSERT_TRUE(lap.run.solution.solve.ok()) << lap.run.solution.solve.message;
  ASSERT_EQ(lap.run.failed_starts.size(), 1u);
  EXPECT_EQ(lap.run.failed_starts[0].from, "the saved lap");
  EXPECT_EQ(lap.run.started_from, "the QSS guess");
  EXPECT_EQ(lap.warm_start_from, "");
  // The converged lap replaced the one that did not fit.
  const std::vector<CachedLap> now =
      NearestCachedLaps(dir.path(), LapCacheKeyOf(car, track, o), {}, 2);
  ASSERT_EQ(now.size(), 1u);
  EXPECT_EQ(now[0].name, "gen7");
}

}  // namespace
}  // namespace hotlap::ocp
