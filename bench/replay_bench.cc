// Replay speed: a 30-lap stint logged at 100 Hz through all eight models (four tyres, four
// brakes). Reports the real-time factor (seconds of log per second of compute) as a counter.
// Argument 0: the car's models (gas-and-rim tyres, bulk discs); 1: their paper parts
// (vehicle::PaperModelsOf), to compare in the same run.
//
// Run: ./build/replay_bench --benchmark_min_time=2

#include <benchmark/benchmark.h>

#include <filesystem>

#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace {

using namespace hotlap;
namespace fs = std::filesystem;

void BM_ReplayStint30Laps100Hz(benchmark::State& state) {
  const fs::path root = HOTLAP_SOURCE_DIR;
  const vehicle::Car gen7 = vehicle::LoadCar(root / "data/cars/gen7/car.yaml");
  const vehicle::Car car = state.range(0) == 1 ? vehicle::PaperModelsOf(gen7) : gen7;
  const Telemetry log = Telemetry::Read(root / "data/telemetry/darlington_example.csv");
  // The example lap resampled at 100 Hz and repeated 30 times.
  const sim::ReplayInputs stint =
      sim::ResampleReplayInputs(sim::ReplayInputsFromTelemetry(log, {}), 100.0, 30);
  const sim::ReplayInitialState initial = sim::InitialStateFor(log, car, {});
  const double logged = stint.time.back() - stint.time.front();
  for (auto _ : state) {
    sim::ReplayResult r = sim::RunReplay(car, stint, initial, sim::ReplayOptions{});
    benchmark::DoNotOptimize(r.corners[3].wear.back());
  }
  state.counters["samples"] = static_cast<double>(stint.time.size());
  state.counters["log_s"] = logged;
  // Seconds of log replayed per second of compute.
  state.counters["realtime_factor"] =
      benchmark::Counter(logged, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ReplayStint30Laps100Hz)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// One evaluation of the tyre model's right-hand side, the innermost cost of every replay.
void BM_TyreDerivatives(benchmark::State& state) {
  const vehicle::Car car =
      vehicle::LoadCar(fs::path(HOTLAP_SOURCE_DIR) / "data/cars/gen7/car.yaml");
  tyre::TyreFile t = car.tyres[3];
  if (state.range(0) == 1) t.params.model = tyre::TyreThermalModel::kPaper;
  tyre::TyreState<double> x{370.0, 350.0, 0.0, 340.0};
  tyre::TyreInput<double> u{70.0, 1500.0, 6000.0, 7000.0, -0.05, 0.02, 298.15, 313.15};
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    const auto dx = tyre::CalcTyreDerivatives(t.params, *t.compound, x, u);
    benchmark::DoNotOptimize(dx);
  }
}
BENCHMARK(BM_TyreDerivatives)->Arg(0)->Arg(1);

}  // namespace
