// Bad input, end to end (issue 25): physically impossible logs refused before any work, values a
// real logger produces treated with a warning, option errors with exit 2 and a plain message, and
// nothing created where an output was asked for when the command refuses.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "hotlap/common/csv.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;
using test::Contains;

const fs::path kExample = fs::path(HOTLAP_SOURCE_DIR) / "data/telemetry/darlington_example.csv";

class RefusalTest : public test::CommandTest {
 protected:
  // The example log with `column` set to `value` on rows [first, last).
  fs::path LogWith(const std::string& column, double value, size_t first, size_t last) {
    CsvTable t = ReadCsv(kExample);
    std::vector<double>& v = t.values.at(t.ColumnIndex(column));
    for (size_t i = first; i < last; ++i) v.at(i) = value;
    const fs::path path = dir() / ("log_" + column + ".csv");
    WriteCsv(path, t.metadata, t.columns, t.values);
    return path;
  }
  // Runs `args`, expects exit 2 with `message` on stderr, and nothing new in the folder.
  void ExpectRefusal(const std::string& args, const std::string& message) {
    std::vector<fs::path> before;
    for (const auto& e : fs::directory_iterator(dir())) before.push_back(e.path());
    const test::RunResult r = Run(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(Contains(r.err, message)) << args << "\n" << r.err;
    for (const char* name : {"out", "out.csv", "out.json", "report", "car.yaml"}) {
      EXPECT_FALSE(fs::exists(dir() / name)) << args << " left " << name;
    }
  }
  std::string Path(const std::string& name) { return (dir() / name).string(); }
};

TEST_F(RefusalTest, ImpossibleLogsAreRefusedBeforeAnyWork) {
  const std::string outputs =
      " --out " + Path("out.csv") + " --json " + Path("out.json") + " --report " + Path("report");
  ExpectRefusal("replay --telemetry " + LogWith("speed_mps", -50.0, 10, 11).string() + outputs,
                "'speed_mps' is -50 mps: impossible");
  ExpectRefusal("replay --telemetry " + LogWith("speed_mps", 1e308, 10, 11).string() + outputs,
                "'speed_mps' is 1e+308 mps: impossible");
  ExpectRefusal("replay --telemetry " + LogWith("fz_fl_N", -3000.0, 10, 11).string() + outputs,
                "'fz_fl_N' is -3000 N: impossible");
  ExpectRefusal(
      "replay --telemetry " + LogWith("slip_angle_fr_deg", 120.0, 10, 11).string() + outputs,
      "+-90 degrees");
  ExpectRefusal("fit tyre --telemetry " + LogWith("speed_mps", -50.0, 10, 11).string() + " --out " +
                    Path("car.yaml") + " --report " + Path("report"),
                "'speed_mps' is -50 mps");
}

TEST_F(RefusalTest, AWheelInTheAirIsTreatedWithAWarningInTheJson) {
  const fs::path log = LogWith("fz_rl_N", -150.0, 100, 110);
  const test::RunResult r = Run("replay --telemetry " + log.string() + " --out " + Path("out.csv") +
                                " --json " + Path("out.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "hotlap: warning: ")) << r.err;
  EXPECT_TRUE(Contains(r.err, "'fz_rl_N': 10 values")) << r.err;
  const nlohmann::json j = Json(dir() / "out.json");
  ASSERT_EQ(j.at("telemetry_warnings").size(), 1u);
  EXPECT_TRUE(Contains(j["telemetry_warnings"][0].get<std::string>(), "a wheel in the air"));
}

TEST_F(RefusalTest, CommandsThatWriteAFolderLeaveNoneWhenTheyRefuse) {
  // /dev/null is there but empty: the message says so, not "no such file".
  ExpectRefusal("fe inflate --config /dev/null --out " + Path("out/nested"), "the file is empty");
  ExpectRefusal("abs --config /dev/null --out " + Path("out"), "the file is empty");
  ExpectRefusal("abs --speed-mps 1e400 --out " + Path("out"), "--speed-mps");
  ExpectRefusal("fe abs --config " + Path("missing.yaml") + " --out " + Path("out"),
                "no such file");
  ExpectRefusal("fe inflate --config " + dir().string() + " --out " + Path("out"),
                "it is a folder, not a file");
}

// An optimal-control request that cannot be met is said in words. A limit below where the discs
// start is refused before any solve; a solve that stops unconverged keeps its last point, writes
// its files, says how far that point is from a lap the car can drive, and exits 3.
TEST_F(RefusalTest, AnOptimalLapThatCannotBeSolvedIsReportedInWordsWithItsPointKept) {
  ExpectRefusal("optimise --disc-limit-C 300 --step-m 30 --coarse-step-m 0 --out " + Path("out"),
                "disc starts at");
  const test::RunResult r =
      Run("optimise --disc-limit-C 500 --step-m 30 --coarse-step-m 0 --max-iterations 3 --out " +
          Path("out") + " --json " + Path("out.json"));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(Contains(r.out + r.err, "stopped at the iteration limit")) << r.out << r.err;
  EXPECT_TRUE(Contains(r.out + r.err, "kept the last point")) << r.out << r.err;
  EXPECT_TRUE(fs::exists(dir() / "out" / "optimal.csv"));
  const nlohmann::json j = Json(dir() / "out.json");
  EXPECT_EQ(j.at("status"), "failed");
  EXPECT_GT(j.at("constraint_violation").get<double>(), 1e-6);
}

// The disk fills while the channels are written (a file-size limit stands in for it): exit 2 with
// the system's reason, the previous output intact and no temporary left beside it.
TEST_F(RefusalTest, AFullDiskLeavesThePreviousOutputIntact) {
  test::WriteTextFile(dir() / "out.csv", "previous\n");
  // ulimit -f counts 1024-byte blocks in bash, 512 in dash: the channels file is far larger.
  const test::RunResult r =
      Run("--version >/dev/null; ulimit -f 64; exec " + std::string(HOTLAP_BINARY) +
          " replay --telemetry " + kExample.string() + " --out " + Path("out.csv") + " --json " +
          Path("out.json"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::ReadTextFile(dir() / "out.csv"), "previous\n");
  EXPECT_TRUE(Contains(r.err, "write failed: File too large")) << r.err;
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir())) {
    files += e.path().filename().string().find(".tmp") != std::string::npos;
  }
  EXPECT_EQ(files, 0) << "a temporary was left";
  EXPECT_FALSE(fs::exists(dir() / "out.json"));
}

TEST_F(RefusalTest, ABadOptionIsExit2WithAPlainMessage) {
  const test::RunResult r = Run("abs --speed-mps -5 --out " + Path("out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Contains(r.err, "--speed-mps: must be a positive number, not -5")) << r.err;
  EXPECT_FALSE(Contains(r.err, "179769313486231570")) << r.err;  // CLI11's own range text
  EXPECT_FALSE(fs::exists(dir() / "out"));
  EXPECT_EQ(Run("replay --no-such-option").exit_code, 2);
  EXPECT_EQ(Run("--help").exit_code, 0);
  EXPECT_EQ(Run("--version").exit_code, 0);
  // One line, as every other refusal, naming the command whose help to read.
  for (const auto& [args, message] :
       {std::pair{"nosuch", "hotlap: error: unknown command 'nosuch' (hotlap --help)\n"},
        std::pair{"lap --laps x --out o",
                  "hotlap: error: Could not convert: --laps = x (hotlap lap --help)\n"},
        std::pair{"tyre eval --fz-N 5000",
                  "hotlap: error: --model is required (hotlap tyre eval "
                  "--help)\n"}}) {
    const test::RunResult bad = Run(args);
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_EQ(bad.err, message) << args;
  }
}

}  // namespace
}  // namespace hotlap
