// A stint's checkpoints (ocp/stint_checkpoint.h): files that hold what was saved, refuse to be
// another stint's, and are not used when torn; and a stint stopped part way resumes from them
// (the command-line test kills one with SIGKILL: tests/apps/stint_command_test.cc).

#include "hotlap/ocp/stint_checkpoint.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/stint.h"
#include "hotlap/track/track_io.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

namespace fs = std::filesystem;

SolveResult Example(double scale) {
  SolveResult r;
  r.status = SolveStatus::kStopped;
  r.message = "checkpoint";
  r.x = {1.0 * scale, 2.0, 3.0};
  r.z_lower = {0.1, 0.2, 0.3};
  r.z_upper = {0.0, 0.0, 0.5};
  r.lambda = {-4.0, 5.0};
  r.iterations = 15;
  r.barrier_mu = 1e-5;
  return r;
}

TEST(StintCheckpointsTest, FilesHoldWhatWasSavedForThisStintOnly) {
  const test::TempDir dir;
  const StintCheckpoints mine(dir.path() / "a" / "b", 42);  // created with its parents
  EXPECT_FALSE(mine.ReadGreedyLap(1).has_value());
  EXPECT_FALSE(mine.ReadStintIterate().has_value());
  mine.WriteGreedyLap(1, PresolvedLap{Example(1.0), Example(2.0)});
  mine.WriteStintIterate(Example(3.0));
  const std::optional<PresolvedLap> lap = mine.ReadGreedyLap(1);
  ASSERT_TRUE(lap.has_value());
  EXPECT_EQ(lap->coarse.x, Example(1.0).x);
  EXPECT_EQ(lap->fine.x, Example(2.0).x);
  EXPECT_EQ(lap->fine.lambda, Example(2.0).lambda);
  EXPECT_FALSE(mine.ReadGreedyLap(2).has_value());
  const std::optional<SolveResult> it = mine.ReadStintIterate();
  ASSERT_TRUE(it.has_value());
  EXPECT_EQ(it->x, Example(3.0).x);
  EXPECT_EQ(it->z_upper, Example(3.0).z_upper);
  EXPECT_EQ(it->iterations, 15);
  EXPECT_EQ(it->barrier_mu, 1e-5);
  EXPECT_EQ(mine.foreign_files(), 0);

  // Another stint's fingerprint: not used, and counted.
  const StintCheckpoints other(dir.path() / "a" / "b", 43);
  EXPECT_FALSE(other.ReadGreedyLap(1).has_value());
  EXPECT_FALSE(other.ReadStintIterate().has_value());
  EXPECT_EQ(other.foreign_files(), 2);

  // A file cut short or with a byte changed: not used (not an error).
  const fs::path file = dir.path() / "a" / "b" / "stint_iterate.bin";
  std::string bytes = test::ReadTextFile(file);
  for (const std::string& broken : {bytes.substr(0, bytes.size() - 9), [&] {
                                      std::string b = bytes;
                                      b[b.size() / 2] ^= 0x10;
                                      return b;
                                    }()}) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << broken;
    EXPECT_FALSE(mine.ReadStintIterate().has_value());
  }
  // A folder that cannot be one.
  const fs::path a_file = dir.Write("plain.txt", "x");
  EXPECT_THROW(StintCheckpoints(a_file, 1), InputError);
}

class StintResumeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    car_ = new vehicle::Car(vehicle::LoadCar(test::Gen7Dir() / "car.yaml"));
    track_ = new track::Track(track::LoadTrack("darlington"));
  }
  static void TearDownTestSuite() {
    delete car_;
    delete track_;
  }
  static StintOptions Coarse() {
    StintOptions o;
    o.laps = 2;
    o.lap.step_m = 20.0;
    o.lap.coarse_step_m = 0.0;
    o.lap.ambient_temp = CelsiusToKelvin(25.0);
    o.lap.track_temp = CelsiusToKelvin(40.0);
    return o;
  }
  static vehicle::Car* car_;
  static track::Track* track_;
};
vehicle::Car* StintResumeTest::car_ = nullptr;
track::Track* StintResumeTest::track_ = nullptr;

