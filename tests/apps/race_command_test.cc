// End-to-end tests of `hotlap race`: the documented JSON keys, a plan no worse than the fixed
// plans it lists, and bad rules refused with nothing written.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/run_hotlap.h"
#include "test_util.h"

namespace hotlap {
namespace {

namespace fs = std::filesystem;

class RaceCommandTest : public test::CommandTest {};

// A short race on coarse QSS laps (the fall-off from 6 laps at 4 m) keeps the test quick.
const std::string kShort = "race --laps 60 --stages 20,40 --fall-off-laps 6 --step-m 4";

TEST_F(RaceCommandTest, WritesThePlanAndTheFixedPlansItBeats) {
  const fs::path json = dir() / "race.json", html = dir() / "race.html";
  const test::RunResult r = Run(kShort + " --json " + json.string() + " --report " + html.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(test::Contains(r.out, "the optimal plan gains")) << r.out;
  // The report: the plans' table, the fall-off and race charts, the cautions' histogram.
  const std::string page = test::ReadTextFile(html);
  for (const char* part :
       {"The optimal plan and the fixed plans", "Lap time on a set", "Lap times over the race",
        "Cautions in the 10000 simulated races", "The policy under cautions",
        "wear over the race, the optimal plan", "tread temperature (lap mean)"}) {
    EXPECT_TRUE(test::Contains(page, part)) << part;
  }
  const nlohmann::json j = Json(json);
  for (const char* key :
       {"command", "rules", "fall_off", "plan", "fixed_plans", "gain_over_best_fixed_s"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["fall_off"]["lap_time_s"].size(), 6u);
  EXPECT_GT(j["fall_off"]["fuel_s_per_kg"].get<double>(), 0.0);  // fuel is weight
  const double best = j["plan"]["race_time_s"].get<double>();
  ASSERT_FALSE(j["fixed_plans"].empty());
  for (const auto& p : j["fixed_plans"]) {
    EXPECT_LE(best, p["race_time_s"].get<double>() + 1e-6) << p["name"];
  }
  EXPECT_GE(j["gain_over_best_fixed_s"].get<double>(), 0.0);
  // 60 laps on a cell of 56: one stop at least.
  EXPECT_GE(j["plan"]["stops"].size(), 1u);
  // Each run's temperatures and wear: the runs cover the race, each tyre worn and warm.
  const nlohmann::json& runs = j["plan"]["runs"];
  ASSERT_FALSE(runs.empty());
  EXPECT_EQ(runs.front()["first_lap"].get<int>(), 1);
  EXPECT_EQ(runs.back()["last_lap"].get<int>(), 60);
  for (const auto& run : runs) {
    for (int k = 0; k < 4; ++k) {
      EXPECT_GT(run["wear_mm"][k].get<double>(), 0.0);
      EXPECT_GT(run["peak_tread_temp_C"][k].get<double>(), 30.0);
      EXPECT_GT(run["end_pressure_kPa"][k].get<double>(), 100.0);  // hot gauge, 20-48 psi cold
    }
  }
  // Raced under the record's cautions (10,000 races by default): each plan's mean and error, and
  // the paired gain, whose error is far below each plan's own (the same cautions for all).
  const nlohmann::json& mc = j["monte_carlo"];
  EXPECT_EQ(mc["races"].get<int>(), 10000);
  EXPECT_EQ(mc["plans"].size(), 1 + j["fixed_plans"].size());
  EXPECT_LT(mc["gain_over_best_fixed"]["standard_error_s"].get<double>(),
            mc["plans"][0]["standard_error_s"].get<double>());
  // The policy: raced in the same races, never slower on average than the best plan there.
  const nlohmann::json& policy = j["policy"];
  EXPECT_EQ(policy["monte_carlo"]["races"].get<int>(), 10000);
  EXPECT_GE(policy["gain_over_best_plan"]["mean_s"].get<double>(),
            -3.0 * policy["gain_over_best_plan"]["standard_error_s"].get<double>());
  EXPECT_NEAR(policy["monte_carlo"]["mean_time_s"].get<double>(),
              policy["expected_time_s"].get<double>(),
              4.0 * policy["monte_carlo"]["standard_error_s"].get<double>());
  EXPECT_FALSE(policy["caution_chart"].empty());
  // Within the rules in every race: the sets, and no set older than the programme keeps.
  EXPECT_LE(policy["monte_carlo"]["most_tyre_sets"].get<int>(), 13);
  EXPECT_GE(policy["monte_carlo"]["most_tyre_sets"].get<int>(), 1);
  EXPECT_GT(policy["monte_carlo"]["longest_set_laps"].get<int>(), 0);
  EXPECT_LE(policy["monte_carlo"]["longest_set_laps"].get<int>(),
            policy["max_tyre_age_laps"].get<int>());
  // With --cautions off there is nothing random: the means are the plans' times, and the policy
  // is the optimal plan.
  const fs::path off = dir() / "off.json";
  ASSERT_EQ(Run(kShort + " --cautions off --races 3 --json " + off.string()).exit_code, 0);
  const nlohmann::json o = Json(off);
  EXPECT_EQ(o["monte_carlo"]["plans"][0]["mean_time_s"], o["plan"]["race_time_s"]);
  EXPECT_EQ(o["monte_carlo"]["plans"][0]["standard_error_s"].get<double>(), 0.0);
  EXPECT_NEAR(o["policy"]["expected_time_s"].get<double>(), o["plan"]["race_time_s"].get<double>(),
              1e-4);
  const fs::path none = dir() / "none.json";
  ASSERT_EQ(Run(kShort + " --no-policy --races 0 --json " + none.string()).exit_code, 0);
  EXPECT_TRUE(Json(none)["policy"].is_null());
  EXPECT_TRUE(Json(none)["spot_checks"].is_null());
}

TEST_F(RaceCommandTest, TheSecondRunReadsTheFallOffFromTheCacheAndPlansTheSame) {
  const fs::path cache = dir() / "my cache", first = dir() / "1.json", second = dir() / "2.json";
  const std::string args =
      kShort + " --races 200 --no-policy --cache-dir '" + cache.string() + "' --json ";
  const test::RunResult a = Run(args + first.string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_TRUE(test::Contains(a.out, "1 of 3: 6 laps on a new set...")) << a.out;  // progress
  EXPECT_TRUE(test::Contains(a.out, "the fall-off driven (and cached) in")) << a.out;
  const test::RunResult b = Run(args + second.string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_TRUE(test::Contains(b.out, "the fall-off read from the cache in")) << b.out;
  EXPECT_FALSE(test::Contains(b.out, "1 of 3")) << b.out;
  const nlohmann::json ja = Json(first), jb = Json(second);
  EXPECT_FALSE(ja["fall_off"]["from_cache"].get<bool>());
  EXPECT_TRUE(jb["fall_off"]["from_cache"].get<bool>());
  EXPECT_EQ(ja["fall_off"]["cache_file"], jb["fall_off"]["cache_file"]);
  EXPECT_EQ(ja["fall_off"]["lap_time_s"], jb["fall_off"]["lap_time_s"]);
  EXPECT_EQ(ja["plan"], jb["plan"]);
  EXPECT_EQ(ja["monte_carlo"], jb["monte_carlo"]);
  // A cache whose first lap the car no longer drives (the models changed under the same files)
  // is not believed: the laps are driven again and the file replaced.
  const fs::path file = ja["fall_off"]["cache_file"].get<std::string>();
  std::string text = test::ReadTextFile(file);
  const size_t at = text.find("\nlap_time_s 6 ") + 14;
  text.replace(at, 2, "29");  // 31.3... s -> 29.3... s
  std::ofstream(file, std::ios::trunc) << text;
  const test::RunResult stale = Run(args + second.string());
  EXPECT_TRUE(test::Contains(stale.out, "the fall-off driven (and cached) in")) << stale.out;
  EXPECT_EQ(Json(second)["plan"], ja["plan"]);
  EXPECT_EQ(Run(args + second.string()).out.find("read from the cache") != std::string::npos, true);
  // Another setting of the laps is another key; --no-cache neither reads nor writes.
  const test::RunResult c =
      Run("race --laps 60 --stages 20,40 --fall-off-laps 7 --step-m 4 --races 0 --no-policy "
          "--cache-dir '" +
          cache.string() + "'");
  EXPECT_TRUE(test::Contains(c.out, "the fall-off driven (and cached) in")) << c.out << c.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(cache), fs::directory_iterator()), 2);
  const test::RunResult d = Run(kShort + " --races 0 --no-policy --no-cache");
  EXPECT_TRUE(test::Contains(d.out, "the fall-off driven in")) << d.out;
}

TEST_F(RaceCommandTest, RightSideStopsDriveTheirOwnLapsAndAreCheckedAgainstThem) {
  const fs::path json = dir() / "rights.json";
  const test::RunResult r =
      Run("race --laps 60 --stages 20,40 --fall-off-laps 16 --step-m 4 "
          "--races 200 --no-policy --right-side-stops --json " +
          json.string() + " --report " + (dir() / "rights.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::Contains(r.out, "right-side stops allowed")) << r.out;
  const nlohmann::json j = Json(json);
  EXPECT_TRUE(j["rules"]["right_side_stops"].get<bool>());
  ASSERT_EQ(j["fall_off"]["right_side_stops"].size(), 4u);  // after 4, 8, 12 and 16 laps
  EXPECT_EQ(j["fall_off"]["right_side_stops"][0]["after_laps"].get<int>(), 4);
  EXPECT_EQ(j["fall_off"]["right_side_stops"][3]["lap_time_s"].size(), 16u);
  const nlohmann::json& check = j["side_check"];
  EXPECT_EQ(check["laps_before"].get<int>(), 6);
  EXPECT_EQ(check["driven_lap_time_s"].size(), 16u);
  EXPECT_LT(check["max_abs_difference_s"].get<double>(), 0.1);
  // The fixed plan that alternates right sides and four tyres is among those tried.
  bool alternating = false;
  for (const auto& p : j["fixed_plans"]) alternating |= p["name"] == "rights between";
  EXPECT_TRUE(alternating);
  EXPECT_TRUE(Json(dir() / "rights.json")["plan"].contains("optimality_gap_s"));
  // The report draws the driven stops and the check.
  const std::string page = test::ReadTextFile(dir() / "rights.html");
  EXPECT_TRUE(test::Contains(page, "new right-side tyres after 4 laps on the set"));
  EXPECT_TRUE(test::Contains(page, "driven (QSS)"));
}

TEST_F(RaceCommandTest, SpotChecksSolveTheOptimalLapFromTheFallOffsStates) {
  const fs::path json = dir() / "spots.json";
  // Ages 1 and 2: the second solve starts from the first's lap and converges from it (59
  // iterations against 81; from age 1 to age 5 the start is given up after 150 and the lap
  // solved from the guess, 194 in all: the fallback has its own tests, FallbackStartTest).
  const test::RunResult r = Run(kShort +
                                " --races 0 --no-policy --spot-checks 1,2 --spot-check-step-m 20 "
                                "--json " +
                                json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::Contains(r.out, "optimal-lap spot checks")) << r.out;
  const nlohmann::json j = Json(json);
  const nlohmann::json& spots = j["spot_checks"];
  EXPECT_EQ(spots["step_m"].get<double>(), 20.0);
  ASSERT_EQ(spots["checks"].size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const nlohmann::json& c = spots["checks"][i];
    EXPECT_TRUE(c["converged"].get<bool>()) << i;
    // The QSS lap is the fall-off's; the minimum-time lap from the same state is faster (the
    // QSS driver keeps to a fixed line and quasi-steady limits), by under two and a half seconds.
    EXPECT_EQ(c["qss_lap_time_s"], j["fall_off"]["lap_time_s"][c["age_laps"].get<int>()]);
    EXPECT_GT(c["difference_s"].get<double>(), 0.5) << i;
    EXPECT_LT(c["difference_s"].get<double>(), 2.5) << i;
    for (const char* key : {"qss_mean_tread_temp_C", "optimal_mean_tread_temp_C"}) {
      EXPECT_GT(c[key].get<double>(), 40.0) << key;
      EXPECT_LT(c[key].get<double>(), 130.0) << key;
    }
  }
  // On the cold second lap the optimal lap slides its tyres into their window: hotter treads and
  // more grip than the QSS lap from the same start (80.8 against 66.2 degC measured).
  const nlohmann::json& cold = spots["checks"][0];
  EXPECT_GT(cold["optimal_mean_tread_temp_C"].get<double>(),
            cold["qss_mean_tread_temp_C"].get<double>() + 5.0);
  EXPECT_GT(cold["optimal_mean_grip_factor"].get<double>(),
            cold["qss_mean_grip_factor"].get<double>());
  EXPECT_NEAR(spots["optimal_fall_off_s"].get<double>(),
              spots["checks"][1]["optimal_lap_time_s"].get<double>() -
                  spots["checks"][0]["optimal_lap_time_s"].get<double>(),
              1e-6);
}

TEST_F(RaceCommandTest, BadRulesFailCleanlyWithoutOutput) {
  const fs::path json = dir() / "bad.json";
  for (const auto& [args, message] :
       {std::pair{std::string("race --laps 0"), "laps 0 must be > 0"},
        std::pair{std::string("race --fuel-capacity-kg 0.5"), "less than one lap's burn"},
        std::pair{std::string("race --pit-loss-s -1"), "pit loss -1 s"},
        std::pair{std::string("race --stages 400"), "--stages"},
        std::pair{std::string("race --tyre-sets 0"), "tyre sets 0"},
        std::pair{std::string("race --cautions 1.5"), "must be in [0, 1]"},
        std::pair{std::string("race --cautions often"), "'record' or 'off'"},
        std::pair{std::string("race --races -1"), "Monte Carlo races -1"},
        std::pair{std::string("race --fuel-units-per-lap 0"), "fuel units a lap"},
        std::pair{std::string("race --right-side-stops --right-tyre-service-s -2"),
                  "right-side tyre service -2 s"},
        std::pair{std::string("race --spot-checks 60"), "--spot-checks '60': ages"},
        std::pair{std::string("race --spot-checks 5,3"), "increasing"},
        std::pair{std::string("race --spot-checks 2,x"), "--spot-checks"},
        std::pair{std::string("race --spot-check-step-m 0.5"), "--spot-check-step-m 0.5"}}) {
    const test::RunResult r = Run(args + " --json " + json.string());
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(test::Contains(r.err, message)) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(json)) << args;
  }
}

}  // namespace
}  // namespace hotlap
