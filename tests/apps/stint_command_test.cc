// `hotlap stint` end to end on a coarse 30 m mesh: two laps, the documented files and JSON keys,
// the channels CSV with a lap column whose laps add up to the JSON's times, and bad options
// refused before any work.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "child_lines.h"
#include "hotlap/common/csv.h"
#include "report/chromium.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;
using test::Contains;

class StintCommandTest : public test::CommandTest {};

TEST_F(StintCommandTest, TwoLapsWriteTheTableTheChannelsTheJsonAndTheReport) {
  const fs::path out = dir() / "stint", json = dir() / "stint.json";
  const test::RunResult r =
      Run("stint --laps 2 --step-m 30 --coarse-step-m 0 --wear-scale 5 --out " + out.string() +
          " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(Contains(r.out, "greedy lap 2 of 2")) << r.out;
  EXPECT_TRUE(Contains(r.out, "managing the stint gains")) << r.out;
  const nlohmann::json j = Json(json);
  EXPECT_EQ(j.at("command"), "stint");
  EXPECT_EQ(j.at("status"), "converged");
  ASSERT_EQ(j.at("laps").size(), 2u);
  ASSERT_EQ(j.at("greedy_laps").size(), 2u);
  double sum = 0.0, greedy = 0.0;
  for (int i = 0; i < 2; ++i) {
    const nlohmann::json& lap = j["laps"][i];
    EXPECT_EQ(lap.at("lap"), i + 1);
    sum += lap.at("lap_time_s").get<double>();
    greedy += j["greedy_laps"][i].at("lap_time_s").get<double>();
    for (const char* c : {"fl", "fr", "rl", "rr"}) {
      for (const char* k :
           {"peak_tread_temp_C", "peak_carcass_temp_C", "peak_disc_temp_C", "min_tread_temp_C",
            "min_carcass_temp_C", "min_disc_temp_C", "wear_mm"}) {
        EXPECT_TRUE(lap.at("corners").at(c).at(k).is_number()) << c << " " << k;
      }
    }
  }
  EXPECT_NEAR(j.at("total_time_s").get<double>(), sum, 1e-6);
  EXPECT_NEAR(j.at("greedy_total_time_s").get<double>(), greedy, 1e-6);
  EXPECT_NEAR(j.at("managing_gain_s").get<double>(), greedy - sum, 1e-6);
  // Wear and fuel carried from lap to lap: more worn and lighter at the end of lap 2.
  EXPECT_GT(j["laps"][1]["corners"]["rr"]["wear_mm"].get<double>(),
            j["laps"][0]["corners"]["rr"]["wear_mm"].get<double>());
  EXPECT_LT(j["laps"][1]["fuel_end_kg"].get<double>(), j["laps"][0]["fuel_end_kg"].get<double>());
  EXPECT_LT(j["laps"][1]["mass_kg"].get<double>(), j["laps"][0]["mass_kg"].get<double>());
  for (const char* k : {"solve_time_s", "ipopt_iterations", "fuel_plan_error_kg"}) {
    EXPECT_TRUE(j.at(k).is_number()) << k;
  }

  // The channels: one row per node of the whole stint, the lap column 1 then 2.
  const CsvTable t = ReadCsv(out / "stint.csv");
  const std::vector<double>& lap = t.values.at(t.ColumnIndex("lap"));
  const std::vector<double>& time = t.values.at(t.ColumnIndex("time_s"));
  EXPECT_EQ(lap.front(), 1.0);
  EXPECT_EQ(lap.back(), 2.0);
  EXPECT_NEAR(time.back() - time.front(), sum, 1e-6);
  // The report: the fall-off, four per-corner charts and the two channel charts, drawn without
  // a script error.
  const std::string page = test::ReadTextFile(out / "stint.html");
  EXPECT_TRUE(Contains(page, "Lap time, lap by lap"));
  EXPECT_TRUE(Contains(page, "greedy (lap by lap)"));
  EXPECT_TRUE(Contains(page, "Cumulative wear"));
  EXPECT_TRUE(test::RenderedCleanly(test::RenderInChromium(out / "stint.html", dir()), 7));
}

// Faults survived (issue 25): `kill -9` during the stint's solve, then the same command again
// with the same --checkpoint folder: the greedy laps come from their files (the same laps, not
// solved again), the stint from the last iterate the killed run said it saved, at most one
// interval (an iteration) behind the furthest iteration it reached, and the run ends converged.
// The kill waits for an event, not for time: the run's line saying its third iterate is saved
// (iteration 3; the solve takes 7), read from its output as it comes. (A checkpoint file that
// kept its first iterate would resume from iteration 1, two behind.)
TEST_F(StintCommandTest, KilledStintResumesFromItsCheckpoints) {
  const int every = 1, kill_at_save = 3;
  const fs::path checkpoints = dir() / "checkpoints", json = dir() / "resumed.json";
  const std::string common =
      "stint --laps 2 --step-m 30 --coarse-step-m 0 --wear-scale 5 --checkpoint " +
      checkpoints.string() + " --checkpoint-every " + std::to_string(every) + " --out ";
  test::ChildLines child("exec " + std::string(HOTLAP_BINARY) + " " + common +
                             (dir() / "killed").string() + " 2>/dev/null",
                         STDOUT_FILENO);
  const std::regex saved_line(R"(the stint: iterate of iteration (\d+) saved)");
  std::smatch m;
  int saves = 0;
  while (const std::optional<std::string> line = child.NextLine()) {
    if (std::regex_search(*line, m, saved_line) && ++saves == kill_at_save) break;
  }
  ASSERT_EQ(saves, kill_at_save) << "the run ended before it saved its iterate " << kill_at_save
                                 << " times:\n"
                                 << child.text();
  const int status = child.KillAndWait();
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "the run ended before it was killed";
  ASSERT_TRUE(fs::exists(checkpoints / "stint_iterate.bin"));
  EXPECT_FALSE(fs::exists(dir() / "killed" / "stint.csv"));
  // What the killed run printed: its greedy laps, and in the stint's solve the iterations it
  // reached (every tenth is printed) and the iterates it saved.
  const std::string killed = child.text();
  std::vector<std::string> greedy;
  const std::regex greedy_line(R"(greedy lap \d of 2: [0-9.]+ s)");
  for (auto it = std::sregex_iterator(killed.begin(), killed.end(), greedy_line);
       it != std::sregex_iterator(); ++it) {
    greedy.push_back(it->str());
  }
  ASSERT_EQ(greedy.size(), 2u) << killed;
  const size_t stint_starts = killed.find("the stint: 2 laps as one problem");
  ASSERT_NE(stint_starts, std::string::npos) << killed;
  const std::string stint_part = killed.substr(stint_starts);
  int reached = 0, last_saved = 0;
  const std::regex iteration_line(R"(iteration +(\d+):)");
  for (auto it = std::sregex_iterator(stint_part.begin(), stint_part.end(), iteration_line);
       it != std::sregex_iterator(); ++it) {
    reached = std::max(reached, std::stoi((*it)[1]));
  }
  for (auto it = std::sregex_iterator(stint_part.begin(), stint_part.end(), saved_line);
       it != std::sregex_iterator(); ++it) {
    last_saved = std::max(last_saved, std::stoi((*it)[1]));
  }
  reached = std::max(reached, last_saved);
  ASSERT_GE(last_saved, kill_at_save * every) << killed;

  const test::RunResult r = Run(common + (dir() / "resumed").string() + " --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  for (const std::string& g : greedy) {
    EXPECT_TRUE(Contains(r.out, g + " (")) << g << "\n" << r.out;  // the same lap time
  }
  EXPECT_TRUE(Contains(r.out, "from its checkpoint")) << r.out;
  ASSERT_TRUE(
      std::regex_search(r.out, m, std::regex(R"(resumed from its checkpoint at iteration (\d+))")))
      << r.out;
  const nlohmann::json j = Json(json);
  EXPECT_EQ(j.at("status"), "converged");
  EXPECT_EQ(j.at("greedy_laps_resumed"), 2);
  const int from = j.at("resumed_from_iteration").get<int>();
  EXPECT_EQ(from, std::stoi(m[1]));
  EXPECT_EQ(from % every, 0);
  EXPECT_EQ(from, last_saved) << "the surviving iterate is not the last one the run saved";
  EXPECT_GE(from, reached - every) << "the surviving iterate is more than one interval behind";
}

TEST_F(StintCommandTest, BadOptionsAreRefusedBeforeAnyWork) {
  const std::string out = " --out " + (dir() / "out").string();
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"stint --laps 0" + out, "--laps"},
           {"stint --wear-scale -1" + out, "--wear-scale"},
           {"stint --fuel-kg 2000" + out, "fuel: 2000 kg"},
           {"stint --thermal-start periodic" + out, "--thermal-start"},
           {"stint --disc-limit-C 300 --step-m 30" + out, "disc starts at"}}) {
    const test::RunResult r = Run(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(Contains(r.err, message)) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir() / "out")) << args;
  }
}

}  // namespace
}  // namespace hotlap
