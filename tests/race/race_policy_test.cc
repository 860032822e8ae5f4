// The race policy: without cautions it is the optimal plan; with them its Monte Carlo races
// average its programme's expected time, it is no worse than the fixed plans in the same races,
// it keeps to the fuel and the tyre sets, pits under a caution on an old set and not on a new one,
// and bad options are refused.

#include "hotlap/race/race_policy.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/race/race_plan.h"
#include "race/short_race.h"

namespace hotlap::race {
namespace {

using testing::Linear;
using testing::ShortRace;

CautionModel Frequent() {
  CautionModel m;
  m.rate_per_lap = 0.05;
  m.length_laps = 4;
  m.lap_time_s = 60.0;
  m.fuel_share = 0.4;
  return m;
}

TEST(RacePolicyTest, WithoutCautionsThePolicyIsTheOptimalPlan) {
  for (double per_lap : {0.0, 0.05, 0.2}) {
    const RaceRules r = ShortRace();
    const FallOff f = Linear(per_lap);
    const RacePolicy p = SolvePolicy(r, f, CautionModel::Off(), {.max_tyre_age = r.laps});
    const double plan = OptimalPlan(r, f).race_time_s;
    EXPECT_NEAR(p.expected_time_s, plan, 1e-9) << per_lap;
    EXPECT_NEAR(RaceWithPolicy(p, f, 7).time_s, plan, 1e-9) << per_lap;
  }
}

TEST(RacePolicyTest, ItsRacesAverageItsExpectedTimeAndBeatTheFixedPlans) {
  const RaceRules r = ShortRace();
  FallOff f = Linear(0.08);
  f.restart_penalty_s = 1.5;  // the cooled tyres' laps after a caution
  const CautionModel m = Frequent();
  // Five fuel units a lap: a caution lap's 0.4 exactly, the same race as the plans'.
  const RacePolicy p = SolvePolicy(r, f, m, {.fuel_units_per_lap = 5});
  std::vector<double> times;
  const MonteCarloResult mc = SimulatePolicy(p, f, 4000, &times);
  EXPECT_NEAR(mc.mean_time_s, p.expected_time_s, 4.0 * mc.standard_error_s);
  EXPECT_GT(mc.standard_error_s, 0.0);
  std::vector<PitStop> plan_stops = OptimalPlan(r, f).stops;
  std::vector<std::vector<PitStop>> plans = {plan_stops};
  for (const RacePlan& fixed : FixedPlans(r, f)) plans.push_back(fixed.stops);
  for (const auto& stops : plans) {
    std::vector<double> plan_times;
    SimulatePlan(r, f, stops, m, 4000, &plan_times);
    const MonteCarloResult gain = GainOver(times, plan_times);
    EXPECT_GE(gain.mean_time_s, -3.0 * gain.standard_error_s);
  }
  // Against the plan it starts from, the policy gains: it stops when a caution makes it cheap.
  std::vector<double> plan_times;
  SimulatePlan(r, f, plan_stops, m, 4000, &plan_times);
  const MonteCarloResult gain = GainOver(times, plan_times);
  EXPECT_GT(gain.mean_time_s, 3.0 * gain.standard_error_s);
}

TEST(RacePolicyTest, ItKeepsToTheFuelAndTheTyreSets) {
  RaceRules r = ShortRace();
  r.tyre_sets = 3;
  const FallOff f = Linear(0.3);  // a steep fall-off would take every set it could
  const RacePolicy p = SolvePolicy(r, f, Frequent());
  for (uint64_t i = 0; i < 500; ++i) {
    const PolicyRace race = RaceWithPolicy(p, f, i);  // throws if the fuel ran out
    EXPECT_LE(race.tyre_sets_used, 3) << i;
    EXPECT_GE(race.stops, 2) << i;
  }
}

TEST(RacePolicyTest, UnderACautionItPitsOnAnOldSetAndStaysOutOnANewOne) {
  RaceRules r = ShortRace();
  r.stage_ends.clear();  // no cheap stop ahead to wait for
  const FallOff f = Linear(0.1);
  const RacePolicy p = SolvePolicy(r, f, Frequent());
  // A caution out on lap 15, 14 laps into the set and the cell: the 46 laps left take two more
  // green stops from this cell, one from a full one, so the cheap stop now is worth it; out on
  // lap 2, the 58 left take two stops either way, so staying out is.
  EXPECT_EQ(CautionDecision(p, 15, 14, 14, 1), Decision::kFourTyresAndFuel);
  EXPECT_EQ(CautionDecision(p, 2, 1, 1, 1), Decision::kStayOut);
  EXPECT_EQ(CautionDecision(p, 0, 1, 1, 1), Decision::kNone);
}

TEST(RacePolicyTest, BadOptionsAreRefused) {
  const RaceRules r = ShortRace();
  const FallOff f = Linear(0.0);
  EXPECT_THROW(SolvePolicy(r, f, Frequent(), {.fuel_units_per_lap = 0}), InputError);
  EXPECT_THROW(SolvePolicy(r, f, Frequent(), {.max_tyre_age = -1}), InputError);
  CautionModel m = Frequent();
  m.rate_per_lap = 1.5;
  EXPECT_THROW(SolvePolicy(r, f, m), InputError);
  RaceRules bad = r;
  bad.laps = 0;
  EXPECT_THROW(SolvePolicy(bad, f, Frequent()), InputError);
  // A cell smaller than a lap's burn.
  RaceRules no_fuel = r;
  no_fuel.fuel_capacity_kg = 0.5;
  EXPECT_THROW(SolvePolicy(no_fuel, f, Frequent()), InputError);
}

}  // namespace
}  // namespace hotlap::race
