// The whole-car observer on short `hotlap synth` logs with known truth (the 30-lap acceptance
// stint is bench/observe_bench.cc's BM_ObserverAcceptance30Laps, docs/observer.md): accuracy on
// the deterministic truth, issue 26's acceptance numbers on synth logs with process noise (and
// that the same check fails a filter with the wrong noise), the gate, the disagreement warning,
// dropouts, the p5 state and the estimate columns.

#include "hotlap/observe/car_observer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/observe/synth_check.h"
#include "hotlap/sim/road.h"
#include "hotlap/sim/synth.h"
#include "hotlap/track/track_io.h"
#include "observe/observer_example.h"
#include "test_util.h"

namespace hotlap::observe {
namespace {

using testing::Column;
using testing::DefaultConfig;
using testing::Gen7;

// Two laps of Darlington at 100 Hz, 0.5 degC sensors without lag (made once, about 0.3 s).
const sim::SynthLog& TwoLaps() {
  static const sim::SynthLog log = [] {
    sim::SynthOptions o;
    o.laps = 2;
    o.rate_hz = 100.0;
    o.temp_noise_K = 0.5;
    o.sensor_lag_s = 0.0;
    return testing::DarlingtonLog(o);
  }();
  return log;
}

// The log's samples as the observer takes them: tread and disc read, nothing else.
std::vector<ObserverSample> Samples(const sim::SynthLog& log) {
  const sim::ReplayInputs& in = log.inputs;
  std::vector<ObserverSample> out(in.time.size());
  for (size_t k = 0; k < in.time.size(); ++k) {
    ObserverSample& s = out[k];
    s.time = in.time[k];
    s.ambient_temp = in.ambient_temp[k];
    s.track_temp = in.track_temp[k];
    for (Corner c : kAllCorners) {
      const int i = CornerIndex(c);
      const std::string n(CornerName(c));
      const sim::CornerChannels& ch = in.corners[i];
      s.inputs[i] = {ch.speed[k], ch.fx[k], ch.fy[k], ch.fz[k], ch.slip_angle[k], ch.slip_ratio[k]};
      if (!ch.brake_fx.empty()) s.inputs[i].brake_fx = ch.brake_fx[k];  // the rear spool's share
      s.readings[i].tread_temp = CelsiusToKelvin(Column(log, "tread_temp_" + n + "_C")[k]);
      s.readings[i].disc_temp = CelsiusToKelvin(Column(log, "disc_temp_" + n + "_C")[k]);
    }
  }
  return out;
}

TEST(CarObserverTest, OnTheSynthTruthCarcassAndWearAreAccurate) {
  const sim::SynthLog& log = TwoLaps();
  SynthCheckOptions o;
  o.score_from_s = log.lap_time_s;  // after the first lap
  o.carcass_offset_K = 4.0;         // the observer starts 4 degC off the true carcass
  const SynthCheck r = CheckObserverOnSynth(Gen7(), log, DefaultConfig(), o);
  EXPECT_GT(r.scored, 3000);
  EXPECT_NEAR(r.disc_missing_fraction, 0.2, 0.05);
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT(r.carcass_rms_K[i], 1.0) << i;  // issue 26: under 1 degC after the first lap
    EXPECT_GT(r.wear_truth_mm[i], 0.0);
    EXPECT_NEAR(r.wear_estimate_mm[i], r.wear_truth_mm[i], 0.1 * r.wear_truth_mm[i]) << i;
  }
  EXPECT_EQ(r.rejected, 0);
  EXPECT_EQ(r.warnings, 0);
  // The innovations are about chi-square(1) (the deterministic truth has no process noise, so
  // they may run slightly below 1).
  EXPECT_GT(r.pooled_mean_nis, 0.95);
  EXPECT_LT(r.pooled_mean_nis, r.pooled_nis_bounds95.second);
}

// Synth logs whose truth has the observer's own process noise (`hotlap synth --process-noise
// default`), one per seed, scored together: issue 26's acceptance numbers. By default on
// AcceptanceLaps() = 12 laps per log and AcceptanceSeeds() = 8 logs instead of 30-lap stints (those
// are bench/observe_bench.cc's BM_ObserverAcceptance30Laps/1 and bench/observe_cli_check.py);
// HOTLAP_ACCEPTANCE_LAPS=30 in the environment runs the full stint here too.
int EnvOr(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && std::atoi(v) > 0 ? std::atoi(v) : fallback;
}
int AcceptanceLaps() { return EnvOr("HOTLAP_ACCEPTANCE_LAPS", 12); }
int AcceptanceSeeds() { return EnvOr("HOTLAP_ACCEPTANCE_SEEDS", 8); }

struct Pooled {
  Coverage coverage;  // over every scored sample of every log
  double nis = 0.0;   // mean NIS of every used reading of every log
  std::pair<double, double> nis_bounds95;
  double worst_carcass_rms_K = 0.0, worst_wear_rel_error = 0.0;
  long rejected = 0, warnings = 0;
};

Pooled RunAcceptance(const ObserverConfig& filter_config, int seeds, int laps = AcceptanceLaps(),
                     double sensor_lag_s = 0.0) {
  static const std::vector<sim::RoadPoint> road =
      sim::SampleRoad(track::LoadTrack("darlington"), 1.0);
  const ObserverConfig truth_config = DefaultConfig();
  Pooled p;
  double nis_sum = 0.0;
  long nis_used = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    sim::SynthOptions so;
    so.laps = laps;
    so.rate_hz = 100.0;
    so.temp_noise_K = 0.5;
    so.sensor_lag_s = sensor_lag_s;
    so.seed = static_cast<uint64_t>(seed);
    const ProcessNoise& q = truth_config.process;
    so.process_noise =
        sim::SynthProcessNoise{q.tread_temp, q.carcass_temp, q.wear, q.disc_temp, q.calliper_temp};
    const sim::SynthLog log = sim::SynthesizeLog(Gen7(), road, so);
    SynthCheckOptions o;
    o.score_from_s = log.lap_time_s;  // after the first lap
    o.carcass_offset_K = 3.0;
    const SynthCheck r = CheckObserverOnSynth(Gen7(), log, filter_config, o);
    const double w = 1.0 / seeds;  // every log has the same number of samples
    p.coverage.tread += w * r.coverage.tread;
    p.coverage.carcass += w * r.coverage.carcass;
    p.coverage.wear += w * r.coverage.wear;
    p.coverage.disc += w * r.coverage.disc;
    p.coverage.calliper += w * r.coverage.calliper;
    nis_sum += r.pooled_mean_nis * static_cast<double>(r.nis_used);
    nis_used += r.nis_used;
    for (double x : r.carcass_rms_K) p.worst_carcass_rms_K = std::max(p.worst_carcass_rms_K, x);
    p.worst_wear_rel_error = std::max(p.worst_wear_rel_error, r.max_wear_rel_error);
    p.rejected += r.rejected;
    p.warnings += r.warnings;
  }
  p.nis = nis_sum / static_cast<double>(nis_used);
  p.nis_bounds95 = MeanNisBounds95(nis_used);
  return p;
}

