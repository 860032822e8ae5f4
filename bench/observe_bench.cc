// The live observer (docs/observer.md): its speed on a 100 Hz stream, four corners on one core,
// and its accuracy and consistency on 30-lap synthetic stints with known truth (the acceptance
// measurement of issue 26; docs/validation/observer.md, "Accuracy and consistency").
//
// Run: ./build/observe_bench --benchmark_min_time=2
//      ./build/observe_bench --benchmark_filter=Acceptance   (about a minute: two 30-lap stints)

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "hotlap/logs/telemetry.h"
#include "hotlap/observe/car_observer.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/observe/synth_check.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/road.h"
#include "hotlap/sim/synth.h"
#include "hotlap/sim/synth_sensor.h"
#include "hotlap/track/track_io.h"

namespace {

using namespace hotlap;
namespace fs = std::filesystem;

// The example lap at 100 Hz, ten laps, with the replayed truth read by a 0.5 degC tread sensor
// and a disc pyrometer missing every fifth sample.
std::vector<observe::ObserverSample> ExampleStream(const vehicle::Car& car) {
  const fs::path root = HOTLAP_SOURCE_DIR;
  const Telemetry log = Telemetry::Read(root / "data/telemetry/darlington_example.csv");
  const sim::ReplayInputs in =
      sim::ResampleReplayInputs(sim::ReplayInputsFromTelemetry(log, {}), 100.0, 10);
  const sim::ReplayResult truth =
      sim::RunReplay(car, in, sim::InitialStateFor(log, car, {}), sim::ReplayOptions{});
  sim::GaussianNoise noise(3);
  std::vector<observe::ObserverSample> samples(in.time.size());
  for (size_t k = 0; k < in.time.size(); ++k) {
    observe::ObserverSample& s = samples[k];
    s.time = in.time[k];
    s.ambient_temp = in.ambient_temp[k];
    s.track_temp = in.track_temp[k];
    for (int i = 0; i < 4; ++i) {
      const sim::CornerChannels& ch = in.corners[i];
      s.inputs[i] = {ch.speed[k], ch.fx[k], ch.fy[k], ch.fz[k], ch.slip_angle[k], ch.slip_ratio[k]};
      s.readings[i].tread_temp = truth.corners[i].tread_temp[k] + 0.5 * noise.Next();
      if (k % 5 != 4) s.readings[i].disc_temp = truth.corners[i].disc_temp[k] + 0.5 * noise.Next();
    }
  }
  return samples;
}

void BM_ObserveStream100Hz(benchmark::State& state) {
  const fs::path root = HOTLAP_SOURCE_DIR;
  const vehicle::Car car = vehicle::LoadCar(root / "data/cars/gen7/car.yaml");
  observe::ObserverConfig config = observe::LoadObserverConfig(root / "data/observer/default.yaml");
  config.p5_scale.estimate = state.range(0) != 0;
  const std::vector<observe::ObserverSample> samples = ExampleStream(car);
  const double logged = samples.back().time - samples.front().time;
  for (auto _ : state) {
    observe::CarObserver observer(car, config);
    for (const observe::ObserverSample& s : samples) {
      benchmark::DoNotOptimize(observer.Step(s));
    }
    benchmark::DoNotOptimize(observer.Estimate(Corner::kRearRight).wear);
  }
  state.counters["samples"] = static_cast<double>(samples.size());
  state.counters["log_s"] = logged;
  // Seconds of 100 Hz log observed (four corners) per second of CPU.
  state.counters["realtime_factor"] =
      benchmark::Counter(logged, benchmark::Counter::kIsIterationInvariantRate);
}
// Argument: 1 with the p5 state.
BENCHMARK(BM_ObserveStream100Hz)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The acceptance stint: 30 laps of Darlington at 100 Hz from `hotlap synth` (0.5 degC sensors,
// no lag), the observer reading tread temperatures and disc temperatures with 20% dropouts, never
// carcass, wear or calliper, started 3 degC off the true carcass. Argument 0: synth's
// deterministic truth (no process noise; dropout seed 7); 1: synth's stochastic truth (`hotlap
// synth --process-noise default`: the model plus the observer's own process noise), eight seeds,
// coverage and NIS averaged over them (one run's time fraction swings by +-0.1 for the slow
// states, whose errors stay correlated for minutes); 2: as 1 with synth's default 0.2 s sensor
// lag, and the observer carrying the lag as a state. One iteration; the scores are counters.
void BM_ObserverAcceptance30Laps(benchmark::State& state) {
  const fs::path root = HOTLAP_SOURCE_DIR;
  const vehicle::Car car = vehicle::LoadCar(root / "data/cars/gen7/car.yaml");
  observe::ObserverConfig config = observe::LoadObserverConfig(root / "data/observer/default.yaml");
  const std::vector<sim::RoadPoint> road = sim::SampleRoad(track::LoadTrack("darlington"), 1.0);
  const bool stochastic = state.range(0) != 0;
  // Argument 2: synth's default 0.2 s sensor lag, and the observer with the lag as a state.
  const double lag = state.range(0) == 2 ? 0.2 : 0.0;
  config.sensor_lag = {lag, lag, lag};
  const int runs = stochastic ? 8 : 1;
  sim::SynthOptions so;
  so.laps = 30;
  so.rate_hz = 100.0;
  so.sensor_lag_s = lag;
  so.temp_noise_K = 0.5;
  if (stochastic) {
    const observe::ProcessNoise& q = config.process;
    so.process_noise =
        sim::SynthProcessNoise{q.tread_temp, q.carcass_temp, q.wear, q.disc_temp, q.calliper_temp};
  }
  std::vector<observe::SynthCheck> results;
  for (auto _ : state) {
    for (int run = 0; run < runs; ++run) {
      so.seed = static_cast<uint64_t>(run + 1);
      const sim::SynthLog log = sim::SynthesizeLog(car, road, so);
      observe::SynthCheckOptions o;
      o.score_from_s = log.lap_time_s;
      o.seed = 7;
      results.push_back(observe::CheckObserverOnSynth(car, log, config, o));
    }
  }
  observe::Coverage cover;
  double carcass_rms = 0.0, worst_rms = 0.0, wear_err = 0.0, nis = 0.0, cover_min = 1.0,
         cover_max = 0.0, nis_lo = 1e9, nis_hi = 0.0, missing = 0.0;
  int sensors = 0, consistent = 0;
  long rejected = 0, warnings = 0, nis_used = 0;
  double nis_sum = 0.0;
  for (const observe::SynthCheck& r : results) {
    cover.tread += r.coverage.tread / runs;
    cover.carcass += r.coverage.carcass / runs;
    cover.wear += r.coverage.wear / runs;
    cover.disc += r.coverage.disc / runs;
    cover.calliper += r.coverage.calliper / runs;
    cover_min = std::min(cover_min, r.coverage.carcass);
    cover_max = std::max(cover_max, r.coverage.carcass);
    carcass_rms += r.carcass_rms_all_K / runs;
    for (double x : r.carcass_rms_K) worst_rms = std::max(worst_rms, x);
    wear_err = std::max(wear_err, r.max_wear_rel_error);
    nis += r.pooled_mean_nis / runs;
    nis_sum += r.pooled_mean_nis * static_cast<double>(r.nis_used);
    nis_used += r.nis_used;
    for (const auto& corner : r.mean_nis) {
      for (int s = 0; s < 2; ++s) {
        nis_lo = std::min(nis_lo, corner[s]);
        nis_hi = std::max(nis_hi, corner[s]);
      }
    }
    sensors += r.sensors;
    consistent += r.sensors_consistent;
    missing += r.disc_missing_fraction / runs;
    rejected += r.rejected;
    warnings += r.warnings;
  }
  state.counters["runs"] = runs;
  state.counters["carcass_rms_C"] = carcass_rms;
  state.counters["carcass_rms_worst_C"] = worst_rms;
  state.counters["wear_rel_err_max"] = wear_err;
  state.counters["cover_tread"] = cover.tread;
  state.counters["cover_carcass"] = cover.carcass;
  state.counters["cover_carcass_min"] = cover_min;
  state.counters["cover_carcass_max"] = cover_max;
  state.counters["cover_wear"] = cover.wear;
  state.counters["cover_disc"] = cover.disc;
  state.counters["cover_calliper"] = cover.calliper;
  // Every used reading of every run: its mean, and that mean's two-sided 95% bounds.
  const std::pair<double, double> bounds = observe::MeanNisBounds95(nis_used);
  state.counters["pooled_mean_nis"] = nis_used > 0 ? nis_sum / static_cast<double>(nis_used) : nis;
  state.counters["pooled_nis_lo95"] = bounds.first;
  state.counters["pooled_nis_hi95"] = bounds.second;
  state.counters["mean_nis_min"] = nis_lo;
  state.counters["mean_nis_max"] = nis_hi;
  state.counters["sensors_consistent_share"] =
      sensors > 0 ? static_cast<double>(consistent) / sensors : 0.0;
  state.counters["disc_missing"] = missing;
  state.counters["rejected"] = static_cast<double>(rejected);
  state.counters["warnings"] = static_cast<double>(warnings);
}
BENCHMARK(BM_ObserverAcceptance30Laps)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace
