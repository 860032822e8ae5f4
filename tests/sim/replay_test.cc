// Tests of the replay integrator: accuracy against a much finer step at logging rates from 10 Hz
// to 1 kHz, convergence order, initial-state rules and input checks.

#include "hotlap/sim/replay.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/sim/replay_io.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

namespace fs = std::filesystem;

vehicle::Car Gen7Car() {
  return vehicle::LoadCar(fs::path(HOTLAP_SOURCE_DIR) / "data/cars/gen7/car.yaml");
}

// The shipped example lap, as replay inputs.
ReplayInputs ExampleInputs() {
  const Telemetry log =
      Telemetry::Read(fs::path(HOTLAP_SOURCE_DIR) / "data/telemetry/darlington_example.csv");
  return ReplayInputsFromTelemetry(log, {});
}

ReplayInitialState WarmStart(const vehicle::Car& car) { return CarStartState(car); }

// Largest difference of any temperature (K) between two results on the same samples.
double MaxTemperatureDifference(const ReplayResult& a, const ReplayResult& b) {
  double worst = 0.0;
  for (int c = 0; c < 4; ++c) {
    const CornerHistory& x = a.corners[c];
    const CornerHistory& y = b.corners[c];
    for (size_t k = 0; k < a.time.size(); ++k) {
      worst = std::max({worst, std::abs(x.tread_temp[k] - y.tread_temp[k]),
                        std::abs(x.carcass_temp[k] - y.carcass_temp[k]),
                        std::abs(x.disc_temp[k] - y.disc_temp[k]),
                        std::abs(x.calliper_temp[k] - y.calliper_temp[k])});
    }
  }
  return worst;
}

class ReplayRateTest : public ::testing::TestWithParam<double> {};

// The default sub-stepping keeps the error below 0.05 degC against a step 32 times finer, at
// logging rates from 10 Hz to 1 kHz.
TEST_P(ReplayRateTest, DefaultStepIsWithinToleranceOfMuchFinerStep) {
  const vehicle::Car car = Gen7Car();
  const ReplayInputs inputs = ResampleReplayInputs(ExampleInputs(), GetParam());
  ReplayOptions normal;
  ReplayOptions fine;
  fine.max_step_s = normal.max_step_s / 32.0;
  fine.max_step_s = std::min(fine.max_step_s, 0.25 / GetParam());
  const ReplayResult a = RunReplay(car, inputs, WarmStart(car), normal);
  const ReplayResult b = RunReplay(car, inputs, WarmStart(car), fine);
  const double error = MaxTemperatureDifference(a, b);
  EXPECT_LT(error, 0.05) << "at " << GetParam() << " Hz";
  // Something happened: the discs heated by hundreds of kelvin during the lap.
  EXPECT_GT(*std::max_element(a.corners[0].disc_temp.begin(), a.corners[0].disc_temp.end()),
            car.initial.disc_temp + 100.0);
}

INSTANTIATE_TEST_SUITE_P(LoggingRates, ReplayRateTest,
                         ::testing::Values(10.0, 50.0, 100.0, 1000.0));

