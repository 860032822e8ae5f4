// End-to-end test of `hotlap fe`: every step up to a short ABS stop on a very coarse, mass-scaled
// copy of the shipped configuration (the mesh and step lengths replaced in the text of
// data/fe/paper_235_75r15.yaml, everything else as shipped); the documented outputs exist, the
// JSON holds the documented keys, and a bad configuration gives one clear message and exit code 2.

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_util.h"

namespace {

namespace fs = std::filesystem;
using hotlap::test::Contains;
using hotlap::test::ReadTextFile;

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class FeCommandTest : public ::testing::Test {
 protected:
  int Run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const int status = std::system(
        (std::string(HOTLAP_BINARY) + " fe " + args + " >" + out.string() + " 2>" + err.string())
            .c_str());
    out_ = ReadTextFile(out);
    err_ = ReadTextFile(err);
    return WEXITSTATUS(status);
  }
  // The shipped file with a coarse mesh, mass scaling and short steps.
  fs::path CoarseConfig() {
    std::string y = ReadTextFile(hotlap::test::SourcePath("data/fe/paper_235_75r15.yaml"));
    y = Replace(y, "meridional_elements_half: 10", "meridional_elements_half: 5");
    y = Replace(y, "circumferential_elements_contact: 24", "circumferential_elements_contact: 8");
    y = Replace(y, "circumferential_elements_rest: 60", "circumferential_elements_rest: 16");
    y = Replace(y, "mass_scaling_min_step_s: 0", "mass_scaling_min_step_s: 5.0e-6");
    y = Replace(y, "config_file: ../abs/paper.yaml",
                "config_file: " + hotlap::test::SourcePath("data/abs/paper.yaml").string());
    y = Replace(y, "damping_per_s: 250", "damping_per_s: 150");  // mass scaled: heavier
    y = Replace(y, "duration_s: 0.1 ", "duration_s: 0.01 ");
    y = Replace(y, "history_interval_s: 1.0e-4", "history_interval_s: 1.0e-3");
    const fs::path p = dir_ / "coarse.yaml";
    std::ofstream(p) << y;
    return p;
  }

  const hotlap::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
  std::string out_, err_;
};

TEST_F(FeCommandTest, AbsStepRunsEveryStepAndWritesTheOutputs) {
  const fs::path cfg = CoarseConfig(), out = dir_ / "out", json = dir_ / "fe.json";
  ASSERT_EQ(Run("abs --config " + cfg.string() + " --out " + out.string() + " --json " +
                json.string() + " --duration-s 0.02"),
            0)
      << err_;
  EXPECT_TRUE(Contains(err_, "fe inflate: t = "));
  EXPECT_TRUE(Contains(err_, "mass scaling added"));
  for (const char* f :
       {"inflate_history.csv", "footprint_history.csv", "roll_history.csv", "abs_history.csv",
        "footprint_pressure.csv", "footprint_pressure.svg", "inflate_002.vtu", "abs_002.vtu"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(json));
  for (const char* k : {"mesh", "inflate", "footprint", "roll", "abs", "performance"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  EXPECT_GT(j["mesh"]["mass_scaling_added_kg"].get<double>(), 0.0);
  // Coarse and short: the reaction is near the load (FeTyre checks it tightly).
  EXPECT_NEAR(j["footprint"]["road_force_z_N"].get<double>(), 4314.0, 0.05 * 4314.0);
  EXPECT_GT(j["inflate"]["outer_radius_after_mm"].get<double>(), 366.75);
  EXPECT_GT(j["roll"]["spin_rad_per_s"].get<double>(), 0.0);
  // Energy balance of the whole run closes to a small fraction of the work done.
  const nlohmann::json& e = j["abs"]["energies"];
  EXPECT_LT(std::abs(e["balance_error_J"].get<double>()),
            1e-3 * e["external_work_J"].get<double>());
  // The driver's pressure reaches the brake after the hydraulic delay (10 ms): torque applied.
  EXPECT_GT(j["abs"]["max_brake_torque_Nm"].get<double>(), 0.0);
  EXPECT_GT(j["abs"]["initial_speed_mps"].get<double>(), 11.0);
}

TEST_F(FeCommandTest, BadConfigurationNamesTheField) {
  std::string y = ReadTextFile(hotlap::test::SourcePath("data/fe/paper_235_75r15.yaml"));
  y = Replace(y, "thickness_elements: 3 ", "thickness_elements: 2 ");
  const fs::path p = dir_ / "bad.yaml";
  std::ofstream(p) << y;
  EXPECT_EQ(Run("inflate --config " + p.string() + " --out " + (dir_ / "o").string()), 2);
  EXPECT_TRUE(Contains(err_, "mesh.thickness_elements")) << err_;
  EXPECT_TRUE(Contains(err_, "bad.yaml")) << err_;
}

}  // namespace
