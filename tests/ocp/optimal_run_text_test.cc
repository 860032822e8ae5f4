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