// Fourth order on a smooth stretch: a log at 1 Hz of steady braking with gentle loads, so no
// input changes sign and the film temperature stays inside one interval of the air table.
TEST(ReplayTest, ConvergesAtFourthOrderOnSmoothInputs) {
  const vehicle::Car car = Gen7Car();
  ReplayInputs in;
  const int n = 8;
  for (int k = 0; k < n; ++k) {
    const double t = k;
    in.time.push_back(t);
    for (int c = 0; c < 4; ++c) {
      CornerChannels& ch = in.corners[c];
      ch.speed.push_back(60.0 - 2.0 * t + 0.3 * std::sin(t));
      ch.fx.push_back(-1500.0 - 100.0 * std::cos(t));
      ch.fy.push_back(800.0 + 50.0 * std::sin(0.7 * t));
      ch.fz.push_back(5000.0 + 200.0 * std::sin(0.5 * t));
      ch.slip_angle.push_back(-0.01 - 0.002 * std::sin(t));
      ch.slip_ratio.push_back(-0.01 - 0.001 * std::cos(t));
    }
    in.ambient_temp.push_back(CelsiusToKelvin(25.0));
    in.track_temp.push_back(CelsiusToKelvin(35.0));
  }
  ReplayInitialState start;
  for (int c = 0; c < 4; ++c) {
    start.tyres[c] = {CelsiusToKelvin(48.0), CelsiusToKelvin(50.0), 0.0, CelsiusToKelvin(40.0)};
    start.brakes[c] = {CelsiusToKelvin(300.0), CelsiusToKelvin(120.0), CelsiusToKelvin(250.0)};
  }
  const auto final_temps = [&](double step) {
    ReplayOptions o;
    o.max_step_s = step;
    const ReplayResult r = RunReplay(car, in, start, o);
    const CornerHistory& h = r.corners[1];
    return std::vector<double>{h.tread_temp.back(), h.carcass_temp.back(), h.disc_temp.back(),
                               h.calliper_temp.back()};
  };
  const std::vector<double> reference = final_temps(1.0 / 256.0);
  std::vector<double> errors;
  for (double step : {1.0, 0.5, 0.25}) {
    const std::vector<double> x = final_temps(step);
    double e = 0.0;
    for (size_t i = 0; i < x.size(); ++i) e = std::max(e, std::abs(x[i] - reference[i]));
    errors.push_back(e);
  }
  // The film temperature stayed inside one air-table interval (30-40 degC), else the test is void.
  const ReplayResult r = RunReplay(car, in, start, ReplayOptions{});
  for (double t : r.corners[1].tread_temp) {
    ASSERT_GT(0.5 * (t + CelsiusToKelvin(25.0)), CelsiusToKelvin(30.0));
    ASSERT_LT(0.5 * (t + CelsiusToKelvin(25.0)), CelsiusToKelvin(40.0));
  }
  const double order1 = std::log2(errors[0] / errors[1]);
  const double order2 = std::log2(errors[1] / errors[2]);
  EXPECT_GT(errors[0], 1e-9);  // the test resolves a real error
  EXPECT_NEAR(order1, 4.0, 0.6);
  EXPECT_NEAR(order2, 4.0, 0.6);
}

// With the paper's models (thermal_model paper, disc_model lumped) the replay is the published
// two-mass tyre and lumped disc integrated apart, bit for bit: the same integrator the fits use
// (sim::IntegrateTyre, sim::IntegrateBrake), so the gas-and-rim model left the paper's untouched.
TEST(ReplayTest, ThePaperModelsReplayAsPublished) {
  const vehicle::Car car = vehicle::PaperModelsOf(Gen7Car());
  const ReplayInputs in = ExampleInputs();
  const ReplayInitialState start = WarmStart(car);
  const ReplayResult r = RunReplay(car, in, start, {});
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerHistory& h = r.corners[i];
    EXPECT_TRUE(h.gas_temp.empty() && h.rim_temp.empty() && h.disc_bulk_temp.empty());
    const CornerSamples samples = CornerSamplesOf(in, c);
    size_t checked = 0;
    IntegrateTyre<double>(car.tyre(c).params, *car.tyre(c).compound, samples, start.tyres[i], 0.02,
                          [&](size_t k, const tyre::TyreState<double>& x) {
                            ASSERT_EQ(h.tread_temp[k], x.tread_temp) << k;
                            ASSERT_EQ(h.carcass_temp[k], x.carcass_temp) << k;
                            ASSERT_EQ(h.wear[k], x.wear) << k;
                            ++checked;
                          });
    IntegrateBrake<double>(car.brake(c).params, BrakeSamplesOf(in, c), start.brakes[i], 0.02,
                           [&](size_t k, const brake::BrakeState<double>& x) {
                             ASSERT_EQ(h.disc_temp[k], x.disc_temp) << k;
                             ASSERT_EQ(h.calliper_temp[k], x.calliper_temp) << k;
                             ++checked;
                           });
    EXPECT_EQ(checked, 2 * in.time.size());
  }
  // The audit closes for the paper's models too (it is bookkeeping), and says where their carcass
  // heat comes from: nothing the car pays for.
  for (const CornerEnergyAudit& a : r.audits.at(0)) {
    EXPECT_LT(std::abs(a.TyreClosure()), 1e-9);
    EXPECT_LT(std::abs(a.BrakeClosure()), 1e-9);
  }
}

