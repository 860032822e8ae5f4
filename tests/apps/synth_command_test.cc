// End-to-end tests of `hotlap synth`: the log and JSON it writes, that --params changes the
// truth, --process-noise (a stochastic truth; the log without it unchanged), and clean failures.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hotlap/logs/telemetry.h"
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

// --process-noise default: the truth moves off the deterministic one (the carcass channel, read
// without sensor noise, differs), the inputs and the sensor noise stream do not; the log and the
// JSON say so; without the option neither has a process-noise entry. A noise file that is not
// there is exit 2 and no log.
TEST_F(SynthCommandTest, ProcessNoiseMakesTheTruthStochastic) {
  const std::string common = "synth --laps 1 --rate-hz 20 --noise-C 0 --lag-s 0 --seed 3 --out ";
  ASSERT_EQ(Run(common + P("plain.csv").string() + " --json " + P("plain.json").string()), 0)
      << err_;
  ASSERT_EQ(Run(common + P("noisy.csv").string() + " --json " + P("noisy.json").string() +
                " --process-noise default"),
            0)
      << err_;
  EXPECT_TRUE(Contains(out_, "truth with process noise from")) << out_;
  EXPECT_TRUE(Contains(out_, "carcass 0.00316, disc 0.1")) << out_;
  const hotlap::Telemetry plain = hotlap::Telemetry::Read(P("plain.csv"));
  const hotlap::Telemetry noisy = hotlap::Telemetry::Read(P("noisy.csv"));
  ASSERT_EQ(plain.size(), noisy.size());
  EXPECT_EQ(plain.Channel("fz", hotlap::Corner::kFrontLeft),
            noisy.Channel("fz", hotlap::Corner::kFrontLeft));
  const auto& a = plain.Channel("carcass_temp", hotlap::Corner::kRearRight);
  const auto& b = noisy.Channel("carcass_temp", hotlap::Corner::kRearRight);
  double moved = 0.0;
  for (size_t k = 0; k < a.size(); ++k) moved = std::max(moved, std::abs(a[k] - b[k]));
  // sqrt(1e-5 K^2/s x 31 s) = 0.018 K by the end of the lap: well above rounding, well below 1 K.
  EXPECT_GT(moved, 2e-3);
  EXPECT_LT(moved, 0.2);
  std::map<std::string, std::string> mp(plain.metadata().begin(), plain.metadata().end());
  std::map<std::string, std::string> mn(noisy.metadata().begin(), noisy.metadata().end());
  EXPECT_EQ(mp.count("process_noise"), 0u);
  EXPECT_TRUE(Contains(mn["process_noise"], "carcass 1e-05 K^2/s")) << mn["process_noise"];
  const nlohmann::json jp = nlohmann::json::parse(ReadTextFile(P("plain.json")));
  const nlohmann::json jn = nlohmann::json::parse(ReadTextFile(P("noisy.json")));
  EXPECT_FALSE(jp.contains("process_noise"));
  EXPECT_EQ(jn["process_noise"]["disc_temp_K2_per_s"].get<double>(), 1e-2);
  EXPECT_TRUE(Contains(jn["process_noise"]["file"].get<std::string>(), "default.yaml"));

  EXPECT_EQ(Run(common + P("bad.csv").string() + " --process-noise " + P("none.yaml").string()), 2);
  EXPECT_TRUE(Contains(err_, "none.yaml")) << err_;
  EXPECT_FALSE(fs::exists(P("bad.csv")));
}

}  // namespace
