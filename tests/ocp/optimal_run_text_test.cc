// What the optimal-lap commands print of hand-made laps: a lap's summary lines and what the disc
// limit costs.

#include "hotlap/ocp/optimal_run_text.h"

#include <gtest/gtest.h>

#include "ocp/solved_lap_example.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

TEST(SolvedLapText, SaysTheFiguresTurnsAndCorners) {
  const std::string t = SolvedLapText(testing::MakeExampleSolvedLap("optimal lap", 30.0), "warm");
  for (const char* line :
       {"  lap 30.000 s, top speed 70.00 m/s, slowest 60.00 m/s, front discs peak 480.0 degC\n",
        "  thermal start warm (4 QSS laps): carcass fl/fr/rl/rr 70/70/70/70 degC, discs "
        "400/400/400/400 degC\n",
        "  brake work 2500 kJ, of it against the engine (drive above 2%) 0.00 kJ\n",
        "  turn 1: lift at 120 m, brake at - m, slowest 60.00 m/s at 100 m\n",
        "  corner    disc pk C   tread pk C    wear mm\n",
        "  fr            481.0         95.5    0.01100\n"}) {
    EXPECT_TRUE(test::Contains(t, line)) << line;
  }
  EXPECT_EQ(t.back(), '\n');
}

TEST(SensitivitiesText, RanksTheStepsByTheirEffect) {
  SolvedLap lap = testing::MakeExampleSolvedLap("optimal lap", 30.0);
  EXPECT_EQ(SensitivitiesText(lap), "");
  const auto& all = CrewChiefParameters();
  lap.sensitivities = {{all[3], 303.4, 0.3034, -5.255e-5}, {all.back(), 1542.0, 1.542, 4.067e-3}};
  const std::string t = SensitivitiesText(lap);
  const size_t mass = t.find("+10 kg chassis mass (fuel):"), rr = t.find("+1 psi right-rear");
  ASSERT_NE(mass, std::string::npos) << t;
  ASSERT_NE(rr, std::string::npos) << t;
  EXPECT_LT(mass, rr);  // the larger effect first
  EXPECT_TRUE(test::Contains(t, "+40.670 ms   (+4.067 ms per kg, at 1542 kg)")) << t;
  EXPECT_TRUE(test::Contains(t, "-0.362 ms   (-0.05255 ms per kPa, at 303.4 kPa)")) << t;
}

TEST(DiscLimitCostText, SaysWhatTheLimitCosts) {
  const SolvedLap free = testing::MakeExampleSolvedLap("no limit", 30.0);
  SolvedLap limited = testing::MakeExampleSolvedLap("discs <= 500 degC", 30.25, 500.0);
  limited.approaches[0].brake_m = 130.0;
  EXPECT_EQ(DiscLimitCostText(free, limited),
            "the discs <= 500 degC limit costs 0.250 s (250 ms); top speed 70.00 -> 70.00 m/s\n"
            "  turn 1: lift 120 -> 120 m, brake - -> 130 m\n");
  EXPECT_EQ(LimitCostSensitivitiesText(free, limited), "");  // none asked
  EXPECT_EQ(OptionalText(std::nullopt, "{:.1f}"), "-");
  EXPECT_EQ(OptionalText(1.26, "{:.1f}"), "1.3");
}

TEST(LimitCostSensitivities, RankTheStepsByTheirEffectOnTheCost) {
  const auto& all = CrewChiefParameters();
  SolvedLap free = testing::MakeExampleSolvedLap("no limit", 30.0);
  SolvedLap limited = testing::MakeExampleSolvedLap("discs <= 500 degC", 30.25, 500.0);
  // The mass costs both laps alike (+0.2 ms of the cost a step); the right-rear pressure helps the
  // limited lap 1.5 ms more, so it leads.
  free.sensitivities = {{all.back(), 1542.0, 1.542, 4.0e-3}, {all[3], 303.4, 0.3034, -1.0e-5}};
  limited.sensitivities = {{all[3], 303.4, 0.3034, -1.0e-5 - 1.5e-3 / all[3].typical_step},
                           {all.back(), 1542.0, 1.542, 4.02e-3}};
  const std::vector<LimitCostSensitivity> both = LimitCostSensitivities(free, limited);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].free->parameter.key, all[3].key);
  EXPECT_NEAR(both[0].typical_cost_effect_s(), -1.5e-3, 1e-12);
  EXPECT_NEAR(both[1].d_cost_per_unit(), 2e-5, 1e-12);
  const std::string t = DiscLimitCostText(free, limited);
  EXPECT_TRUE(test::Contains(t, "what each step does to the discs <= 500 degC limit's cost")) << t;
  EXPECT_TRUE(test::Contains(t, "-1.500 ms   (free -0.069, limited -1.569 ms)")) << t;
  EXPECT_TRUE(test::Contains(t, "+0.200 ms   (free +40.000, limited +40.200 ms)")) << t;
  EXPECT_LT(t.find("right-rear"), t.find("chassis mass"));
  limited.sensitivities.pop_back();  // a parameter only one lap has is left out
  EXPECT_EQ(LimitCostSensitivities(free, limited).size(), 1u);
}

}  // namespace
}  // namespace hotlap::ocp
