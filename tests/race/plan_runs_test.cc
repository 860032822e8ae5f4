// A plan's laps as the tyres see them: each corner's state from the fall-off's laps at its own
// age (the left tyres older after a right-side stop), the wear carried on past the table, and the
// runs between tyre changes (a fuel-only stop does not end one).

#include "hotlap/race/plan_runs.h"

#include <gtest/gtest.h>

#include "race/short_race.h"

namespace hotlap::race {
namespace {

using testing::Linear;
using testing::ShortRace;

// A set whose tyre k wears (k + 1) * 0.01 mm a lap and whose treads warm 1 K a lap from 330 K.
FallOff WithSetLaps(int table = 30) {
  FallOff f = Linear(0.05, table);
  f.right_stop_after_laps = {table};  // right-side stops "driven": old lefts cost nothing
  f.right_stop_lap_time_s = {f.lap_time_s};
  for (int a = 0; a < table; ++a) {
    SetLap s;
    for (size_t k = 0; k < 4; ++k) {
      s.wear_mm[k] = 0.01 * static_cast<double>(k + 1) * (a + 1);
      s.tread_temp[k] = 330.0 + a;
      s.carcass_temp[k] = 340.0 + a;
      s.disc_peak_temp[k] = 800.0 - a;
      s.pressure[k] = 200e3 + 100.0 * a;
    }
    f.set_laps.push_back(s);
  }
  return f;
}

TEST(PlanRunsTest, EachCornerTakesTheLapOfItsOwnAgeAndTheRunsEndAtTyreChanges) {
  RaceRules r = ShortRace();
  r.right_side_stops = true;
  const FallOff f = WithSetLaps();
  // Four tyres after lap 20, fuel only after 35, right sides after 45.
  const RacePlan plan = EvaluatePlan(r, f,
                                     {{20, Service::kFourTyresAndFuel, 0.0},
                                      {35, Service::kFuelOnly, 0.0},
                                      {45, Service::kRightTyresAndFuel, 0.0}},
                                     "test");
  const std::vector<SetLap> laps = PlanLapStates(plan, f);
  ASSERT_EQ(laps.size(), 60u);
  EXPECT_DOUBLE_EQ(laps[0].wear_mm[3], 0.04);            // lap 1: age 0, rr
  EXPECT_DOUBLE_EQ(laps[20].wear_mm[0], 0.01);           // lap 21 on new tyres
  EXPECT_DOUBLE_EQ(laps[44].tread_temp[1], 330.0 + 24);  // lap 45: age 24 (no new tyres at 35)
  EXPECT_DOUBLE_EQ(laps[45].tread_temp[1], 330.0);       // lap 46: new right tyres
  EXPECT_DOUBLE_EQ(laps[45].tread_temp[0], 330.0 + 25);  // the lefts run on
  // Past the 30-lap table (the lefts are 39 laps old on lap 60) the wear grows at the last ten
  // laps' rate and the temperatures hold.
  EXPECT_NEAR(laps[59].wear_mm[2], 0.03 * 40, 1e-12);
  EXPECT_DOUBLE_EQ(laps[59].tread_temp[2], 330.0 + 29);

  const std::vector<PlanRun> runs = PlanRuns(plan, laps);
  ASSERT_EQ(runs.size(), 3u);  // the fuel-only stop ends none
  EXPECT_EQ(runs[0].first_lap, 1);
  EXPECT_EQ(runs[0].last_lap, 20);
  EXPECT_EQ(runs[1].first_lap, 21);
  EXPECT_EQ(runs[1].last_lap, 45);
  EXPECT_EQ(runs[2].fitted, Service::kRightTyresAndFuel);
  EXPECT_EQ(runs[2].last_lap, 60);
  EXPECT_DOUBLE_EQ(runs[0].wear_mm[3], 0.04 * 20);
  EXPECT_DOUBLE_EQ(runs[1].peak_tread_temp[0], 330.0 + 24);
  EXPECT_DOUBLE_EQ(runs[1].peak_disc_temp[0], 800.0);  // the run's first lap is its hottest disc
  EXPECT_DOUBLE_EQ(runs[2].end_pressure[1], 200e3 + 100.0 * 14);
}

TEST(PlanRunsTest, WithoutSetLapsThereIsNothingToSay) {
  const RaceRules r = ShortRace();
  const FallOff f = Linear(0.05);
  const RacePlan plan =
      EvaluatePlan(r, f, {{25, Service::kFuelOnly, 0.0}, {50, Service::kFuelOnly, 0.0}}, "x");
  EXPECT_TRUE(PlanLapStates(plan, f).empty());
  EXPECT_TRUE(PlanRuns(plan, {}).empty());
}

}  // namespace
}  // namespace hotlap::race