TEST(CarObserverTest, OnSynthLogsWithProcessNoiseTheAcceptanceNumbersHold) {
  const Pooled p = RunAcceptance(DefaultConfig(), AcceptanceSeeds());
  RecordProperty("coverage_tread", std::to_string(p.coverage.tread));
  RecordProperty("coverage_carcass", std::to_string(p.coverage.carcass));
  RecordProperty("coverage_disc", std::to_string(p.coverage.disc));
  RecordProperty("pooled_nis", std::to_string(p.nis));
  std::printf(
      "%d logs x %d laps: inside 1 sigma tread %.3f carcass %.3f wear %.3f disc %.3f calliper "
      "%.3f; pooled NIS %.4f in [%.4f, %.4f]; worst carcass RMS %.4f C, worst wear error %.3g%%\n",
      AcceptanceSeeds(), AcceptanceLaps(), p.coverage.tread, p.coverage.carcass, p.coverage.wear,
      p.coverage.disc, p.coverage.calliper, p.nis, p.nis_bounds95.first, p.nis_bounds95.second,
      p.worst_carcass_rms_K, 100.0 * p.worst_wear_rel_error);
  // Issue 26: carcass RMS under 1 degC after the first lap, wear within 10% at the end.
  EXPECT_LT(p.worst_carcass_rms_K, 1.0);
  EXPECT_LT(p.worst_wear_rel_error, 0.1);
  // The 1-sigma band holds the truth 65-72% of the time (68.3% for a consistent filter).
  for (const auto& [share, name] :
       {std::pair{p.coverage.tread, "tread"}, std::pair{p.coverage.carcass, "carcass"},
        std::pair{p.coverage.disc, "disc"}}) {
    EXPECT_GE(share, 0.65) << name;
    EXPECT_LE(share, 0.72) << name;
  }
  // The normalised innovations are chi-square(1): their mean within its two-sided 95% bounds.
  EXPECT_GT(p.nis, p.nis_bounds95.first);
  EXPECT_LT(p.nis, p.nis_bounds95.second);
  EXPECT_EQ(p.warnings, 0);
}

// The same check fails a filter whose noise is wrong: assuming ten times the process noise the
// truth has, the bands are too wide (they hold the truth far more than 72% of the time) and the
// innovations fall below their chi-square bounds; assuming a tenth, the reverse.
TEST(CarObserverTest, TheAcceptanceCheckFailsAFilterWithTheWrongProcessNoise) {
  for (const double factor : {10.0, 0.1}) {
    ObserverConfig wrong = DefaultConfig();
    for (double* q : {&wrong.process.tread_temp, &wrong.process.carcass_temp,
                      &wrong.process.disc_temp, &wrong.process.calliper_temp}) {
      *q *= factor;
    }
    const Pooled p = RunAcceptance(wrong, 2);
    std::printf(
        "process noise x %g: inside 1 sigma tread %.3f carcass %.3f disc %.3f; pooled NIS "
        "%.4f in [%.4f, %.4f]\n",
        factor, p.coverage.tread, p.coverage.carcass, p.coverage.disc, p.nis, p.nis_bounds95.first,
        p.nis_bounds95.second);
    if (factor > 1.0) {
      EXPECT_GT(p.coverage.tread, 0.72);
      EXPECT_GT(p.coverage.disc, 0.72);
      EXPECT_LT(p.nis, p.nis_bounds95.first);
    } else {
      EXPECT_LT(p.coverage.tread, 0.65);
      EXPECT_LT(p.coverage.disc, 0.65);
      EXPECT_GT(p.nis, p.nis_bounds95.second);
    }
  }
}

// `hotlap synth`'s default sensors lag by 0.2 s. Taken as unlagged, the readings trail the states
// during braking by several sigma: the innovations fail the chi-square test and the monitor warns.
// With the lag as a state (ObserverConfig::sensor_lag, what `hotlap observe` takes from the log's
// `# sensor_lag_s:` line) the filter is consistent again: no warnings, the pooled NIS within its
// bounds, the bands holding the truth about 68% of the time.
TEST(CarObserverTest, ALaggingSensorIsConsistentOnceTheLagIsAState) {
  const double lag = 0.2;
  ObserverConfig config = DefaultConfig();
  const Pooled unlagged = RunAcceptance(config, 2, 6, lag);
  std::printf(
      "lagged logs, filter without the lag: inside 1 sigma tread %.3f disc %.3f; pooled NIS "
      "%.4f in [%.4f, %.4f]; %ld warnings, %ld rejected\n",
      unlagged.coverage.tread, unlagged.coverage.disc, unlagged.nis, unlagged.nis_bounds95.first,
      unlagged.nis_bounds95.second, unlagged.warnings, unlagged.rejected);
  EXPECT_GT(unlagged.nis, 1.5 * unlagged.nis_bounds95.second);
  EXPECT_GT(unlagged.warnings, 0);

  config.sensor_lag = {lag, lag, lag};
  const Pooled p = RunAcceptance(config, 8, 6, lag);
  std::printf(
      "lagged logs, lag as a state: inside 1 sigma tread %.3f carcass %.3f disc %.3f; "
      "pooled NIS %.4f in [%.4f, %.4f]; %ld warnings; worst carcass RMS %.4f C\n",
      p.coverage.tread, p.coverage.carcass, p.coverage.disc, p.nis, p.nis_bounds95.first,
      p.nis_bounds95.second, p.warnings, p.worst_carcass_rms_K);
  EXPECT_EQ(p.warnings, 0);
  EXPECT_GT(p.nis, p.nis_bounds95.first);
  EXPECT_LT(p.nis, p.nis_bounds95.second);
  EXPECT_NEAR(p.coverage.tread, 0.683, 0.035);
  EXPECT_NEAR(p.coverage.disc, 0.683, 0.035);
  EXPECT_NEAR(p.coverage.carcass, 0.683, 0.1);  // 8 short logs: the slow state swings more
  EXPECT_LT(p.worst_carcass_rms_K, 1.0);
  EXPECT_LT(p.worst_wear_rel_error, 0.1);
}

