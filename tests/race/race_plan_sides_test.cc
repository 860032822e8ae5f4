// Right-side stops: the two-age lap time against hand-computed values, the dynamic programme over
// both sides' ages against brute force on a short race (and its Lagrangian bound where the tyre
// sets bind), the plan that takes right sides when the left tyres barely wear, and the Monte
// Carlo that races such a plan as the plan's own arithmetic does.

#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/race/cautions.h"
#include "hotlap/race/race_plan.h"
#include "race/short_race.h"

namespace hotlap::race {
namespace {

using testing::BruteForce;
using testing::Linear;
using testing::ShortRace;

// The linear set with right-side stops "driven" after 10 and 20 laps: new right tyres lose
// `per_lap` a lap as the set does; each lap of the left tyres' extra age costs `left_per_lap`.
FallOff WithSides(double per_lap, double left_per_lap) {
  FallOff f = Linear(per_lap);
  for (int after : {10, 20}) {
    f.right_stop_after_laps.push_back(after);
    f.right_stop_lap_time_s.push_back(f.lap_time_s);
    for (double& t : f.right_stop_lap_time_s.back()) t += left_per_lap * after;
  }
  return f;
}

RaceRules WithRightSideStops() {
  RaceRules r = ShortRace();
  r.right_side_stops = true;
  r.right_tyre_service_s = 5.0;
  r.fuel_rate_kg_per_s = 10.0;  // the tyres, not the fuel, set the service time
  return r;
}

constexpr std::initializer_list<Service> kAllServices = {
    Service::kFuelOnly, Service::kFourTyresAndFuel, Service::kRightTyresAndFuel};

int RightSideStops(const RacePlan& plan) {
  int n = 0;
  for (const PitStop& s : plan.stops) n += s.service == Service::kRightTyresAndFuel;
  return n;
}

TEST(RightSideStopTest, TheTwoAgeLapTimeInterpolatesTheDrivenStops) {
  FallOff f = Linear(0.05);
  EXPECT_THROW(f.LapTime(12, 4, 12.0), InputError);  // no right-side stops driven
  EXPECT_EQ(f.LapTime(7, 7, 14.0), f.LapTime(7, 14.0));
  f.right_stop_after_laps = {10, 20};
  f.right_stop_lap_time_s = {f.lap_time_s, f.lap_time_s};
  for (double& t : f.right_stop_lap_time_s[0]) t += 0.4;  // 10 laps older lefts: +0.4 s
  for (double& t : f.right_stop_lap_time_s[1]) t += 0.6;  // 20 laps: +0.6 s
  // Right tyres 4 laps old (30.2 s at the reference fuel), the lefts 5, 15 and 30 laps older.
  EXPECT_NEAR(f.LapTime(9, 4, 12.0), 30.2 + 0.2, 1e-12);          // halfway to the first stop
  EXPECT_NEAR(f.LapTime(19, 4, 12.0), 30.2 + 0.5, 1e-12);         // halfway between the two
  EXPECT_NEAR(f.LapTime(34, 4, 12.0), 30.2 + 0.8, 1e-12);         // the last two carried on
  EXPECT_NEAR(f.LapTime(19, 4, 14.0), 30.2 + 0.5 + 0.06, 1e-12);  // and the fuel weighs
  EXPECT_THROW(f.LapTime(4, 9, 12.0), InputError);                // the lefts the younger
}

TEST(RightSideStopTest, TheProgrammeEqualsBruteForceOnAShortRace) {
  for (double left_per_lap : {0.0, 0.01, 0.05}) {
    const RaceRules r = WithRightSideStops();
    const FallOff f = WithSides(0.08, left_per_lap);
    // Ages kept to the race's length, as brute force keeps them (left tyres that cost nothing
    // may run the whole race).
    const RacePlan plan = OptimalPlanWithRightSideStops(r, f, r.laps);
    EXPECT_NEAR(plan.race_time_s, BruteForce(r, f, kAllServices), 1e-9) << left_per_lap;
    EXPECT_EQ(plan.optimality_gap_s, 0.0);
    // By default the ages are kept to two fuel windows (50 laps here): a left set of the whole
    // race is then out of reach, and the plan changes it once.
    if (left_per_lap == 0.0) {
      EXPECT_EQ(RightSideStops(plan), static_cast<int>(plan.stops.size()));
      const RacePlan capped = OptimalPlan(r, f);
      EXPECT_EQ(RightSideStops(capped) + 1, static_cast<int>(capped.stops.size()));
      EXPECT_GT(capped.race_time_s, plan.race_time_s);
    }
  }
}

TEST(RightSideStopTest, OldLeftTyresThatCostNothingAreKeptAndOnesThatCostMuchAreNot) {
  const RaceRules r = WithRightSideStops();
  EXPECT_GE(RightSideStops(OptimalPlan(r, WithSides(0.08, 0.0))), 1);
  EXPECT_EQ(RightSideStops(OptimalPlan(r, WithSides(0.08, 0.2))), 0);
  // Four tyres take no longer than two: nothing is gained by keeping the lefts.
  RaceRules same = r;
  same.right_tyre_service_s = same.tyre_service_s;
  EXPECT_EQ(RightSideStops(OptimalPlan(same, WithSides(0.08, 0.01))), 0);
}

TEST(RightSideStopTest, WhereTheSetsBindTheBoundHoldsTheBestPlanWithinThem) {
  RaceRules r = WithRightSideStops();
  const FallOff f = WithSides(0.08, 0.01);
  const int free_sets = OptimalPlanWithRightSideStops(r, f, r.laps).tyre_sets_used;
  ASSERT_GE(free_sets, 3);
  r.tyre_sets = free_sets - 1;
  const RacePlan plan = OptimalPlanWithRightSideStops(r, f, r.laps);
  EXPECT_LE(plan.tyre_sets_used, r.tyre_sets);
  const double best = BruteForce(r, f, kAllServices);
  EXPECT_GE(plan.race_time_s, best - 1e-9);
  EXPECT_LE(plan.race_time_s - plan.optimality_gap_s, best + 1e-9);
}

TEST(RightSideStopTest, RulesOfFourTyresRefuseAPlanWithRightSides) {
  const RaceRules r = ShortRace();
  EXPECT_THROW(EvaluatePlan(r, WithSides(0.08, 0.0),
                            {{20, Service::kRightTyresAndFuel, 0.0}, {40, Service::kFuelOnly, 0.0}},
                            "rights"),
               InputError);
  RaceRules allowed = WithRightSideStops();
  EXPECT_THROW(OptimalPlanWithRightSideStops(allowed, Linear(0.08)), InputError);  // no sides
}

TEST(RightSideStopTest, WithoutCautionsTheMonteCarloRacesThePlanExactly) {
  const RaceRules r = WithRightSideStops();
  const FallOff f = WithSides(0.08, 0.0);
  const RacePlan plan = OptimalPlan(r, f);
  ASSERT_GE(RightSideStops(plan), 1);
  const MonteCarloResult mc = SimulatePlan(r, f, plan.stops, CautionModel::Off(), 3);
  EXPECT_EQ(mc.mean_time_s, plan.race_time_s);
  EXPECT_EQ(mc.standard_error_s, 0.0);
}

}  // namespace
}  // namespace hotlap::race