// The gas-and-rim car over the same log: each balance closes to rounding, a stretch boundary
// splits the run's audit into two that add up to it, and no tyre makes more heat than work.
TEST(ReplayTest, TheAuditClosesAndAddsUpOverStretches) {
  const vehicle::Car car = Gen7Car();
  const ReplayInputs in = ExampleInputs();
  const ReplayResult whole = RunReplay(car, in, WarmStart(car), {});
  ReplayOptions split;
  split.audit_starts = {in.time.size() / 3};
  const ReplayResult parts = RunReplay(car, in, WarmStart(car), split);
  ASSERT_EQ(whole.audits.size(), 1u);
  ASSERT_EQ(parts.audits.size(), 2u);
  for (int c = 0; c < 4; ++c) {
    const CornerEnergyAudit& a = whole.audits[0][c];
    EXPECT_TRUE(a.has_rim);
    EXPECT_GT(a.GeneratedHeat(), 0.0);
    EXPECT_LT(std::abs(a.TyreClosure()), 1e-9);
    EXPECT_LT(std::abs(a.RimClosure()), 1e-9);
    EXPECT_LT(std::abs(a.BrakeClosure()), 1e-9);
    EXPECT_LE(a.HeatOverWork(), 1.0);
    const CornerEnergyAudit& p = parts.audits[0][c];
    const CornerEnergyAudit& q = parts.audits[1][c];
    EXPECT_NEAR(p.GeneratedHeat() + q.GeneratedHeat(), a.GeneratedHeat(), 1e-9 * a.GeneratedHeat());
    EXPECT_NEAR(p.tyre_stored + q.tyre_stored, a.tyre_stored, 1e-6);
    EXPECT_NEAR(p.duration_s + q.duration_s, a.duration_s, 1e-9);
  }
  ReplayOptions bad;
  bad.audit_starts = {0};
  EXPECT_THROW(RunReplay(car, in, WarmStart(car), bad), InputError);
  ReplayInitialState no_rim = WarmStart(car);
  no_rim.tyres[1].rim_temp = 0.0;
  EXPECT_THROW(RunReplay(car, in, no_rim, {}), InputError);
}

TEST(ReplayTest, HistoryStatsUseTimeWeightedMean) {
  // Value 0 for 1 s, ramp to 10 over 1 s, then 10 for 2 s: mean (0 + 5 + 20) / 4 = 6.25.
  const std::vector<double> t = {0.0, 1.0, 2.0, 4.0};
  const std::vector<double> v = {0.0, 0.0, 10.0, 10.0};
  const HistoryStats s = CalcHistoryStats(t, v);
  EXPECT_DOUBLE_EQ(s.peak, 10.0);
  EXPECT_DOUBLE_EQ(s.final, 10.0);
  EXPECT_DOUBLE_EQ(s.mean, 6.25);
}

