// End-to-end test of `hotlap fe`: every step up to a short ABS stop on a very coarse, mass-scaled
// copy of the shipped configuration (the mesh and step lengths replaced in the text of
// data/fe/paper_235_75r15.yaml, everything else as shipped); the documented outputs exist, the
// JSON holds the documented keys, and a bad configuration gives one clear message and exit code 2.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "child_lines.h"
#include "fe/coarse_fe_config.h"
#include "hotlap/fe/explicit_solver.h"
#include "report/chromium.h"
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
    // Passive OpenMP waiting: under ctest -j the cores are shared, and spinning threads would
    // wait for each other's time slices (docs/validation/fe-tyre.md, Speed).
    const int status = std::system(("OMP_WAIT_POLICY=passive " + std::string(HOTLAP_BINARY) +
                                    " fe " + args + " >" + out.string() + " 2>" + err.string())
                                       .c_str());
    out_ = ReadTextFile(out);
    err_ = ReadTextFile(err);
    return WEXITSTATUS(status);
  }
  // The shipped file with a coarse mesh, mass scaling and short steps (coarse_fe_config.h).
  fs::path CoarseConfig() { return hotlap::test::WriteCoarseFeConfig(dir_ / "coarse.yaml"); }

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
  for (const char* f : {"inflate_history.csv", "footprint_history.csv", "roll_history.csv",
                        "abs_history.csv", "footprint_pressure.csv", "footprint_pressure.svg",
                        "inflate_002.vtu", "abs_002.vtu", "abs_report.html"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(json));
  for (const char* k : {"mesh", "inflate", "footprint", "roll", "abs", "performance"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  // Every step reports its largest cord strain, within what the stable step allows for.
  for (const char* k : {"inflate", "footprint", "roll", "abs"}) {
    EXPECT_GT(j[k]["max_cord_strain"].get<double>(), 0.0) << k;
    EXPECT_LT(j[k]["max_cord_strain"].get<double>(), hotlap::fe::kCordStrainAllowance) << k;
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
  // 20 ms is shorter than a control cycle: the cycle figures are there, and null.
  EXPECT_TRUE(j["abs"]["cycle_starts_s"].is_array());
  EXPECT_EQ(j["abs"]["cycle_starts_s"].size(), 0u);
  EXPECT_EQ(j["abs"]["control_cycles"].get<int>(), 0);
  EXPECT_EQ(j["abs"]["cycles_per_s"].get<double>(), 0.0);
  for (const char* k : {"first_cycle_start_s", "second_cycle_start_s", "abs_exit_s",
                        "max_lambda_after_first_cycle", "fraction_time_lambda_below_0_135"}) {
    ASSERT_TRUE(j["abs"].contains(k)) << k;
    EXPECT_TRUE(j["abs"][k].is_null()) << k;
  }
  const std::string html = ReadTextFile(out / "abs_report.html");
  for (const char* title : {"cf. 002 Fig. 8", "cf. 002 Fig. 9", "cf. 002 Fig. 10",
                            "cf. 002 Fig. 11", "Energy balance error"}) {
    EXPECT_TRUE(Contains(html, title)) << title;
  }
  // Both lumped runs: the FE file's ABS file and the lumped quarter car's own tuning.
  EXPECT_TRUE(j["abs"].contains("lumped"));
  ASSERT_TRUE(j["abs"].contains("lumped_own_tuning"));
  EXPECT_TRUE(Contains(j["abs"]["lumped_own_tuning"]["config_file"].get<std::string>(),
                       "data/abs/paper.yaml"));
  for (const char* label : {"slip (lumped, same ABS file)", "slip (lumped, own tuning)"}) {
    EXPECT_TRUE(Contains(html, label)) << label;
  }
  // The page draws its six charts without a script error.
  fs::create_directories(dir_ / "chromium");
  const auto status = hotlap::test::RenderInChromium(out / "abs_report.html", dir_ / "chromium");
  EXPECT_TRUE(hotlap::test::RenderedCleanly(status, 6));
}

// `hotlap fe abs --ensemble`: the steps before the braking once, then the members' short stops,
// each figure's statistic in the JSON (one member's figures per member, in order), one CSV row per
// member, the report with the band; an ensemble with a checkpoint option is refused before
// anything is written.
TEST_F(FeCommandTest, EnsembleWritesEachFiguresStatisticAndRefusesCheckpoints) {
  const fs::path cfg = CoarseConfig(), out = dir_ / "ens", json = dir_ / "ens.json";
  ASSERT_EQ(
      Run("abs --config " + cfg.string() + " --out " + out.string() + " --json " + json.string() +
          " --duration-s 0.02 --ensemble 3 --perturb sum-order --threads 2 --abs-set "
          "controller.reapply_fraction=0.9"),
      0)
      << err_;
  EXPECT_TRUE(Contains(out_, "abs ensemble: 3 members, perturbation sum-order")) << out_;
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(json));
  ASSERT_TRUE(j.contains("abs_ensemble")) << j.dump();
  EXPECT_FALSE(j.contains("abs"));
  const nlohmann::json& e = j["abs_ensemble"];
  EXPECT_EQ(e["members"].get<int>(), 3);
  EXPECT_EQ(e["perturbation"].get<std::string>(), "sum-order");
  EXPECT_EQ(e["member_figures"].size(), 3u);
  for (const char* k : {"fraction_below_0_135", "slip_p99", "slip_mean", "slip_max", "cycles_per_s",
                        "first_release_s", "distance_m", "mean_deceleration_mps2"}) {
    ASSERT_TRUE(e["figures"].contains(k)) << k;
    for (const char* s : {"n", "mean", "standard_error", "sd", "min", "max", "unit"}) {
      EXPECT_TRUE(e["figures"][k].contains(s)) << k << " " << s;
    }
  }
  // 20 ms: no cycle, so no window after the first; the distance is every member's.
  EXPECT_EQ(e["figures"]["fraction_below_0_135"]["n"].get<int>(), 0);
  EXPECT_EQ(e["figures"]["distance_m"]["n"].get<int>(), 3);
  EXPECT_GT(e["figures"]["distance_m"]["mean"].get<double>(), 0.2);
  EXPECT_TRUE(e.contains("lumped"));
  EXPECT_TRUE(e.contains("lumped_own_tuning"));
  EXPECT_DOUBLE_EQ(j["abs_overrides"]["controller.reapply_fraction"].get<double>(), 0.9);
  EXPECT_TRUE(Contains(ReadTextFile(out / "abs_ensemble.csv"), "member,control_cycles,"));
  const std::string html = ReadTextFile(out / "abs_report.html");
  EXPECT_TRUE(Contains(html, "Ensemble figures"));
  EXPECT_TRUE(Contains(html, "lumped, own tuning"));
  // The page draws its three charts (torque, speeds, slip: each a band) without a script error.
  fs::create_directories(dir_ / "chromium");
  const auto status = hotlap::test::RenderInChromium(out / "abs_report.html", dir_ / "chromium");
  EXPECT_TRUE(hotlap::test::RenderedCleanly(status, 3));

  // A shard (--first-member): its member is the same bits as that member of the whole ensemble.
  const fs::path shard_json = dir_ / "shard.json";
  ASSERT_EQ(Run("abs --config " + cfg.string() + " --out " + (dir_ / "shard").string() +
                " --json " + shard_json.string() +
                " --duration-s 0.02 --ensemble 1 --first-member 2 --perturb sum-order "
                "--abs-set controller.reapply_fraction=0.9"),
            0)
      << err_;
  const nlohmann::json shard = nlohmann::json::parse(ReadTextFile(shard_json))["abs_ensemble"];
  EXPECT_EQ(shard["first_member"].get<int>(), 2);
  ASSERT_EQ(shard["member_figures"].size(), 1u);
  EXPECT_EQ(shard["member_figures"][0], e["member_figures"][2]);
  EXPECT_EQ(e["member_figures"][2]["member"].get<int>(), 2);

  const fs::path refused = dir_ / "refused";
  EXPECT_EQ(Run("abs --config " + cfg.string() + " --out " + refused.string() +
                " --ensemble 2 --checkpoint-every-s 0.01"),
            2);
  EXPECT_TRUE(Contains(err_, "--ensemble")) << err_;
  EXPECT_FALSE(fs::exists(refused));
  // A spin member depends on the ensemble's size: no shards of it.
  EXPECT_EQ(Run("abs --config " + cfg.string() + " --out " + refused.string() +
                " --ensemble 2 --first-member 2 --perturb spin"),
            2);
  EXPECT_TRUE(Contains(err_, "--first-member")) << err_;
  EXPECT_FALSE(fs::exists(refused));
}

// A braking step run straight through and one stopped at a checkpoint and continued from it (all
// on 2 threads): the end-of-step checkpoints, which hold the whole state (nodes, rim, energies,
// the ABS controller and hydraulics, the history), are the same bytes, and so are the braking
// histories. Bit-identical because the restart reads every double as its bytes and the same
// thread count sums the element forces in the same order (a restart on another thread count is
// allowed and agrees to round-off; it says so).
TEST_F(FeCommandTest, RunStoppedAtACheckpointAndRestartedEqualsAStraightRun) {
  const fs::path cfg = CoarseConfig(), a = dir_ / "a", b = dir_ / "b", c = dir_ / "c";
  const std::string common = "abs --config " + cfg.string() + " --out ";
  ASSERT_EQ(Run(common + a.string() + " --duration-s 0.03 --checkpoint-every-s 1 --threads 2"), 0)
      << err_;
  EXPECT_TRUE(Contains(err_, "2 threads")) << err_;
  // Stopped at 0.012 s, having checkpointed at 0.005 and 0.010 s and at its end.
  ASSERT_EQ(Run(common + b.string() + " --duration-s 0.012 --checkpoint-every-s 0.005 --threads 2"),
            0)
      << err_;
  ASSERT_EQ(Run(common + c.string() + " --duration-s 0.03 --checkpoint-every-s 1 --threads 2 " +
                "--json " + (dir_ / "c.json").string() + " --restart " +
                (b / "abs_checkpoint.bin").string()),
            0)
      << err_;
  EXPECT_TRUE(Contains(err_, "restarting from")) << err_;
  EXPECT_FALSE(Contains(err_, "fe inflate")) << err_;  // the earlier steps are not rerun
  const std::string straight = ReadTextFile(a / "abs_checkpoint.bin");
  ASSERT_GT(straight.size(), 1000u);
  EXPECT_TRUE(straight == ReadTextFile(c / "abs_checkpoint.bin"));
  EXPECT_EQ(ReadTextFile(a / "abs_history.csv"), ReadTextFile(c / "abs_history.csv"));
  EXPECT_NE(ReadTextFile(a / "abs_history.csv"), ReadTextFile(b / "abs_history.csv"));
  // The restarted run's JSON carries the earlier steps' summary and the whole braking step.
  const nlohmann::json j = nlohmann::json::parse(ReadTextFile(dir_ / "c.json"));
  for (const char* k : {"mesh", "inflate", "footprint", "roll", "abs", "performance"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  // Every step reports its largest cord strain, within what the stable step allows for.
  for (const char* k : {"inflate", "footprint", "roll", "abs"}) {
    EXPECT_GT(j[k]["max_cord_strain"].get<double>(), 0.0) << k;
    EXPECT_LT(j[k]["max_cord_strain"].get<double>(), hotlap::fe::kCordStrainAllowance) << k;
  }
  EXPECT_GT(j["abs"]["max_brake_torque_Nm"].get<double>(), 0.0);
  EXPECT_EQ(j["performance"]["threads"].get<int>(), 2);
}

// Faults survived (issue 25): `kill -9` in the middle of a checkpointed braking step leaves a
// whole checkpoint, the last one the run said it wrote, no older than one checkpoint interval
// behind the run, and the run continued from it ends bit for bit where the run straight through
// ends. The kill waits for an event, not for time: the run's line saying its fifth checkpoint is
// written (of 30), read from its output as it comes.
TEST_F(FeCommandTest, KilledRunRestartsFromItsLastCheckpointLosingAtMostOneInterval) {
  const fs::path cfg = CoarseConfig(), straight = dir_ / "straight", killed = dir_ / "killed",
                 resumed = dir_ / "resumed";
  const std::string common = "abs --config " + cfg.string() + " --duration-s 0.3 --threads 1 ";
  ASSERT_EQ(Run(common + "--out " + straight.string() + " --checkpoint-every-s 1"), 0) << err_;

  // The run to kill, as its own process (exec: the pid is hotlap's, not a shell's), its standard
  // error read line by line.
  const double interval_s = 0.01;
  const int kill_at_checkpoint = 5;
  const fs::path checkpoint = killed / "abs_checkpoint.bin";
  hotlap::test::ChildLines child("exec env OMP_WAIT_POLICY=passive " + std::string(HOTLAP_BINARY) +
                                     " fe " + common + "--out " + killed.string() +
                                     " --checkpoint-every-s 0.01 >/dev/null",
                                 STDERR_FILENO);
  const std::regex written(R"(fe abs: checkpoint written at t = ([0-9.e+-]+) s)");
  std::smatch m;
  int checkpoints = 0;
  while (const std::optional<std::string> line = child.NextLine()) {
    if (std::regex_search(*line, m, written) && ++checkpoints == kill_at_checkpoint) break;
  }
  ASSERT_EQ(checkpoints, kill_at_checkpoint)
      << "the run ended before its checkpoint " << kill_at_checkpoint << ":\n"
      << child.text();
  const int status = child.KillAndWait();
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "the run ended before it was killed";
  ASSERT_TRUE(fs::exists(checkpoint));

  // The latest simulated time the killed run reported reaching, and its last checkpoint.
  double reached_s = 0.0, last_written_s = 0.0;
  const std::string killed_err = child.text();
  const std::regex progress(R"(fe abs: t = ([0-9.]+) s)");
  for (auto it = std::sregex_iterator(killed_err.begin(), killed_err.end(), progress);
       it != std::sregex_iterator(); ++it) {
    reached_s = std::max(reached_s, std::stod((*it)[1]));
  }
  for (auto it = std::sregex_iterator(killed_err.begin(), killed_err.end(), written);
       it != std::sregex_iterator(); ++it) {
    last_written_s = std::max(last_written_s, std::stod((*it)[1]));
  }
  reached_s = std::max(reached_s, last_written_s);
  ASSERT_EQ(Run(common + "--out " + resumed.string() + " --checkpoint-every-s 1 --restart " +
                checkpoint.string()),
            0)
      << err_;
  ASSERT_TRUE(
      std::regex_search(err_, m, std::regex(R"(restarting from '.*' at t = ([0-9.e-]+) s)")))
      << err_;
  const double checkpoint_s = std::stod(m[1]);
  EXPECT_EQ(checkpoint_s, last_written_s)
      << "the surviving checkpoint is not the last one the run wrote";
  EXPECT_GE(checkpoint_s, reached_s - interval_s - 1e-9)
      << "the surviving checkpoint is more than one interval behind the run";
  EXPECT_TRUE(ReadTextFile(straight / "abs_checkpoint.bin") ==
              ReadTextFile(resumed / "abs_checkpoint.bin"));
}

// A damaged checkpoint, one of another configuration, and --restart on another step: exit 2 with
// one message naming the file, and nothing written into the output folder.
TEST_F(FeCommandTest, BadCheckpointIsRefusedAndNothingIsWritten) {
  const fs::path cfg = CoarseConfig(), a = dir_ / "a";
  const std::string common = "abs --config " + cfg.string() + " --out ";
  ASSERT_EQ(Run(common + a.string() + " --duration-s 0.001 --checkpoint-every-s 1"), 0) << err_;
  const fs::path ckpt = a / "abs_checkpoint.bin";
  std::string bytes = ReadTextFile(ckpt);
  ASSERT_GT(bytes.size(), 1000u);
  const auto refused = [&](const std::string& args, const std::string& what) {
    const fs::path out = dir_ / "refused";
    fs::remove_all(out);
    EXPECT_EQ(Run(args + " --out " + out.string() + " --json " + (dir_ / "r.json").string()), 2)
        << args;
    EXPECT_TRUE(Contains(err_, what)) << err_;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << args;
    EXPECT_FALSE(fs::exists(dir_ / "r.json"));
  };
  const std::string base = "abs --config " + cfg.string() + " --duration-s 0.002";
  // One byte in the middle of the state flipped.
  std::string damaged = bytes;
  damaged[damaged.size() / 2] ^= 1;
  std::ofstream(dir_ / "damaged.bin", std::ios::binary) << damaged;
  refused(base + " --restart " + (dir_ / "damaged.bin").string(), "damaged.bin' is damaged");
  // Truncated.
  std::ofstream(dir_ / "short.bin", std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  refused(base + " --restart " + (dir_ / "short.bin").string(), "short.bin' is damaged");
  // Another configuration: the same mesh, another inflation pressure.
  std::string y = ReadTextFile(cfg);
  y = Replace(y, "pressure_kPa: 220 ", "pressure_kPa: 200 ");
  std::ofstream(dir_ / "other.yaml") << y;
  refused("abs --config " + (dir_ / "other.yaml").string() + " --restart " + ckpt.string(),
          "written for another configuration");
  // The same files with a number of the ABS file overridden.
  refused(base + " --restart " + ckpt.string() + " --abs-set controller.reapply_fraction=0.9",
          "written for another configuration");
  // --abs-set: only the abs step, and a key the ABS file has.
  refused("roll --config " + cfg.string() + " --abs-set controller.reapply_fraction=0.9",
          "--abs-set: only `hotlap fe abs`");
  refused(base + " --abs-set controller.reaply_fraction=0.9",
          "override 'controller.reaply_fraction=0.9'");
  // Another mesh.
  std::string m = ReadTextFile(cfg);
  m = Replace(m, "circumferential_elements_rest: 16", "circumferential_elements_rest: 20");
  std::ofstream(dir_ / "mesh.yaml") << m;
  refused("abs --config " + (dir_ / "mesh.yaml").string() + " --restart " + ckpt.string(),
          "written for another mesh");
  refused("roll --config " + cfg.string() + " --restart " + ckpt.string(),
          "only `hotlap fe abs` continues");
  refused(base + " --restart " + (dir_ / "none.bin").string(), "does not exist");
}

TEST_F(FeCommandTest, BadConfigurationNamesTheField) {
  std::string y = ReadTextFile(hotlap::test::SourcePath("data/fe/paper_235_75r15.yaml"));
  y = Replace(y, "thickness_elements: 3 ", "thickness_elements: 2 ");
  const fs::path p = dir_ / "bad.yaml";
  std::ofstream(p) << y;
  EXPECT_EQ(Run("inflate --config " + p.string() + " --out " + (dir_ / "o").string()), 2);
  EXPECT_TRUE(Contains(err_, "mesh.thickness_elements")) << err_;
  EXPECT_TRUE(Contains(err_, "bad.yaml")) << err_;

  // The lumped quarter car's own tuning, optional, must name a file that exists.
  y = Replace(ReadTextFile(hotlap::test::SourcePath("data/fe/paper_235_75r15.yaml")),
              "lumped_config_file: ../abs/paper.yaml", "lumped_config_file: ../abs/none.yaml");
  y = Replace(y, "config_file: ../abs/fe_tyre.yaml",
              "config_file: " + hotlap::test::SourcePath("data/abs/fe_tyre.yaml").string());
  std::ofstream(p) << y;
  EXPECT_EQ(Run("inflate --config " + p.string() + " --out " + (dir_ / "o").string()), 2);
  EXPECT_TRUE(Contains(err_, "abs.lumped_config_file")) << err_;
  EXPECT_TRUE(Contains(err_, "does not exist")) << err_;
  // One that exists but is not valid is refused before any step runs, nothing written.
  std::string lumped = ReadTextFile(hotlap::test::SourcePath("data/abs/paper.yaml"));
  lumped = Replace(lumped, "reapply_fraction: 0.95 ", "reapply_fraction: 1.5 ");
  lumped = Replace(
      lumped, "tyre_file: ", "tyre_file: " + hotlap::test::SourcePath("data/abs").string() + "/");
  lumped = Replace(
      lumped, "brake_file: ", "brake_file: " + hotlap::test::SourcePath("data/abs").string() + "/");
  std::ofstream(dir_ / "bad_lumped.yaml") << lumped;
  std::ofstream(p) << Replace(y, "lumped_config_file: ../abs/none.yaml",
                              "lumped_config_file: " + (dir_ / "bad_lumped.yaml").string());
  EXPECT_EQ(Run("abs --config " + p.string() + " --out " + (dir_ / "o").string()), 2);
  EXPECT_TRUE(Contains(err_, "bad_lumped.yaml")) << err_;
  EXPECT_TRUE(Contains(err_, "controller.reapply_fraction")) << err_;
  EXPECT_FALSE(fs::exists(dir_ / "o"));
}

// The stick spring's penalty factor: outside (0, 1), or above the stability bound
// 4 (1 - time_step_safety^2) = 0.76 (road_contact.h).
TEST_F(FeCommandTest, BadTangentialPenaltyFactorNamesTheFieldAndTheBound) {
  const std::string shipped =
      ReadTextFile(hotlap::test::SourcePath("data/fe/paper_235_75r15.yaml"));
  for (const auto& [value, expected] : {std::pair{"0.9",
                                                  "must be at most 4 (1 - "
                                                  "solver.time_step_safety^2) = 0.76"},
                                        std::pair{"0", "in (0, 1)"}}) {
    const std::string y = Replace(shipped, "tangential_penalty_factor: 0.1",
                                  std::string("tangential_penalty_factor: ") + value);
    const fs::path p = dir_ / "bad.yaml";
    std::ofstream(p) << y;
    EXPECT_EQ(Run("inflate --config " + p.string() + " --out " + (dir_ / "o").string()), 2);
    EXPECT_TRUE(Contains(err_, "road.tangential_penalty_factor")) << err_;
    EXPECT_TRUE(Contains(err_, "bad.yaml")) << err_;
    EXPECT_TRUE(Contains(err_, expected)) << err_;
  }
}

}  // namespace
