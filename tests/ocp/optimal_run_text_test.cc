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
  EXPECT_EQ(OptionalText(std::nullopt, "{:.1f}"), "-");
  EXPECT_EQ(OptionalText(1.26, "{:.1f}"), "1.3");
}

}  // namespace
}  // namespace hotlap::ocp
