// Quasi-steady-state lap speed: one Darlington lap at 1 m resolution (2198 road points) with the
// Gen-7 car, the thermal models replayed along it, thermal coupling on (the first lap run twice),
// as `hotlap lap` runs it (/0; /1 without the tyres' cornering drag, one profile). Also the parts:
// the speed profile alone, and a lap without coupling.
//
// Run: ./build/qss_bench --benchmark_min_time=2

#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "hotlap/common/data_path.h"
#include "hotlap/common/units.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/sim/qss_profile.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/road.h"
#include "hotlap/track/track_io.h"

namespace {

using namespace hotlap;

struct Setup {
  vehicle::Car car = vehicle::LoadCar(ResolveCarFile("gen7"));
  track::Track track = track::LoadTrack("darlington");
  std::vector<sim::RoadPoint> road = sim::SampleRoad(track, 1.0);
  sim::QssOptions options;
  Setup() {
    options.ambient_temp = CelsiusToKelvin(25.0);
    options.track_temp = CelsiusToKelvin(40.0);
    options.initial = sim::CarStartState(car);
  }
};

const Setup& Shared() {
  static const Setup s;
  return s;
}

// Argument: the most speed profiles a pass solves for the tyres' cornering drag (QssOptions::
// max_drag_passes): 0 the default (until the drag settles), 1 leaves the drag out (the way
// before 2026-11-27), 3 at most three. Issue 45's goal: /0 at most 1.15 times /1 in the same run.
void BM_QssDarlingtonLap1m(benchmark::State& state) {
  const Setup& s = Shared();
  sim::QssOptions options = s.options;
  if (state.range(0) > 0) options.max_drag_passes = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(sim::RunQssLap(s.car, s.road, options));
  state.counters["lap_time_s"] = sim::RunQssLap(s.car, s.road, options).laps[0].lap_time;
  state.counters["points"] = static_cast<double>(s.road.size());
}
BENCHMARK(BM_QssDarlingtonLap1m)->Arg(0)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_QssDarlingtonLap1mUncoupled(benchmark::State& state) {
  const Setup& s = Shared();
  sim::QssOptions options = s.options;
  options.couple_first_lap = false;
  for (auto _ : state) benchmark::DoNotOptimize(sim::RunQssLap(s.car, s.road, options));
}
BENCHMARK(BM_QssDarlingtonLap1mUncoupled)->Unit(benchmark::kMillisecond);

void BM_QssSpeedProfileOnly(benchmark::State& state) {
  const Setup& s = Shared();
  const sim::QssVehicle car(*s.car.vehicle);
  std::array<std::vector<double>, 4> grip;
  for (auto& g : grip) g.assign(s.road.size(), 0.95);
  for (auto _ : state) benchmark::DoNotOptimize(sim::CalcSpeedProfile(car, s.road, grip));
}
BENCHMARK(BM_QssSpeedProfileOnly)->Unit(benchmark::kMillisecond);

}  // namespace