// The fingerprint changes with the stint's options, the car's parameters (through the warm-up)
// and the caller's key, and with nothing else.
TEST_F(StintResumeTest, FingerprintTellsStintsApart) {
  const StintOptions o = Coarse();
  const LapWarmUp w = RunLapWarmUp(*car_, *track_, o.lap);
  const std::uint64_t base = StintFingerprint(o, *track_, w);
  EXPECT_EQ(StintFingerprint(o, *track_, RunLapWarmUp(*car_, *track_, o.lap)), base);
  StintOptions changed = o;
  changed.wear_scale = 2.0;
  EXPECT_NE(StintFingerprint(changed, *track_, w), base);
  changed = o;
  changed.lap.front_disc_limit = CelsiusToKelvin(600.0);
  EXPECT_NE(StintFingerprint(changed, *track_, w), base);
  changed = o;
  changed.checkpoint_key = "car.yaml:123;";
  EXPECT_NE(StintFingerprint(changed, *track_, w), base);
  // A heavier car: another warm-up.
  vehicle::Car heavier = *car_;
  heavier.vehicle->chassis.mass += 20.0;
  EXPECT_NE(StintFingerprint(o, *track_, RunLapWarmUp(heavier, *track_, o.lap)), base);
  // The folder and the checkpoint interval are not the stint.
  changed = o;
  changed.checkpoint_dir = "/elsewhere";
  changed.checkpoint_every = 3;
  EXPECT_EQ(StintFingerprint(changed, *track_, w), base);
}

// A run stopped part way through the stint's solve (as a kill would stop it) resumes with every
// greedy lap from its file and the stint from its last saved iterate, and ends on the same stint
// having lost at most one checkpoint interval; a run of a finished stint converges at once.
TEST_F(StintResumeTest, StoppedStintResumesFromItsCheckpoints) {
  const test::TempDir dir;
  StintOptions o = Coarse();
  o.checkpoint_dir = dir.path() / "checkpoints";
  o.checkpoint_every = 5;
  const StintResult whole = SolveStint(*car_, *track_, o);
  ASSERT_TRUE(whole.ok()) << whole.run.solution.solve.message;
  ASSERT_GT(whole.ipopt_iterations, 10) << "too short to stop part way";
  EXPECT_EQ(whole.greedy_laps_resumed, 0);
  EXPECT_EQ(whole.resumed_from_iteration, 0);
  for (const char* f : {"greedy_lap_1.bin", "greedy_lap_2.bin", "stint_iterate.bin"}) {
    EXPECT_TRUE(fs::is_regular_file(o.checkpoint_dir / f)) << f;
  }

  // The same stint again: nothing solved but a check of the saved end.
  const StintResult again = SolveStint(*car_, *track_, o);
  ASSERT_TRUE(again.ok()) << again.run.solution.solve.message;
  EXPECT_EQ(again.greedy_laps_resumed, 2);
  EXPECT_EQ(again.resumed_from_iteration, whole.ipopt_iterations);
  EXPECT_LE(again.ipopt_iterations, 3);
  EXPECT_NEAR(again.total_time_s, whole.total_time_s, 1e-5);
  EXPECT_DOUBLE_EQ(again.greedy_total_time_s, whole.greedy_total_time_s);

  // Stopped at iteration 8 of the stint's solve: its file holds iteration 5.
  fs::remove(o.checkpoint_dir / "stint_iterate.bin");
  StintOptions stopping = o;
  bool in_stint = false;
  stopping.lap.ipopt.on_iteration = [&in_stint](int it, double, double, double) {
    return !(in_stint && it >= 8);
  };
  const StintResult stopped = SolveStint(*car_, *track_, stopping, [&](const std::string& line) {
    if (line.rfind("the stint:", 0) == 0) in_stint = true;
  });
  EXPECT_FALSE(stopped.ok());
  EXPECT_EQ(stopped.greedy_laps_resumed, 2);
  const StintResult resumed = SolveStint(*car_, *track_, o);
  ASSERT_TRUE(resumed.ok()) << resumed.run.solution.solve.message;
  EXPECT_EQ(resumed.greedy_laps_resumed, 2);
  EXPECT_EQ(resumed.resumed_from_iteration, 5);
  EXPECT_NEAR(resumed.total_time_s, whole.total_time_s, 1e-3);
  EXPECT_LE(resumed.ipopt_iterations, whole.ipopt_iterations - 5 + o.checkpoint_every)
      << "the whole solve took " << whole.ipopt_iterations;
}

// A checkpoint that cannot be written (here its path is a folder; a full disk alike) costs the
// resume, not the run: the stint ends as without checkpoints, with one warning.
TEST_F(StintResumeTest, CheckpointThatCannotBeWrittenIsAWarning) {
  const test::TempDir dir;
  StintOptions o = Coarse();
  o.wear_scale = 0.0;
  o.fuel_kg = 0.0;
  o.checkpoint_dir = dir.path();
  o.checkpoint_every = 4;
  for (const char* f : {"greedy_lap_1.bin", "greedy_lap_2.bin", "stint_iterate.bin"}) {
    fs::create_directories(dir.path() / f / "in_the_way");
  }
  std::vector<std::string> warnings;
  const StintResult r = SolveStint(*car_, *track_, o, [&](const std::string& line) {
    if (line.rfind("warning:", 0) == 0) warnings.push_back(line);
  });
  ASSERT_TRUE(r.ok()) << r.run.solution.solve.message;
  EXPECT_EQ(r.greedy_laps_resumed, 0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("greedy_lap_1.bin"), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace hotlap::ocp
