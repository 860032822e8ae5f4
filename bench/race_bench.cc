// Race plan speed: the Southern 500 (367 laps, 13 sets, a 56-lap cell) planned by the dynamic
// programme from a fall-off table of 60 laps (a steady 0.04 s a lap, so tyres are worth stopping
// for), and the fixed plans; the policy under the record's cautions (the stochastic programme) and
// 10,000 Monte Carlo races of it. The fall-off's QSS laps are qss_bench's business.
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
