// ABS speed: the FE/ABS paper's 1.5 s braking event (data/abs/paper.yaml: the controller at
// 200 Hz, the plant in 0.5 ms RK4 steps, the brake's temperatures, every step recorded).
// Reports the real-time factor (seconds of event per second of compute) as a counter; the
// goal is at least 1,000.
//
// Run: ./build/abs_bench --benchmark_min_time=2

#include <benchmark/benchmark.h>

#include <filesystem>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_plant.h"
#include "hotlap/abs/abs_run.h"

namespace {

using namespace hotlap;

const sim::AbsConfig& Config() {
  static const sim::AbsConfig c =
      sim::LoadAbsConfig(std::filesystem::path(HOTLAP_SOURCE_DIR) / "data/abs/paper.yaml");
  return c;
}

void BM_AbsPaperEvent(benchmark::State& state) {
  const sim::AbsConfig& c = Config();
  int steps = 0;
  for (auto _ : state) {
    const sim::AbsRunResult r = sim::RunAbs(c, c.event);
    steps = r.steps;
    benchmark::DoNotOptimize(r.final.speed);
  }
  state.counters["steps"] = steps;
  state.counters["realtime_factor"] =
      benchmark::Counter(c.event.duration_s, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AbsPaperEvent)->Unit(benchmark::kMillisecond);

// The same with the figures computed, as `hotlap abs` does.
void BM_AbsPaperEventWithMetrics(benchmark::State& state) {
  const sim::AbsConfig& c = Config();
  for (auto _ : state) {
    const sim::AbsRunResult r = sim::RunAbs(c, c.event);
    const sim::AbsMetrics m = sim::CalcAbsMetrics(c, r);
    benchmark::DoNotOptimize(m.cycles_per_s);
  }
  state.counters["realtime_factor"] =
      benchmark::Counter(c.event.duration_s, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AbsPaperEventWithMetrics)->Unit(benchmark::kMillisecond);

// One evaluation of the plant's right-hand side (brush tyre, paper's friction law).
void BM_AbsPlantDerivatives(benchmark::State& state) {
  const sim::AbsConfig& c = Config();
  sim::AbsPlantState<double> x;
  x.speed = 10.0;
  x.wheel_speed = 9.0 / c.plant.wheel.radius;
  x.slip = -0.08;
  x.pressure = 7e6;
  const sim::AbsPlantInput<double> in{.pressure_target = 7e6,
                                      .road = c.SurfaceNamed("paper").segments[0].law};
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    const auto d = sim::CalcAbsPlantDerivatives(c.plant, x, in);
    benchmark::DoNotOptimize(d);
  }
}
BENCHMARK(BM_AbsPlantDerivatives);

}  // namespace