TEST(CarObserverTest, TheGateRejectsOutliersAsIfTheyWereMissing) {
  const std::vector<ObserverSample> clean = Samples(TwoLaps());
  std::vector<ObserverSample> spiked = clean, dropped = clean;
  int spikes = 0;
  for (size_t k = 500; k < spiked.size(); k += 300) {
    spiked[k].readings[1].tread_temp += 40.0;  // 80 sigma
    dropped[k].readings[1].tread_temp = std::nan("");
    ++spikes;
  }
  CarObserver a(Gen7(), DefaultConfig()), b(Gen7(), DefaultConfig()), c(Gen7(), DefaultConfig());
  double worst = 0.0, moved = 0.0;
  for (size_t k = 0; k < clean.size(); ++k) {
    a.Step(clean[k]);
    b.Step(spiked[k]);
    c.Step(dropped[k]);
    const CornerEstimate eb = b.Estimate(Corner::kFrontRight), ec = c.Estimate(Corner::kFrontRight);
    worst = std::max({worst, std::abs(eb.carcass_temp - ec.carcass_temp),
                      std::abs(eb.tread_temp - ec.tread_temp)});
    moved = std::max(moved, std::abs(a.Estimate(Corner::kFrontRight).tread_temp - eb.tread_temp));
  }
  EXPECT_EQ(b.monitor(Corner::kFrontRight, Sensor::kTread).rejected, spikes);
  EXPECT_EQ(a.monitor(Corner::kFrontRight, Sensor::kTread).rejected, 0);
  EXPECT_EQ(worst, 0.0);  // a rejected reading is as a missing one
  EXPECT_LT(moved, 0.5);  // and the 40 degC spikes moved nothing by more than the noise
  EXPECT_EQ(b.monitor(Corner::kFrontRight, Sensor::kTread).readings,
            static_cast<long>(clean.size()));
  EXPECT_EQ(c.monitor(Corner::kFrontRight, Sensor::kTread).missing, spikes);
}

TEST(CarObserverTest, ASensorThatDriftsOffIsWarnedAboutOnceAfterTheSetTime) {
  std::vector<ObserverSample> samples = Samples(TwoLaps());
  const double from = 20.0;  // s: the rear-left disc pyrometer reads 8 degC high (16 sigma)
  for (ObserverSample& s : samples) {
    if (s.time >= from) s.readings[2].disc_temp += 8.0;
  }
  const ObserverConfig config = DefaultConfig();
  CarObserver observer(Gen7(), config);
  std::vector<DisagreementWarning> warnings;
  for (const ObserverSample& s : samples) {
    for (DisagreementWarning& w : observer.Step(s)) warnings.push_back(w);
  }
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].corner, Corner::kRearLeft);
  EXPECT_EQ(warnings[0].sensor, Sensor::kDisc);
  EXPECT_GE(warnings[0].since_s, from);
  EXPECT_LT(warnings[0].since_s, from + 2.0 * config.window_s);
  EXPECT_NEAR(warnings[0].time_s - warnings[0].since_s, config.disagree_after_s, 0.05);
  EXPECT_TRUE(test::Contains(warnings[0].message, "rl disc_temp"));
  // Every reading after the fault is beyond the gate.
  EXPECT_GT(observer.monitor(Corner::kRearLeft, Sensor::kDisc).rejected,
            static_cast<long>(0.9 * (samples.back().time - from) * 100.0));
  // Without the fault, no warning.
  CarObserver clean(Gen7(), config);
  for (const ObserverSample& s : Samples(TwoLaps())) EXPECT_TRUE(clean.Step(s).empty());
}