TEST(ReplayTest, SummaryPerCornerByHand) {
  ReplayResult r;
  r.time = {0.0, 1.0, 2.0, 4.0};
  for (int c = 0; c < 4; ++c) {
    CornerHistory& h = r.corners[c];
    h.tread_temp = {300.0, 300.0, 310.0 + c, 310.0 + c};
    h.carcass_temp = {320.0, 321.0, 322.0, 323.0};
    h.disc_temp = {400.0, 500.0, 450.0, 420.0};
    h.calliper_temp = {350.0, 350.0, 350.0, 350.0};
    h.wear = {0.0, 0.001, 0.002, 0.004 * (c + 1)};
    h.grip_factor = {1.0, 0.9 - 0.1 * c, 0.95, 0.97};
    h.brake_power = {0.0, 100.0, 100.0, 0.0};  // 50 + 100 + 100 J
  }
  const std::array<CornerReplaySummary, 4> s = SummarizeReplay(r);
  for (int c = 0; c < 4; ++c) {
    EXPECT_DOUBLE_EQ(s[c].tread.peak, 310.0 + c) << c;
    EXPECT_DOUBLE_EQ(s[c].tread.mean, (300.0 + 0.5 * (610.0 + c) + 2.0 * (310.0 + c)) / 4.0);
    EXPECT_DOUBLE_EQ(s[c].disc.peak, 500.0);
    EXPECT_DOUBLE_EQ(s[c].disc.final, 420.0);
    EXPECT_DOUBLE_EQ(s[c].calliper.mean, 350.0);
    EXPECT_DOUBLE_EQ(s[c].final_wear_mm, 0.004 * (c + 1));
    EXPECT_DOUBLE_EQ(s[c].min_grip_factor, std::min(0.9 - 0.1 * c, 1.0));
    EXPECT_DOUBLE_EQ(s[c].brake_energy_J, 250.0);
  }
}

// Four samples at uneven times from t = 10 s with a kink at 11 s; every channel differs.
ReplayInputs KinkedInputs() {
  ReplayInputs in;
  in.time = {10.0, 10.5, 11.0, 12.0};
  for (int c = 0; c < 4; ++c) {
    CornerChannels& ch = in.corners[c];
    ch.speed = {10.0 + c, 20.0 + c, 30.0 + c, 50.0 + c};
    ch.fx = {-100.0 * c, 0.0, 100.0, 300.0};
    ch.fy = {1.0, 2.0, 3.0, 5.0};
    ch.fz = {4000.0, 4100.0, 4200.0, 4400.0};
    ch.slip_angle = {0.0, 0.01, 0.02, 0.04};
    ch.slip_ratio = {0.0, -0.01, -0.02, -0.04};
  }
  in.ambient_temp = {290.0, 291.0, 292.0, 294.0};
  in.track_temp = {300.0, 302.0, 304.0, 308.0};
  return in;
}

TEST(ReplayTest, ResampleCoversTheLogOnAUniformGrid) {
  const ReplayInputs in = KinkedInputs();
  const ReplayInputs r = ResampleReplayInputs(in, 4.0);
  // floor(2 s * 4 Hz) + 1 samples at 10, 10.25, ..., 12 s.
  ASSERT_EQ(r.time.size(), 9u);
  for (size_t k = 0; k < r.time.size(); ++k) {
    EXPECT_DOUBLE_EQ(r.time[k], 10.0 + 0.25 * k) << k;
  }
  for (int c = 0; c < 4; ++c) {
    const CornerChannels& ch = r.corners[c];
    for (const std::vector<double>* v :
         {&ch.speed, &ch.fx, &ch.fy, &ch.fz, &ch.slip_angle, &ch.slip_ratio}) {
      EXPECT_EQ(v->size(), 9u);
    }
    EXPECT_DOUBLE_EQ(ch.speed[1], 15.0 + c);  // t = 10.25 s, a quarter of the way to 11 s
    EXPECT_DOUBLE_EQ(ch.speed[4], 30.0 + c);  // on the sample at 11 s
    EXPECT_DOUBLE_EQ(ch.speed[6], 40.0 + c);  // t = 11.5 s, past the kink
    EXPECT_DOUBLE_EQ(ch.speed[8], 50.0 + c);  // the last sample
  }
  EXPECT_DOUBLE_EQ(r.corners[2].fx[1], -100.0);
  EXPECT_DOUBLE_EQ(r.corners[3].fz[7], 4350.0);
  EXPECT_DOUBLE_EQ(r.ambient_temp[6], 293.0);
  EXPECT_DOUBLE_EQ(r.track_temp[2], 302.0);
  // The result is a log the replay accepts.
  const vehicle::Car car = Gen7Car();
  EXPECT_NO_THROW(RunReplay(car, r, WarmStart(car), {}));
}

