// Cautions by Monte Carlo: without cautions every race is the deterministic plan's time exactly;
// the Southern 500's caution model gives the record's count; the draws are repeatable and the
// standard error falls as the races grow; a caution that catches a green stop costs a lap.

#include "hotlap/race/cautions.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"

namespace hotlap::race {
namespace {

FallOff LinearFallOff(double per_lap) {
  FallOff f;
  f.reference_fuel_kg = 25.0;
  f.fuel_s_per_kg = 0.004;
  for (int a = 0; a < 60; ++a) f.lap_time_s.push_back(30.9 + (a == 0 ? 0.8 : 0.0) + per_lap * a);
  return f;
}

TEST(CautionsTest, WithoutCautionsEveryRaceIsTheDeterministicTime) {
  const RaceRules r = SouthernFiveHundred();
  const FallOff f = LinearFallOff(0.03);
  std::vector<std::vector<PitStop>> plans = {OptimalPlan(r, f).stops};
  for (const RacePlan& p : FixedPlans(r, f)) plans.push_back(p.stops);
  for (const auto& stops : plans) {
    const MonteCarloResult mc = SimulatePlan(r, f, stops, CautionModel::Off(), 20);
    EXPECT_EQ(mc.mean_time_s, EvaluatePlan(r, f, stops, "p").race_time_s);
    EXPECT_EQ(mc.standard_error_s, 0.0);
    EXPECT_EQ(mc.mean_cautions, 0.0);
  }
}

TEST(CautionsTest, TheSouthern500ModelGivesTheRecordsCount) {
  const RaceRules r = SouthernFiveHundred();
  const FallOff f = LinearFallOff(0.03);
  const MonteCarloResult mc =
      SimulatePlan(r, f, OptimalPlan(r, f).stops, SouthernFiveHundredCautions(), 2000);
  // 2023: 8 cautions (facts); within 20%.
  EXPECT_NEAR(mc.mean_cautions, 8.0, 1.6);
  EXPECT_GT(mc.mean_time_s, OptimalPlan(r, f).race_time_s);  // slow laps behind the pace car
  EXPECT_GT(mc.standard_error_s, 0.0);
}

TEST(CautionsTest, DrawsRepeatAndTheStandardErrorFalls) {
  const RaceRules r = SouthernFiveHundred();
  const FallOff f = LinearFallOff(0.03);
  const auto stops = OptimalPlan(r, f).stops;
  const CautionModel m = SouthernFiveHundredCautions();
  EXPECT_EQ(SimulatePlan(r, f, stops, m, 50).mean_time_s,
            SimulatePlan(r, f, stops, m, 50).mean_time_s);
  const double se100 = SimulatePlan(r, f, stops, m, 100).standard_error_s;
  const double se1600 = SimulatePlan(r, f, stops, m, 1600).standard_error_s;
  EXPECT_LT(se1600, 0.5 * se100);  // about a quarter
  EXPECT_THROW(SimulatePlan(r, f, stops, m, 0), InputError);
  CautionModel bad = m;
  bad.rate_per_lap = 1.5;
  EXPECT_THROW(SimulatePlan(r, f, stops, bad, 10), InputError);
}

// A green stop on the lap before a caution comes out is caught a lap down: against the same stop
// a lap earlier (both green), the race is one green lap longer (a flat fall-off, fuel weightless)
// and the later stop fills one lap's more fuel.
TEST(CautionsTest, AGreenStopCaughtByACautionCostsALap) {
  RaceRules r = SouthernFiveHundred();
  r.laps = 60;
  r.stage_ends = {};
  FallOff f = LinearFallOff(0.0);
  f.lap_time_s[0] = f.lap_time_s[1];
  f.fuel_s_per_kg = 0.0;
  const CautionModel m = SouthernFiveHundredCautions();
  // A race whose first caution comes out on a lap k from 5 to 50.
  for (uint64_t stream = 0; stream < 200; ++stream) {
    std::vector<int> starts;
    RaceUnderCautions(r, f, {}, m, stream, &starts);
    if (starts.empty() || starts[0] < 5 || starts[0] > 50) continue;
    const int k = starts[0];
    const double caught = RaceUnderCautions(r, f, {{k - 1, Service::kFuelOnly}}, m, stream);
    const double clear = RaceUnderCautions(r, f, {{k - 2, Service::kFuelOnly}}, m, stream);
    // One green lap, and the fill of the one more lap's fuel the later stop puts in.
    EXPECT_NEAR(caught - clear, f.LapTime(5, 25.0) + r.fuel_per_lap_kg / r.fuel_rate_kg_per_s, 1e-6)
        << "caution on lap " << k;
    return;
  }
  FAIL() << "no race with an early caution in 200 draws";
}

// The paired gain: race by race, so a plan against itself gains nothing with no error, and a plan
// always a second ahead gains a second with no error, however much the races themselves spread.
TEST(CautionsTest, ThePairedGainIsRaceByRace) {
  const RaceRules r = SouthernFiveHundred();
  const FallOff f = LinearFallOff(0.03);
  std::vector<double> times;
  SimulatePlan(r, f, OptimalPlan(r, f).stops, SouthernFiveHundredCautions(), 200, &times);
  ASSERT_EQ(times.size(), 200u);
  const MonteCarloResult none = GainOver(times, times);
  EXPECT_EQ(none.mean_time_s, 0.0);
  EXPECT_EQ(none.standard_error_s, 0.0);
  std::vector<double> slower = times;
  for (double& t : slower) t += 1.0;
  EXPECT_NEAR(GainOver(times, slower).mean_time_s, 1.0, 1e-9);
  EXPECT_LT(GainOver(times, slower).standard_error_s, 1e-9);
  EXPECT_THROW(GainOver(times, {1.0}), InputError);
}

}  // namespace
}  // namespace hotlap::race
