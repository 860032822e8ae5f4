// Replay speed: a 30-lap stint logged at 100 Hz through all eight models (four tyres, four
// brakes). Reports the real-time factor (seconds of log per second of compute) as a counter.
//
// Run: ./build/replay_bench --benchmark_min_time=2

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "hotlap/common/telemetry.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace {

using namespace hotlap;
namespace fs = std::filesystem;

// The example lap resampled at `rate_hz` and repeated `laps` times.
sim::ReplayInputs Stint(const sim::ReplayInputs& lap, int laps, double rate_hz) {
  sim::ReplayInputs out;
  const double period = lap.time.back() - lap.time.front() + 1.0 / 50.0;
  const int per_lap = static_cast<int>(std::floor(period * rate_hz));
  const auto at = [&](const std::vector<double>& v, double t) {
    const auto it = std::upper_bound(lap.time.begin(), lap.time.end(), t);
    const size_t j = std::clamp<size_t>(it - lap.time.begin(), 1, lap.time.size() - 1);
    const double f = std::clamp((t - lap.time[j - 1]) / (lap.time[j] - lap.time[j - 1]), 0.0, 1.0);
    return v[j - 1] + f * (v[j] - v[j - 1]);
  };
  for (int l = 0; l < laps; ++l) {
    for (int k = 0; k < per_lap; ++k) {
      const double t = k / rate_hz;
      out.time.push_back(l * period + t);
      for (int c = 0; c < 4; ++c) {
        const sim::CornerChannels& a = lap.corners[c];
        sim::CornerChannels& b = out.corners[c];
        b.speed.push_back(at(a.speed, t));
        b.fx.push_back(at(a.fx, t));
        b.fy.push_back(at(a.fy, t));
        b.fz.push_back(at(a.fz, t));
        b.slip_angle.push_back(at(a.slip_angle, t));
        b.slip_ratio.push_back(at(a.slip_ratio, t));
      }
      out.ambient_temp.push_back(at(lap.ambient_temp, t));
      out.track_temp.push_back(at(lap.track_temp, t));
    }
  }
  return out;
}

void BM_ReplayStint30Laps100Hz(benchmark::State& state) {
  const fs::path root = HOTLAP_SOURCE_DIR;
  const vehicle::Car car = vehicle::LoadCar(root / "data/cars/gen7/car.yaml");
  const Telemetry log = Telemetry::Read(root / "data/telemetry/darlington_example.csv");
  const sim::ReplayInputs stint = Stint(sim::ReplayInputsFromTelemetry(log, {}), 30, 100.0);
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
BENCHMARK(BM_ReplayStint30Laps100Hz)->Unit(benchmark::kMillisecond);

// One evaluation of the tyre model's right-hand side, the innermost cost of every replay.
void BM_TyreDerivatives(benchmark::State& state) {
  const vehicle::Car car =
      vehicle::LoadCar(fs::path(HOTLAP_SOURCE_DIR) / "data/cars/gen7/car.yaml");
  const tyre::TyreFile& t = car.tyres[3];
  tyre::TyreState<double> x{370.0, 350.0, 0.0};
  tyre::TyreInput<double> u{70.0, 1500.0, 6000.0, 7000.0, -0.05, 0.02, 298.15, 313.15};
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    const auto dx = tyre::CalcTyreDerivatives(t.params, *t.compound, x, u);
    benchmark::DoNotOptimize(dx);
  }
}
BENCHMARK(BM_TyreDerivatives);

}  // namespace