TEST(ReplayTest, ResampleRepeatsLapsWithOneSampleSpacingBetweenThem) {
  const ReplayInputs in = KinkedInputs();
  const ReplayInputs r = ResampleReplayInputs(in, 4.0, 3);
  // Period 2 s + 0.5 s (the first spacing); floor(2.5 s * 4 Hz) = 10 samples a lap.
  const size_t per_lap = 10;
  ASSERT_EQ(r.time.size(), 3 * per_lap);
  for (size_t l = 0; l < 3; ++l) {
    for (size_t k = 0; k < per_lap; ++k) {
      EXPECT_DOUBLE_EQ(r.time[l * per_lap + k], 10.0 + 2.5 * l + 0.25 * k) << l << " " << k;
    }
  }
  for (size_t i = 1; i < r.time.size(); ++i) ASSERT_GT(r.time[i], r.time[i - 1]) << i;
  EXPECT_DOUBLE_EQ(r.corners[0].speed[6], 40.0);  // t = 11.5 s into the first lap
  EXPECT_DOUBLE_EQ(r.corners[0].speed[9], 50.0);  // 12.25 s: past the log, held
  for (int c = 0; c < 4; ++c) {
    const CornerChannels& ch = r.corners[c];
    for (const std::vector<double>* v : {&ch.speed, &ch.fx, &ch.fy, &ch.fz, &ch.slip_angle,
                                         &ch.slip_ratio, &r.ambient_temp, &r.track_temp}) {
      ASSERT_EQ(v->size(), 3 * per_lap);
      for (size_t i = per_lap; i < v->size(); ++i) {
        EXPECT_EQ((*v)[i], (*v)[i - per_lap]) << "corner " << c << " sample " << i;
      }
    }
  }
}

TEST(ReplayTest, ResampleRejectsBadArguments) {
  const ReplayInputs in = KinkedInputs();
  EXPECT_THROW(ResampleReplayInputs(in, 0.0), InputError);
  EXPECT_THROW(ResampleReplayInputs(in, -10.0), InputError);
  EXPECT_THROW(ResampleReplayInputs(in, std::nan("")), InputError);
  EXPECT_THROW(ResampleReplayInputs(in, 10.0, 0), InputError);
  EXPECT_THROW(ResampleReplayInputs(in, 10.0, -2), InputError);
  EXPECT_THROW(ResampleReplayInputs(in, 0.1), InputError);  // a single sample in 2 s
  ReplayInputs one = in;
  for (auto* v : {&one.time, &one.ambient_temp, &one.track_temp}) v->resize(1);
  for (CornerChannels& ch : one.corners) {
    for (auto* v : {&ch.speed, &ch.fx, &ch.fy, &ch.fz, &ch.slip_angle, &ch.slip_ratio}) {
      v->resize(1);
    }
  }
  EXPECT_THROW(ResampleReplayInputs(one, 10.0), InputError);
  ReplayInputs short_fy = in;
  short_fy.corners[1].fy.pop_back();
  EXPECT_THROW(ResampleReplayInputs(short_fy, 10.0), InputError);
}

TEST(ReplayTest, RejectsNonIncreasingTimeAndWrongLengths) {
  const vehicle::Car car = Gen7Car();
  ReplayInputs in = ResampleReplayInputs(ExampleInputs(), 10.0);
  ReplayInputs bad_time = in;
  bad_time.time[5] = bad_time.time[4];
  EXPECT_THROW(RunReplay(car, bad_time, WarmStart(car), {}), InputError);
  ReplayInputs short_fx = in;
  short_fx.corners[2].fx.pop_back();
  try {
    RunReplay(car, short_fx, WarmStart(car), {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fx_rl"), std::string::npos) << e.what();
  }
}

// A corner's samples are spans into the inputs; its brake's take the brake's own force where the
// inputs have one, and refuse one of another length than time (RunStochasticReplay had no check).
TEST(ReplayTest, BrakeSamplesTakeTheBrakesOwnForce) {
  ReplayInputs in = ResampleReplayInputs(ExampleInputs(), 10.0);
  const CornerSamples tyre = CornerSamplesOf(in, Corner::kRearLeft);
  EXPECT_EQ(tyre.fx.data(), in.corners[2].fx.data());
  EXPECT_EQ(tyre.ambient_temp.data(), in.ambient_temp.data());
  EXPECT_EQ(BrakeSamplesOf(in, Corner::kRearLeft).fx.data(), in.corners[2].fx.data());
  in.corners[2].brake_fx.assign(in.time.size(), -100.0);
  const CornerSamples brake = BrakeSamplesOf(in, Corner::kRearLeft);
  EXPECT_EQ(brake.fx.data(), in.corners[2].brake_fx.data());
  EXPECT_EQ(brake.fy.data(), in.corners[2].fy.data());
  in.corners[2].brake_fx.pop_back();
  try {
    BrakeSamplesOf(in, Corner::kRearLeft);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(), "the brake force of corner rl")) << e.what();
  }
}

