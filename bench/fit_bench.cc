// Fitting speed (the fitting issue's goal: under 5 s): a four-corner tyre fit (p1..p5 and the
// initial temperatures, then wp1, wp2) to one lap of Darlington logged at 50 Hz, synthesized
// from parameters 50% away from the car's with 0.5 degC noise and a 0.2 s sensor lag (modelled).
// Arguments: corners fitted at once (1: one after another; 4: one thread per corner, as
// `hotlap fit` does on a machine with four cores). Also one corner's Jacobian evaluation.
//
// Run: ./build/fit_bench (the data folder is found as every command finds it: $HOTLAP_DATA_DIR,
// else the source tree's data/).

#include <benchmark/benchmark.h>

#include <thread>
#include <vector>

#include "hotlap/common/data_path.h"
#include "hotlap/ident/tyre_thermal_fit.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/road.h"
#include "hotlap/sim/synth.h"
#include "hotlap/track/track_io.h"

namespace {

using namespace hotlap;

struct Setup {
  vehicle::Car car;
  sim::SynthLog log;
  std::vector<double> weights;
};

const Setup& GetSetup() {
  static const Setup setup = [] {
    Setup s{vehicle::LoadCar(ResolveCarFile("gen7")), {}, {}};
    vehicle::Car truth = s.car;
    for (auto& t : truth.tyres) {
      auto& p = t.params;
      for (double* v : {&p.p1, &p.p2, &p.p3, &p.p4, &p.p5, &p.wear_coeff, &p.wear_exponent}) {
        *v *= 1.5;
      }
    }
    const std::vector<sim::RoadPoint> road = sim::SampleRoad(track::LoadTrack("darlington"), 1.0);
    s.log = sim::SynthesizeLog(truth, road, sim::SynthOptions{});
    s.weights = ident::TrapezoidWeights(s.log.inputs.time);
    return s;
  }();
  return setup;
}

// The log's measured channel as the fit reads it, straight from the synthesized columns.
ident::LoggedChannel Channel(const sim::SynthLog& log, const std::string& column, double offset) {
  ident::LoggedChannel ch;
  for (size_t i = 0; i < log.columns.size(); ++i) {
    if (log.columns[i] != column) continue;
    ch.values = log.values[i];
    for (double& v : ch.values) v += offset;
  }
  ch.column = column;
  ch.usable = !ch.values.empty();
  return ch;
}

void FitCorner(const Setup& s, Corner c) {
  const std::string n(CornerName(c));
  ident::TyreCornerData d;
  d.samples = ident::CornerSamplesOf(s.log.inputs, c);
  d.tread = Channel(s.log, "tread_temp_" + n + "_C", 273.15);
  d.carcass = Channel(s.log, "carcass_temp_" + n + "_C", 273.15);
  d.wear = Channel(s.log, "wear_" + n + "_mm", 0.0);
  d.weights = s.weights;
  ident::LogFitOptions o;
  o.sensor_lag_s = 0.2;
  const ident::TyreFitResult r = ident::FitTyreCorner(s.car.tyre(c), d, o);
  benchmark::DoNotOptimize(r.params.p1);
}

void BM_FitTyreFourCornersOneLap50Hz(benchmark::State& state) {
  const Setup& s = GetSetup();
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&, t] {
        for (int i = t; i < 4; i += threads) FitCorner(s, kAllCorners[i]);
      });
    }
    for (std::thread& th : pool) th.join();
  }
  state.counters["samples"] = static_cast<double>(s.log.inputs.time.size());
  state.counters["log_s"] = s.log.inputs.time.back() - s.log.inputs.time.front();
}
BENCHMARK(BM_FitTyreFourCornersOneLap50Hz)
    ->Arg(1)
    ->Arg(4)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(2);

}  // namespace
