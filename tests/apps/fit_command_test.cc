// End-to-end tests of `hotlap fit tyre|contact-length|brake` on a log made by `hotlap synth`: the
// documented JSON keys, a fitted car that `hotlap replay` accepts as it is, the report rendering
// in Chromium, warnings for a dead channel, and clean failures for bad input.

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "report/chromium.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;
using hotlap::test::ReadTextFile;

using hotlap::test::RunResult;

const char* kTruth =
    "name: truth-test\n"
    "model: parameter_overrides\n"
    "corners:\n"
    "  rr:\n"
    "    tyre:\n"
    "      heat_generation: {p1: 0.492, p5_W_per_m2K: 641.25}   # 000 Table 4 x 1.5\n"
    "    brake:\n"
    "      heat_partition: 0.8   # assumed\n";

class FitCommandTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One lap of Darlington at 20 Hz with the default sensors (0.5 degC, 0.2 s lag).
    dir_ = new hotlap::test::TempDir;
    const fs::path truth = dir_->Write("truth.yaml", kTruth);
    const RunResult r = Run("synth --params " + truth.string() + " --rate-hz 20 --out " +
                            (dir_->path() / "log.csv").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { delete dir_; }

  static RunResult Run(const std::string& args) {
    return hotlap::test::RunHotlap(args, dir_->path());
  }
  static fs::path P(const std::string& name) { return dir_->path() / name; }
  static std::string Log() { return P("log.csv").string(); }

  static hotlap::test::TempDir* dir_;
};
hotlap::test::TempDir* FitCommandTest::dir_ = nullptr;

void ExpectParameter(const nlohmann::json& p, const std::string& what) {
  ASSERT_TRUE(p.is_object()) << what;
  EXPECT_TRUE(p["value"].is_number()) << what;
  EXPECT_TRUE(p["std_error"].is_number() || p["std_error"].is_null()) << what;
  ASSERT_TRUE(p["ci95"].is_array()) << what;
  EXPECT_EQ(p["ci95"].size(), 2u) << what;
  EXPECT_TRUE(p["well_determined"].is_boolean()) << what;
  // The joint interval contains the 95% one (where both ends are numbers).
  ASSERT_TRUE(p["ci95_joint"].is_array()) << what;
  ASSERT_EQ(p["ci95_joint"].size(), 2u) << what;
  if (p["ci95"][0].is_number() && p["ci95_joint"][0].is_number()) {
    EXPECT_LE(p["ci95_joint"][0].get<double>(), p["ci95"][0].get<double>()) << what;
  }
  if (p["ci95"][1].is_number() && p["ci95_joint"][1].is_number()) {
    EXPECT_GE(p["ci95_joint"][1].get<double>(), p["ci95"][1].get<double>()) << what;
  }
}

TEST_F(FitCommandTest, TyreJsonHasTheDocumentedKeysAndTheCarReplays) {
  fs::create_directories(P("tyre"));
  const RunResult r =
      Run("fit tyre --telemetry " + Log() + " --corners fr,rr --sensor-lag-s 0.2 --out " +
          P("tyre/car.yaml").string() + " --json " + P("tyre.json").string() + " --truth " +
          P("truth.yaml").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.out, "well determined"));
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(P("tyre.json")));
  EXPECT_EQ(j["command"], "fit tyre");
  EXPECT_EQ(j["corners"].size(), 2u);
  EXPECT_TRUE(j["warnings"].is_array());
  for (const char* c : {"fr", "rr"}) {
    const nlohmann::json& corner = j["corners"][c];
    EXPECT_TRUE(corner["fitted"].get<bool>());
    EXPECT_NEAR(corner["rms_tread_C"].get<double>(), 0.5, 0.1) << c;
    EXPECT_NEAR(corner["rms_carcass_C"].get<double>(), 0.5, 0.1) << c;
    for (const char* k : {"p1", "p2_J_per_kgN", "p3_J_per_kgN", "p4_J_per_kgN", "p5_W_per_m2K",
                          "wp1_mm_per_s", "wp2"}) {
      ExpectParameter(corner["parameters"][k], std::string(c) + " " + k);
      EXPECT_TRUE(corner["parameters"][k].contains("truth"));
    }
    EXPECT_TRUE(corner["fits"]["thermal"]["correlation"]["matrix"].is_array());
    EXPECT_TRUE(corner["fits"]["thermal"]["nuisance"].contains("initial_tread_temp_C"));
  }
  EXPECT_TRUE(j["corners"]["rr"]["parameters"]["p1"]["in_ci95"].is_boolean());
  EXPECT_TRUE(j["corners"]["rr"]["parameters"]["p1"]["in_ci95_joint"].is_boolean());
  EXPECT_EQ(j["joint_family_size"].get<int>(), 14);  // 7 parameters on each of two corners
  EXPECT_TRUE(Contains(r.out, "joint ["));
  EXPECT_NEAR(j["corners"]["rr"]["parameters"]["p1"]["truth"].get<double>(), 0.492, 1e-9);

  // The fitted car is a car: replay the log with it.
  const std::string fr = ReadTextFile(P("tyre/car/tyres/fr.yaml"));
  EXPECT_TRUE(Contains(fr, "# fitted ")) << fr;
  EXPECT_TRUE(Contains(fr, "to log.csv: std error"));
  const RunResult replay = Run("replay --telemetry " + Log() + " --car " +
                               P("tyre/car.yaml").string() + " --out " + P("replay.csv").string());
  EXPECT_EQ(replay.exit_code, 0) << replay.err;
}