// A log's brake_power column is that brake's heat input: the force the brake takes gives the
// logged power back at the corner's speed, resampling keeps it, and a replay's brake power is it.
TEST(ReplayTest, ALoggedBrakePowerIsTheBrakesInput) {
  const fs::path source = fs::path(HOTLAP_SOURCE_DIR) / "data/telemetry/darlington_example.csv";
  const test::TempDir dir;
  {
    std::ifstream in(source);
    std::ofstream out(dir.path() / "log.csv");
    std::string line;
    bool header = true;
    int row = 0;
    while (std::getline(in, line)) {
      if (line.starts_with("#")) {
        out << line << "\n";
      } else if (header) {
        out << line << ",brake_power_rl_kW\n";
        header = false;
      } else {
        out << line << "," << (row++ % 2 == 0 ? "20" : "0") << "\n";  // 20 kW, every other row
      }
    }
  }
  const Telemetry log = Telemetry::Read(dir.path() / "log.csv");
  const ReplayInputs in = ReplayInputsFromTelemetry(log, {});
  const CornerChannels& rl = in.corners[CornerIndex(Corner::kRearLeft)];
  ASSERT_EQ(rl.brake_fx.size(), in.time.size());
  for (size_t k = 0; k < in.time.size(); k += 97) {
    EXPECT_NEAR(rl.brake_fx[k] * -rl.speed[k], k % 2 == 0 ? 20000.0 : 0.0, 1e-6) << k;
  }
  for (Corner c : {Corner::kFrontLeft, Corner::kFrontRight, Corner::kRearRight}) {
    EXPECT_TRUE(in.corners[CornerIndex(c)].brake_fx.empty()) << CornerName(c);
  }
  EXPECT_EQ(ResampleReplayInputs(in, 10.0).corners[2].brake_fx.size(),
            ResampleReplayInputs(in, 10.0).time.size());
  const vehicle::Car car = Gen7Car();
  const ReplayResult r = RunReplay(car, in, WarmStart(car), {});
  const CornerHistory& h = r.corners[CornerIndex(Corner::kRearLeft)];
  const ReplayResult example = RunReplay(car, ExampleInputs(), WarmStart(car), {});
  const CornerHistory& plain = example.corners[CornerIndex(Corner::kRearLeft)];
  for (size_t k = 0; k < in.time.size(); k += 97) {
    EXPECT_NEAR(h.brake_power[k], k % 2 == 0 ? 20000.0 : 0.0, 1e-6) << k;
  }
  // The disc integrates that power, not the tyre's: 10 kW on average all lap instead of the
  // example's braking zones (its disc peaks near 940 degC) runs it far from the plain replay.
  double gap = 0.0;
  for (size_t k = 0; k < h.disc_temp.size(); ++k) {
    gap = std::max(gap, std::abs(h.disc_temp[k] - plain.disc_temp[k]));
  }
  EXPECT_GT(gap, 100.0);
  EXPECT_EQ(r.corners[0].disc_temp, example.corners[0].disc_temp);  // the other corners alike
}

TEST(ReplayTest, DivergenceIsReportedNotReturned) {
  const vehicle::Car car = Gen7Car();
  ReplayInputs in = ResampleReplayInputs(ExampleInputs(), 10.0);
  // An absurd braking force heats the front-left disc far past any material limit.
  for (double& fx : in.corners[0].fx) fx = -5e6;
  EXPECT_THROW(RunReplay(car, in, WarmStart(car), {}), NumericalError);
}

