// The race plan: the dynamic programme against brute force on a short race, the plans it must
// make (fuel only without fall-off; within the fuel and tyre sets), monotone in the pit loss and
// the fall-off, never worse than the fixed plans, and bad rules refused.

#include "hotlap/race/race_plan.h"

#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "race/short_race.h"

namespace hotlap::race {
namespace {

using testing::BruteForce;
using testing::Linear;
using testing::ShortRace;

TEST(RacePlanTest, TheDynamicProgrammeEqualsBruteForceOnAShortRace) {
  for (double per_lap : {0.0, 0.02, 0.08}) {
    const RaceRules r = ShortRace();
    const FallOff f = Linear(per_lap);
    const RacePlan plan = OptimalPlan(r, f);
    EXPECT_NEAR(plan.race_time_s, BruteForce(r, f), 1e-9) << per_lap;
    EXPECT_GE(plan.stops.size(), 2u);
  }
}

TEST(RacePlanTest, WithoutFallOffItStopsForFuelOnlyAndTheFewestTimes) {
  FallOff flat = Linear(0.0);
  flat.lap_time_s[0] = 30.0;  // not even a cold out lap
  const RaceRules r = ShortRace();
  const RacePlan plan = OptimalPlan(r, flat);
  ASSERT_EQ(plan.stops.size(), 2u);  // 60 laps on 25-lap cells
  for (const PitStop& s : plan.stops) EXPECT_EQ(s.service, Service::kFuelOnly);
  EXPECT_EQ(plan.tyre_sets_used, 1);
}

TEST(RacePlanTest, ThePlanKeepsToTheFuelAndTheTyreSets) {
  RaceRules r = ShortRace();
  r.tyre_sets = 2;  // a steep fall-off would take more
  const RacePlan plan = OptimalPlan(r, Linear(0.3));
  EXPECT_LE(plan.tyre_sets_used, 2);
  int since = 0;
  size_t next = 0;
  for (int lap = 1; lap <= r.laps; ++lap) {
    ++since;
    EXPECT_LE(since, r.FuelWindow()) << lap;
    if (next < plan.stops.size() && plan.stops[next].lap == lap) {
      since = 0;
      ++next;
    }
  }
  // The evaluation refuses what the rules do not allow.
  EXPECT_THROW(EvaluatePlan(r, Linear(0.0), {}, "no stop"), InputError);
  EXPECT_THROW(EvaluatePlan(r, Linear(0.0),
                            {{20, Service::kFourTyresAndFuel}, {40, Service::kFourTyresAndFuel}},
                            "three sets"),
               InputError);
}

TEST(RacePlanTest, MorePitLossNeverAddsAStopAndMoreFallOffNeverRemovesOne) {
  for (double per_lap : {0.01, 0.03, 0.06, 0.12}) {
    const RaceRules r = ShortRace();
    RaceRules dear = r;
    dear.pit_loss_s += 10.0;
    dear.caution_pit_loss_s += 10.0;
    const size_t stops = OptimalPlan(r, Linear(per_lap)).stops.size();
    EXPECT_LE(OptimalPlan(dear, Linear(per_lap)).stops.size(), stops) << per_lap;
    EXPECT_GE(OptimalPlan(r, Linear(2.0 * per_lap)).stops.size(), stops) << per_lap;
  }
}

TEST(RacePlanTest, TheOptimalPlanIsNoWorseThanTheFixedOnes) {
  const RaceRules r = ShortRace();
  const FallOff f = Linear(0.05);
  const RacePlan best = OptimalPlan(r, f);
  const std::vector<RacePlan> fixed = FixedPlans(r, f);
  ASSERT_EQ(fixed.size(), 2u);
  for (const RacePlan& p : fixed) EXPECT_LE(best.race_time_s, p.race_time_s + 1e-9) << p.name;
  // A stop at a stage end costs the caution's pit loss.
  EXPECT_NEAR(StopTime(r, 20, Service::kFourTyresAndFuel, 5.0), 12.0 + 11.0, 1e-12);
  EXPECT_NEAR(StopTime(r, 21, Service::kFuelOnly, 20.0), 30.0 + 8.0, 1e-12);
}

TEST(RacePlanTest, BadRulesAreRefused) {
  const auto refused = [](const std::function<void(RaceRules&)>& edit) {
    RaceRules r = ShortRace();
    edit(r);
    EXPECT_THROW(CheckRaceRules(r), InputError);
    EXPECT_THROW(OptimalPlan(r, Linear(0.0)), InputError);
  };
  refused([](RaceRules& r) { r.laps = 0; });
  refused([](RaceRules& r) { r.fuel_capacity_kg = 0.5; });
  refused([](RaceRules& r) { r.pit_loss_s = -1.0; });
  refused([](RaceRules& r) { r.stage_ends = {40, 20}; });
  refused([](RaceRules& r) { r.tyre_sets = 0; });
  EXPECT_NO_THROW(CheckRaceRules(SouthernFiveHundred()));
  EXPECT_EQ(SouthernFiveHundred().laps, 367);
}

TEST(FallOffTest, PastItsTableTheLastTrendCarriesOnAndFuelWeighs) {
  const FallOff f = Linear(0.05, 20);
  EXPECT_NEAR(f.LapTime(5, 12.0), 30.25, 1e-12);
  EXPECT_NEAR(f.LapTime(29, 12.0), 30.0 + 0.05 * 29, 1e-9);
  EXPECT_NEAR(f.LapTime(5, 22.0), 30.25 + 0.3, 1e-12);
  EXPECT_NEAR(f.Spread(), 0.05 * 18, 1e-12);  // the last lap over the fastest, lap 1
}

}  // namespace
}  // namespace hotlap::race
