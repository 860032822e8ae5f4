// End-to-end tests of `hotlap synth`: the log and JSON it writes, that --params changes the
// truth, and clean failures.

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/telemetry.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;
using hotlap::test::ReadTextFile;

class SynthCommandTest : public ::testing::Test {
 protected:
  int Run(const std::string& args) {
    const fs::path out = dir_.path() / "stdout.txt", err = dir_.path() / "stderr.txt";
    const std::string command =
        std::string(HOTLAP_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    out_ = ReadTextFile(out);
    err_ = ReadTextFile(err);
    return WEXITSTATUS(status);
  }
  fs::path P(const std::string& name) const { return dir_.path() / name; }
  const hotlap::test::TempDir dir_;
  std::string out_, err_;
};

TEST_F(SynthCommandTest, WritesALogAndJsonThatAgree) {
  ASSERT_EQ(Run("synth --laps 2 --rate-hz 10 --noise-C 0.3 --lag-s 0.1 --seed 5 --out " +
                P("log.csv").string() + " --json " + P("s.json").string()),
            0)
      << err_;
  const hotlap::Telemetry log = hotlap::Telemetry::Read(P("log.csv"));
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(P("s.json")));
  EXPECT_EQ(j["command"], "synth");
  EXPECT_EQ(j["track"], "darlington");
  EXPECT_EQ(j["laps"], 2);
  EXPECT_EQ(j["samples"].get<size_t>(), log.size());
  EXPECT_NEAR(j["duration_s"].get<double>(), 2.0 * j["lap_time_s"].get<double>(), 0.2);
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    EXPECT_GT(j["corners"][c]["peak_tread_temp_C"].get<double>(), 60.0);
    EXPECT_GE(j["corners"][c]["wear_mm"].get<double>(), 0.0);
  }
  std::map<std::string, std::string> meta(log.metadata().begin(), log.metadata().end());
  EXPECT_EQ(meta["laps"], "2");
  EXPECT_EQ(meta["seed"], "5");
  EXPECT_EQ(meta["temp_noise_C"], "0.3");
  EXPECT_EQ(meta["track"], "darlington");
  EXPECT_TRUE(log.Has("rolling_radius", hotlap::Corner::kRearRight));
  EXPECT_TRUE(log.Has("disc_temp", hotlap::Corner::kFrontLeft));
}

TEST_F(SynthCommandTest, ParamsChangeTheTruth) {
  const fs::path truth =
      dir_.Write("t.yaml",
                 "name: hot\nmodel: parameter_overrides\ncorners:\n  rr:\n    tyre:\n"
                 "      heat_generation: {p1: 0.6}   # assumed\n");
  ASSERT_EQ(
      Run("synth --rate-hz 10 --out " + P("a.csv").string() + " --json " + P("a.json").string()), 0)
      << err_;
  ASSERT_EQ(Run("synth --rate-hz 10 --params " + truth.string() + " --out " + P("b.csv").string() +
                " --json " + P("b.json").string()),
            0)
      << err_;
  EXPECT_TRUE(Contains(out_, "with hot parameters"));
  const auto a = nlohmann::json::parse(ReadTextFile(P("a.json")));
  const auto b = nlohmann::json::parse(ReadTextFile(P("b.json")));
  EXPECT_GT(b["corners"]["rr"]["peak_tread_temp_C"].get<double>(),
            a["corners"]["rr"]["peak_tread_temp_C"].get<double>() + 1.0);
  EXPECT_EQ(a["overrides"], nlohmann::json::object());

  // The same value set with --set: the same truth, and the override recorded.
  ASSERT_EQ(Run("synth --rate-hz 10 --set tyres.rr.heat_generation.p1=0.6 --out " +
                P("c.csv").string() + " --json " + P("c.json").string()),
            0)
      << err_;
  const auto c = nlohmann::json::parse(ReadTextFile(P("c.json")));
  EXPECT_EQ(c["corners"], b["corners"]);
  EXPECT_EQ(c["overrides"], nlohmann::json({{"tyres.rr.heat_generation.p1", 0.6}}));
  const hotlap::Telemetry log = hotlap::Telemetry::Read(P("c.csv"));
  std::map<std::string, std::string> meta(log.metadata().begin(), log.metadata().end());
  EXPECT_EQ(meta["overrides"], "tyres.rr.heat_generation.p1=0.6");
}

TEST_F(SynthCommandTest, BadInputFailsCleanly) {
  const fs::path bad = dir_.Write("bad.yaml",
                                  "name: x\nmodel: parameter_overrides\ncorners:\n"
                                  "  rr:\n    tyre:\n      p1: 0.5\n");
  EXPECT_EQ(Run("synth --params " + bad.string() + " --out " + P("x.csv").string()), 2);
  EXPECT_TRUE(Contains(err_, "bad.yaml")) << err_;
  EXPECT_EQ(Run("synth --track nowhere --out " + P("x.csv").string()), 2);
  EXPECT_TRUE(Contains(err_, "nowhere")) << err_;
  EXPECT_EQ(Run("synth --out " + P("no/x.csv").string()), 2);
  EXPECT_EQ(Run("synth --set tyres.rr.heat_generation.p1=1.5 --out " + P("x.csv").string()), 2);
  EXPECT_TRUE(Contains(err_, "override 'tyres.rr.heat_generation.p1=1.5': ")) << err_;
  EXPECT_TRUE(Contains(err_, "must be in [0, 1]")) << err_;
  EXPECT_FALSE(fs::exists(P("x.csv")));
}

}  // namespace
