// End-to-end tests of `hotlap abs`: the default run is the paper's case and writes the
// documented CSV columns, JSON keys and a report that renders in headless Chromium; options
// change what they say; bad input gives one clear message, exit code 2 and no output.

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/csv.h"
#include "report/chromium.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;
using hotlap::test::ReadTextFile;

class AbsCommandTest : public ::testing::Test {
 protected:
  int Run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const int status = std::system(
        (std::string(HOTLAP_BINARY) + " abs " + args + " >" + out.string() + " 2>" + err.string())
            .c_str());
    out_ = ReadTextFile(out);
    err_ = ReadTextFile(err);
    return WEXITSTATUS(status);
  }
  nlohmann::json Json(const fs::path& p) { return nlohmann::json::parse(ReadTextFile(p)); }

  const hotlap::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
  std::string out_, err_;
};

TEST_F(AbsCommandTest, TheDefaultIsThePapersCase) {
  const fs::path out = dir_ / "run", json = dir_ / "abs.json";
  ASSERT_EQ(Run("--out " + out.string() + " --json " + json.string()), 0) << err_;
  const nlohmann::json j = Json(json);
  for (const char* key : {"stopping_distance_m", "stop_time_s", "max_lambda_after_first_cycle",
                          "fraction_time_lambda_below_0_135", "cycles_per_s", "wheel_locked",
                          "peak_disc_temp_C", "energy", "cycles", "stopped", "distance_m"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["surface"], "paper");
  EXPECT_DOUBLE_EQ(j["initial_speed_mps"].get<double>(), 11.165);
  EXPECT_DOUBLE_EQ(j["duration_s"].get<double>(), 1.5);
  EXPECT_EQ(j["wheel_locked"], false);
  EXPECT_GE(j["cycles_per_s"].get<double>(), 5.0);
  EXPECT_LE(j["cycles_per_s"].get<double>(), 12.0);
  EXPECT_GE(j["fraction_time_lambda_below_0_135"].get<double>(), 0.9);
  EXPECT_LT(std::abs(j["energy"]["closure_error"].get<double>()), 0.01);
  // 1.5 s does not bring the quarter car to rest: no stopping distance, honestly.
  EXPECT_EQ(j["stopped"], false);
  EXPECT_TRUE(j["stopping_distance_m"].is_null());

  // The CSV has the documented columns and agrees with the JSON.
  const hotlap::CsvTable t = hotlap::ReadCsv(out / "abs.csv");
  for (const char* c : {"time_s", "pressure_MPa", "brake_torque_Nm", "speed_mps", "wheel_speed_mps",
                        "lambda", "fx_N", "abs_state", "disc_temp_C"}) {
    EXPECT_GE(t.ColumnIndex(c), 0) << c;
  }
  const auto& time = t.values[t.ColumnIndex("time_s")];
  EXPECT_DOUBLE_EQ(time.back(), 1.5);
  const auto& disc = t.values[t.ColumnIndex("disc_temp_C")];
  EXPECT_NEAR(*std::max_element(disc.begin(), disc.end()), j["peak_disc_temp_C"].get<double>(),
              1e-6);
  const auto& speed = t.values[t.ColumnIndex("speed_mps")];
  EXPECT_NEAR(speed.back(), j["final_speed_mps"].get<double>(), 1e-6);
  EXPECT_TRUE(Contains(out_, "control cycles"));
}

TEST_F(AbsCommandTest, WithScenariosTheReportRendersInChromium) {
  const fs::path out = dir_ / "run", json = dir_ / "abs.json";
  ASSERT_EQ(Run("--out " + out.string() + " --json " + json.string() + " --scenarios"), 0) << err_;
  const nlohmann::json j = Json(json);
  ASSERT_TRUE(j.contains("scenarios"));
  for (const auto& s : j["scenarios"]["comparison"]) {
    EXPECT_LT(s["abs"]["stopping_distance_m"].get<double>(),
              s["locked"]["stopping_distance_m"].get<double>())
        << s["surface"];
  }
  EXPECT_EQ(j["scenarios"]["stop_series"]["peak_disc_temp_C"].size(), 10u);
  const fs::path html = out / "abs_report.html";
  const std::string page = ReadTextFile(html);
  EXPECT_TRUE(Contains(page, "Braking slip"));
  EXPECT_TRUE(Contains(page, "ABS against locked wheels"));
  const auto status = hotlap::test::RenderInChromium(html, dir_);
  EXPECT_TRUE(hotlap::test::RenderedCleanly(status, 9));
}

TEST_F(AbsCommandTest, OptionsChangeTheEvent) {
  const fs::path json = dir_ / "abs.json";
  ASSERT_EQ(Run("--out " + (dir_ / "a").string() + " --json " + json.string() +
                " --no-abs --surface wet --speed-mps 8 --duration-s 5"),
            0)
      << err_;
  nlohmann::json j = Json(json);
  EXPECT_EQ(j["abs"], false);
  EXPECT_EQ(j["surface"], "wet");
  EXPECT_EQ(j["wheel_locked"], true);
  EXPECT_EQ(j["cycles"], 0);
  EXPECT_EQ(j["stopped"], true);
  EXPECT_GT(j["stopping_distance_m"].get<double>(), 0.0);
  EXPECT_TRUE(j["max_lambda_after_first_cycle"].is_null());
  const hotlap::CsvTable t = hotlap::ReadCsv(dir_ / "a" / "abs.csv");
  EXPECT_TRUE(std::isnan(t.values[t.ColumnIndex("abs_state")][0]));  // no controller

  ASSERT_EQ(Run("--out " + (dir_ / "b").string() + " --json " + json.string() + " --drum"), 0)
      << err_;
  j = Json(json);
  EXPECT_EQ(j["vehicle"], "drum");
  EXPECT_NEAR(j["final_speed_mps"].get<double>(), 11.165, 1e-9);
  EXPECT_GT(j["energy"]["drum_work_J"].get<double>(), 0.0);
}

// --set replaces numbers of the ABS file (a tuning study without copies of the file): the
// run follows the new value, the JSON records it, and a key the file does not have or a value
// outside the field's range is refused as the file's own would be, before anything is written.
TEST_F(AbsCommandTest, SetOverridesTheFilesNumbers) {
  const fs::path json = dir_ / "abs.json";
  ASSERT_EQ(Run("--out " + (dir_ / "a").string() + " --json " + json.string()), 0) << err_;
  const nlohmann::json plain = Json(json);
  EXPECT_EQ(plain["overrides"], nlohmann::json::object());
  // Reapplying at half the last release pressure rather than 95%: other cycles.
  ASSERT_EQ(Run("--out " + (dir_ / "b").string() + " --json " + json.string() +
                " --set controller.reapply_fraction=0.5 --set hydraulics.delay_s=0.02"),
            0)
      << err_;
  const nlohmann::json set = Json(json);
  EXPECT_DOUBLE_EQ(set["overrides"]["controller.reapply_fraction"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(set["overrides"]["hydraulics.delay_s"].get<double>(), 0.02);
  EXPECT_NE(set["distance_m"].get<double>(), plain["distance_m"].get<double>());
  EXPECT_TRUE(
      Contains(ReadTextFile(dir_ / "b" / "abs_report.html"), "controller.reapply_fraction=0.5"));

  const fs::path out = dir_ / "refused";
  EXPECT_EQ(Run("--out " + out.string() + " --set controller.reaply_fraction=0.5"), 2);
  EXPECT_TRUE(Contains(err_, "override 'controller.reaply_fraction=0.5'")) << err_;
  EXPECT_TRUE(Contains(err_, "controller.reapply_fraction")) << err_;  // the closest key
  EXPECT_EQ(Run("--out " + out.string() + " --set controller.reapply_fraction=1.5"), 2);
  EXPECT_TRUE(Contains(err_, "reapply_fraction")) << err_;
  EXPECT_TRUE(Contains(err_, "[0, 1)")) << err_;
  EXPECT_EQ(Run("--out " + out.string() + " --set controller.reapply_fraction"), 2);
  EXPECT_TRUE(Contains(err_, "expected KEY=VALUE")) << err_;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(AbsCommandTest, BadInputFailsCleanly) {
  const fs::path out = dir_ / "run";
  EXPECT_EQ(Run("--out " + out.string() + " --surface ice"), 2);
  EXPECT_EQ(err_.rfind("hotlap: error: ", 0), 0u) << err_;
  EXPECT_TRUE(Contains(err_, "no surface 'ice'"));
  EXPECT_FALSE(fs::exists(out / "abs.csv"));
  const fs::path bad = dir_ / "bad.yaml";
  hotlap::test::WriteTextFile(bad, "name: x\nmodel: abs_quarter_car\n");
  EXPECT_EQ(Run("--out " + out.string() + " --config " + bad.string()), 2);
  EXPECT_TRUE(Contains(err_, "bad.yaml"));
  EXPECT_EQ(Run("--out " + out.string() + " --json " + (dir_ / "no" / "x.json").string()), 2);
  EXPECT_TRUE(Contains(err_, "--json"));
  EXPECT_NE(Run("--out " + out.string() + " --speed-mps -3"), 0);
}

}  // namespace