// Initial temperatures: first measured value, else the command line, else the car file.
TEST(ReplayIoTest, InitialStatePrefersMeasuredThenOverridesThenCar) {
  const test::TempDir dir;
  const fs::path csv = dir.Write("log.csv",
                                 "time_s,tread_temp_fl_C,disc_temp_fr_K\n"
                                 "0,,\n"
                                 "0.1,71.5,\n"
                                 "0.2,72,600\n");
  const Telemetry log = Telemetry::Read(csv);
  const vehicle::Car car = Gen7Car();
  InitialTemperatureOverrides o;
  o.carcass_temp = CelsiusToKelvin(55.0);
  const ReplayInitialState s = InitialStateFor(log, car, o);
  EXPECT_DOUBLE_EQ(s.tyres[0].tread_temp, CelsiusToKelvin(71.5));    // first non-empty value
  EXPECT_DOUBLE_EQ(s.brakes[1].disc_temp, 600.0);                    // K column
  EXPECT_DOUBLE_EQ(s.tyres[0].carcass_temp, CelsiusToKelvin(55.0));  // override
  EXPECT_DOUBLE_EQ(s.tyres[3].tread_temp, car.initial.tread_temp);   // car file
  EXPECT_DOUBLE_EQ(s.brakes[2].calliper_temp, car.initial.calliper_temp);
  EXPECT_DOUBLE_EQ(s.tyres[2].wear, 0.0);
}

// A three-line log with every corner input, then the columns `header` names (",name,...") with
// the cells `cells` (",value,...") on every line.
std::string SmallLog(const std::string& header, const std::string& cells) {
  std::ostringstream f;
  f << "time_s,speed_mps";
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    f << ",fx_" << c << "_N,fy_" << c << "_N,fz_" << c << "_N,slip_angle_" << c
      << "_rad,slip_ratio_" << c;
  }
  f << header << "\n";
  for (int k = 0; k < 3; ++k) {
    f << k * 0.1 << ",50";
    for (int c = 0; c < 4; ++c) f << ",100,200,4000,0.01,0.001";
    f << cells << "\n";
  }
  return f.str();
}

TEST(ReplayIoTest, MissingAmbientNeedsAnOption) {
  const test::TempDir dir;
  const Telemetry log = Telemetry::Read(dir.Write("log.csv", SmallLog(",track_temp_C", ",40")));
  try {
    ReplayInputsFromTelemetry(log, {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "none given instead (hotlap: --ambient-temp-C; Python: ambient_temp_C=)"),
              std::string::npos)
        << e.what();
  }
  InitialTemperatureOverrides o;
  o.ambient_temp = CelsiusToKelvin(20.0);
  const ReplayInputs in = ReplayInputsFromTelemetry(log, o);
  EXPECT_DOUBLE_EQ(in.ambient_temp[2], CelsiusToKelvin(20.0));
  EXPECT_DOUBLE_EQ(in.track_temp[0], CelsiusToKelvin(40.0));
}

// A column with no value on any row (a dead air-temperature sensor) is as good as none: the option
// stands in for it, and without one the message names the option (it refused even with one).
TEST(ReplayIoTest, AnEmptyAmbientColumnTakesTheOption) {
  const test::TempDir dir;
  const Telemetry log =
      Telemetry::Read(dir.Write("log.csv", SmallLog(",ambient_temp_C,track_temp_C", ",,40")));
  try {
    ReplayInputsFromTelemetry(log, {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(test::Contains(e.what(),
                               "column 'ambient_temp_C' (or '_K') has no value on any row, "
                               "and none given instead (hotlap: --ambient-temp-C"))
        << e.what();
  }
  InitialTemperatureOverrides o;
  o.ambient_temp = CelsiusToKelvin(5.0);
  const ReplayInputs in = ReplayInputsFromTelemetry(log, o);
  EXPECT_DOUBLE_EQ(in.ambient_temp[1], CelsiusToKelvin(5.0));
}

}  // namespace
}  // namespace hotlap::sim
