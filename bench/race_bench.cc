// Race plan speed: the Southern 500 (367 laps, 13 sets, a 56-lap cell) planned by the dynamic
// programme from a fall-off table of 60 laps (a steady 0.04 s a lap, so tyres are worth stopping
// for), and with right-side stops allowed; the policy under the record's cautions (the stochastic
// programme) and 10,000 Monte Carlo races of it. The fall-off's QSS laps are qss_bench's business.
//
// Run: ./build/race_bench

#include <benchmark/benchmark.h>

#include "hotlap/race/race_plan.h"
#include "hotlap/race/race_policy.h"

namespace {

using namespace hotlap;

race::FallOff Table() {
  race::FallOff f;
  f.reference_fuel_kg = 25.0;
  f.fuel_s_per_kg = 0.004;
  for (int a = 0; a < 60; ++a) f.lap_time_s.push_back(30.9 + (a == 0 ? 0.8 : 0.0) + 0.04 * a);
  return f;
}

void BM_RacePlanSouthern500(benchmark::State& state) {
  const race::RaceRules rules = race::SouthernFiveHundred();
  const race::FallOff f = Table();
  for (auto _ : state) benchmark::DoNotOptimize(race::OptimalPlan(rules, f));
  state.counters["stops"] = static_cast<double>(race::OptimalPlan(rules, f).stops.size());
}
BENCHMARK(BM_RacePlanSouthern500)->Unit(benchmark::kMillisecond);

// The same with right-side stops allowed: the programme over both sides' ages (to two fuel
// windows), the left tyres' extra age costing 0.01 s a lap (right-side stops after 15 to 60
// laps "driven").
void BM_RacePlanRightSideStops(benchmark::State& state) {
  race::RaceRules rules = race::SouthernFiveHundred();
  rules.right_side_stops = true;
  race::FallOff f = Table();
  for (int after : {15, 30, 45, 60}) {
    f.right_stop_after_laps.push_back(after);
    f.right_stop_lap_time_s.push_back(f.lap_time_s);
    for (double& t : f.right_stop_lap_time_s.back()) t += 0.01 * after;
  }
  for (auto _ : state) benchmark::DoNotOptimize(race::OptimalPlan(rules, f));
  const race::RacePlan plan = race::OptimalPlan(rules, f);
  int rights = 0;
  for (const race::PitStop& s : plan.stops)
    rights += s.service == race::Service::kRightTyresAndFuel;
  state.counters["stops"] = static_cast<double>(plan.stops.size());
  state.counters["right_side"] = rights;
}
BENCHMARK(BM_RacePlanRightSideStops)->Unit(benchmark::kMillisecond);

void BM_RacePolicySouthern500(benchmark::State& state) {
  const race::RaceRules rules = race::SouthernFiveHundred();
  race::FallOff f = Table();
  f.restart_penalty_s = 3.0;
  const race::CautionModel cautions = race::SouthernFiveHundredCautions();
  for (auto _ : state) benchmark::DoNotOptimize(race::SolvePolicy(rules, f, cautions));
}
BENCHMARK(BM_RacePolicySouthern500)->Unit(benchmark::kMillisecond);

void BM_PolicyMonteCarlo10000(benchmark::State& state) {
  const race::RaceRules rules = race::SouthernFiveHundred();
  race::FallOff f = Table();
  f.restart_penalty_s = 3.0;
  const race::RacePolicy p = race::SolvePolicy(rules, f, race::SouthernFiveHundredCautions());
  for (auto _ : state) benchmark::DoNotOptimize(race::SimulatePolicy(p, f, 10000));
}
BENCHMARK(BM_PolicyMonteCarlo10000)->Unit(benchmark::kMillisecond);

}  // namespace
