// A stint's checkpoint files (ocp/stint_checkpoint.h): they hold what was saved, refuse to be
// another stint's, and are not used when torn. A stint resuming from them: stint_test.cc; one
// killed with SIGKILL: tests/apps/stint_command_test.cc.

#include "hotlap/ocp/stint_checkpoint.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

namespace fs = std::filesystem;

SolveResult ExampleResult(double scale) {
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
  mine.WriteGreedyLap(1, PresolvedLap{ExampleResult(1.0), ExampleResult(2.0), {}, {}, {}});
  mine.WriteStintIterate(ExampleResult(3.0));
  const std::optional<PresolvedLap> lap = mine.ReadGreedyLap(1);
  ASSERT_TRUE(lap.has_value());
  EXPECT_EQ(lap->coarse.x, ExampleResult(1.0).x);
  EXPECT_EQ(lap->fine.x, ExampleResult(2.0).x);
  EXPECT_EQ(lap->fine.lambda, ExampleResult(2.0).lambda);
  EXPECT_FALSE(mine.ReadGreedyLap(2).has_value());
  const std::optional<SolveResult> it = mine.ReadStintIterate();
  ASSERT_TRUE(it.has_value());
  EXPECT_EQ(it->x, ExampleResult(3.0).x);
  EXPECT_EQ(it->z_upper, ExampleResult(3.0).z_upper);
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

}  // namespace
}  // namespace hotlap::ocp