TEST_F(FitCommandTest, BrakeAndContactLengthJsonKeys) {
  const RunResult b = Run("fit brake --telemetry " + Log() +
                          " --corners rr --sensor-lag-s 0.2 "
                          "--out " +
                          P("brake.yaml").string() + " --json " + P("brake.json").string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const nlohmann::json jb = nlohmann::json::parse(ReadTextFile(P("brake.json")));
  EXPECT_EQ(jb["command"], "fit brake");
  const nlohmann::json& rr = jb["corners"]["rr"];
  EXPECT_TRUE(rr["rms_disc_C"].is_number());
  EXPECT_TRUE(rr["rms_calliper_C"].is_number());
  ExpectParameter(rr["parameters"]["heat_partition"], "gamma");
  ExpectParameter(rr["parameters"]["mass_participation"], "xi");
  for (const char* e : {"P11", "P21", "P22", "P31", "P32", "P33"}) {
    ExpectParameter(rr["parameters"][std::string("disc_convection_") + e + "_W_per_K"], e);
    ExpectParameter(rr["parameters"][std::string("calliper_convection_") + e + "_W_per_K"], e);
  }
  EXPECT_NEAR(rr["parameters"]["heat_partition"]["value"].get<double>(), 0.8, 0.02);

  const RunResult c = Run("fit contact-length --telemetry " + Log() + " --out " +
                          P("contact.yaml").string() + " --json " + P("contact.json").string());
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const nlohmann::json jc = nlohmann::json::parse(ReadTextFile(P("contact.json")));
  for (const char* corner : {"fl", "fr", "rl", "rr"}) {
    EXPECT_NEAR(jc["corners"][corner]["rms_rolling_radius_mm"].get<double>(), 0.1, 0.02);
    ExpectParameter(jc["corners"][corner]["parameters"]["p_cp1"], "p_cp1");
    ExpectParameter(jc["corners"][corner]["parameters"]["p_cp2"], "p_cp2");
  }
  EXPECT_EQ(Run("replay --telemetry " + Log() + " --car " + P("contact.yaml").string() + " --out " +
                P("replay2.csv").string())
                .exit_code,
            0);
}

TEST_F(FitCommandTest, ReportRendersInChromium) {
  const RunResult r =
      Run("fit tyre --telemetry " + Log() + " --corners rr --out " + P("rep.yaml").string() +
          " --report " + P("report").string() + " --truth " + P("truth.yaml").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = ReadTextFile(P("report/index.html"));
  EXPECT_TRUE(Contains(html, "Uncertainty"));
  EXPECT_TRUE(Contains(html, "correlation of the estimates"));
  EXPECT_TRUE(Contains(ReadTextFile(P("report/channels.csv")), "measured_tread_temp_rr_C"));
  const auto status = hotlap::test::RenderInChromium(P("report/index.html"), P("chromium"));
  EXPECT_TRUE(hotlap::test::RenderedCleanly(status, 3));
}

TEST_F(FitCommandTest, DeadChannelIsExcludedWithAWarning) {
  // The log with the rr carcass sensor stuck at 61.5 degC.
  std::string text = ReadTextFile(P("log.csv"));
  std::istringstream in(text);
  std::string line, out, header;
  int column = -1;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      out += line + "\n";
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (column < 0) {
      for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i] == "carcass_temp_rr_C") column = static_cast<int>(i);
      }
    } else {
      cells[column] = "61.5";
    }
    for (size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + cells[i];
    out += "\n";
  }
  ASSERT_GE(column, 0);
  const fs::path dead = dir_->Write("dead.csv", out);
  const RunResult r = Run("fit tyre --telemetry " + dead.string() + " --corners rr --out " +
                          P("dead.yaml").string() + " --json " + P("dead.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err, "hotlap: warning: rr: carcass_temp_rr_C: excluded from the fit"));
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(P("dead.json")));
  EXPECT_EQ(j["corners"]["rr"]["fits"]["thermal"]["channels"]["carcass_temp"]["samples"], 0);
}

TEST_F(FitCommandTest, BadInputFailsCleanly) {
  const std::string out = " --out " + P("bad.yaml").string();
  for (const auto& [args, needle] : std::vector<std::pair<std::string, std::string>>{
           {"fit tyre --telemetry " + P("nope.csv").string() + out, "nope.csv"},
           {"fit tyre --telemetry " + Log() + " --corners fl,xx" + out, "unknown corner 'xx'"},
           {"fit brake --telemetry " + Log() + " --loss l2" + out, "loss 'l2'"},
           {"fit tyre --telemetry " + Log() + " --out " + P("bad.txt").string(), ".yaml"},
           {"fit tyre --telemetry " + Log() + " --wear-per-lap-mm rr:1" + out, "CORNER=VALUE"},
           {"fit contact-length --telemetry " + Log() + " --out " + P("no/dir/x.yaml").string(),
            "does not exist"}}) {
    const RunResult r = Run(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("hotlap: error: ", 0), 0u) << r.err;
    EXPECT_TRUE(Contains(r.err, needle)) << args;
  }
  EXPECT_FALSE(fs::exists(P("bad.yaml")));
}

}  // namespace