TEST(CarObserverTest, DropoutsAreCountedAndWidenTheBand) {
  std::vector<ObserverSample> samples = Samples(TwoLaps());
  const size_t gap_from = 2000, gap_to = 2300;  // 3 s without the front-left disc
  CarObserver observer(Gen7(), DefaultConfig());
  double sd_before = 0.0, sd_in_gap = 0.0;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (k >= gap_from && k < gap_to) samples[k].readings[0].disc_temp = std::nan("");
    observer.Step(samples[k]);
    if (k == gap_from - 1) sd_before = observer.Estimate(Corner::kFrontLeft).disc_temp_sd;
    if (k == gap_to - 1) sd_in_gap = observer.Estimate(Corner::kFrontLeft).disc_temp_sd;
  }
  EXPECT_EQ(observer.monitor(Corner::kFrontLeft, Sensor::kDisc).missing,
            static_cast<long>(gap_to - gap_from));
  EXPECT_GT(sd_in_gap, sd_before);
  EXPECT_EQ(observer.monitor(Corner::kFrontLeft, Sensor::kCalliper).readings, 0);
}

TEST(CarObserverTest, TheP5StateFindsAConductanceTheCarFileHasWrong) {
  // The truth's tread-carcass conductance is 25% above the car file's.
  vehicle::Car truth_car = Gen7();
  for (tyre::TyreFile& t : truth_car.tyres) t.params.p5 *= 1.25;
  sim::SynthOptions so;
  so.laps = 2;
  so.rate_hz = 50.0;
  so.temp_noise_K = 0.5;
  so.sensor_lag_s = 0.0;
  const sim::SynthLog log =
      sim::SynthesizeLog(truth_car, sim::SampleRoad(track::LoadTrack("darlington"), 1.0), so);
  ObserverConfig config = DefaultConfig();
  config.p5_scale.estimate = true;
  config.p5_scale.initial_sd = 0.3;
  CarObserver observer(Gen7(), config);
  for (const ObserverSample& s : Samples(log)) observer.Step(s);
  for (Corner c : kAllCorners) {
    const CornerEstimate e = observer.Estimate(c);
    EXPECT_LT(e.p5_scale_sd, 0.1) << CornerName(c);
    EXPECT_NEAR(e.p5_scale, 1.25, 3.0 * e.p5_scale_sd + 0.01) << CornerName(c);
    EXPECT_NEAR(e.carcass_temp, log.truth.corners[CornerIndex(c)].carcass_temp.back(), 1.0);
  }
}

TEST(CarObserverTest, EstimateColumnsAndRowAgree) {
  CarObserver observer(Gen7(), DefaultConfig());
  const std::vector<std::string> names = EstimateColumns(observer);
  EXPECT_EQ(names.size(), 1u + 4u * 10u);
  EXPECT_EQ(names[0], "time_s");
  EXPECT_EQ(names[3], "carcass_temp_fl_C");
  EXPECT_EQ(names[4], "carcass_temp_fl_sd_C");
  ObserverConfig with_p5 = DefaultConfig();
  with_p5.p5_scale.estimate = true;
  EXPECT_EQ(EstimateColumns(CarObserver(Gen7(), with_p5)).size(), 1u + 4u * 12u);
  // The car's own models: rim, disc bulk, gas and pressure with their bands at every corner.
  CarObserver car(Gen7(), DefaultConfig(), {}, ObservedModels::kCar);
  const std::vector<std::string> car_names = EstimateColumns(car);
  EXPECT_EQ(car_names.size(), 1u + 4u * 18u);
  EXPECT_EQ(car_names[17], "pressure_fl_kPa");
  EXPECT_EQ(car_names[18], "pressure_fl_sd_kPa");
  car.Step(Samples(TwoLaps())[0]);
  EXPECT_EQ(EstimateRow(car).size(), car_names.size());
  observer.Step(Samples(TwoLaps())[0]);
  const std::vector<double> row = EstimateRow(observer);
  ASSERT_EQ(row.size(), names.size());
  EXPECT_EQ(row[0], TwoLaps().inputs.time[0]);
  // The first reading starts the tread state, with the sensor's standard deviation.
  EXPECT_NEAR(row[2], 0.5, 1e-12);
}

TEST(CarObserverTest, RefusesTimeThatDoesNotIncrease) {
  CarObserver observer(Gen7(), DefaultConfig());
  const std::vector<ObserverSample> samples = Samples(TwoLaps());
  observer.Step(samples[1]);
  const std::string message = test::InputErrorOf([&] { observer.Step(samples[0]); });
  EXPECT_TRUE(test::Contains(message, "does not follow"));
}

}  // namespace
}  // namespace hotlap::observe
