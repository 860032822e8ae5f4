// The observer on the car's own models (observe/wheel_filter.h, ObservedModels::kCar): without
// readings its mean is the replay of those models; its transition is the derivative of the
// prediction; on a log whose truth is the car's own models, with TPMS channels, every sensor's
// innovations are chi-square(1) and the gas and hot pressure are tracked within their bands,
// where the paper's models fail the same check.

#include "hotlap/observe/wheel_filter.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/observe/car_observer.h"
#include "hotlap/observe/observer_config.h"
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

// Two laps of Darlington at 50 Hz with the car's own models as the truth: 0.5 degC temperature
// sensors without lag, TPMS with the synth's defaults (0.35 kPa, 0.5 degC, 2 s lag; the observer's
// noise file says the same).
const sim::SynthLog& CarTruthLaps() {
  static const sim::SynthLog log = [] {
    sim::SynthOptions o;
    o.laps = 2;
    o.rate_hz = 50.0;
    o.sensor_lag_s = 0.0;
    o.paper_models = false;
    return testing::DarlingtonLog(o);
  }();
  return log;
}

// The log's samples as the observer takes them; without `readings`, none read.
std::vector<ObserverSample> Samples(const sim::SynthLog& log, bool readings) {
  const sim::ReplayInputs& in = log.inputs;
  std::vector<ObserverSample> out(in.time.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
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
      if (!ch.brake_fx.empty()) s.inputs[i].brake_fx = ch.brake_fx[k];
      const auto read = [&](const std::string& column, double scale, double offset) {
        return readings ? scale * Column(log, column)[k] + offset : nan;
      };
      s.readings[i] = {read("tread_temp_" + n + "_C", 1.0, kZeroCelsius),
                       read("disc_temp_" + n + "_C", 1.0, kZeroCelsius),
                       read("calliper_temp_" + n + "_C", 1.0, kZeroCelsius),
                       read("pressure_" + n + "_kPa", 1e3, 0.0),
                       read("gas_temp_" + n + "_C", 1.0, kZeroCelsius)};
    }
  }
  return out;
}

TEST(WheelFilterTest, WithoutReadingsTheMeanIsTheReplayOfTheCarsModels) {
  const sim::SynthLog& log = CarTruthLaps();
  CarObserver observer(Gen7(), DefaultConfig(), {}, ObservedModels::kCar);
  for (const ObserverSample& s : Samples(log, false)) observer.Step(s);
  for (Corner c : kAllCorners) {
    ASSERT_TRUE(observer.observes_gas(c));
    const CornerEstimate e = observer.Estimate(c);
    const sim::CornerHistory& truth = log.truth.corners[CornerIndex(c)];
    // The same integrator on the same inputs: equal to round-off.
    EXPECT_NEAR(e.tread_temp, truth.tread_temp.back(), 1e-8);
    EXPECT_NEAR(e.carcass_temp, truth.carcass_temp.back(), 1e-8);
    EXPECT_NEAR(e.rim_temp, truth.rim_temp.back(), 1e-8);
    EXPECT_NEAR(e.disc_temp, truth.disc_temp.back(), 1e-8);
    EXPECT_NEAR(e.calliper_temp, truth.calliper_temp.back(), 1e-8);
    EXPECT_NEAR(e.gas_temp, truth.gas_temp.back(), 1e-8);
    EXPECT_NEAR(e.pressure, truth.pressure.back(), 1e-5);
    if (!truth.disc_bulk_temp.empty()) {
      EXPECT_NEAR(e.disc_bulk_temp, truth.disc_bulk_temp.back(), 1e-8);
    }
    EXPECT_NEAR(e.wear, truth.wear.back(), 1e-12);
    // Nothing read: the bands grow from the start's.
    EXPECT_GT(e.carcass_temp_sd, DefaultConfig().initial_sd.carcass_temp * 0.5);
  }
}

TEST(WheelFilterTest, TheTransitionIsTheDerivativeOfThePrediction) {
  const sim::SynthLog& log = CarTruthLaps();
  const Corner c = Corner::kFrontLeft;
  const int i = CornerIndex(c);
  const ObserverConfig config = DefaultConfig();
  const auto make = [&] {
    return WheelFilter(Gen7().tyre(c).params, Gen7().tyre(c).compound, Gen7().brake(c).params,
                       config.process, *config.car_models, config.max_step_s, config.sensor_lag);
  };
  // An interval inside the first braking zone (the largest fx at the front left).
  const sim::CornerChannels& ch = log.inputs.corners[i];
  size_t k = 0;
  for (size_t j = 0; j + 1 < ch.fx.size(); ++j) {
    if (ch.fx[j] < ch.fx[k]) k = j;
  }
  const std::array<double, 2> time = {log.inputs.time[k], log.inputs.time[k + 1]},
                              speed = {ch.speed[k], ch.speed[k + 1]}, fx = {ch.fx[k], ch.fx[k + 1]},
                              fy = {ch.fy[k], ch.fy[k + 1]}, fz = {ch.fz[k], ch.fz[k + 1]},
                              alpha = {ch.slip_angle[k], ch.slip_angle[k + 1]},
                              kappa = {ch.slip_ratio[k], ch.slip_ratio[k + 1]},
                              ambient = {298.15, 298.15}, track = {313.15, 313.15};
  const sim::CornerSamples in{time, speed, fx, fy, fz, alpha, kappa, ambient, track};
  Gaussian<WheelFilter::kStates> start;
  start.mean << 360.0, 380.0, 0.1, 330.0, 700.0, 420.0, 650.0;
  WheelFilter base = make();
  base.Reset(start, speed[0]);
  base.Predict(in, in);
  for (int j = 0; j < WheelFilter::kStates; ++j) {
    const double h = 1e-4 * std::max(1.0, std::abs(start.mean(j)));
    Gaussian<WheelFilter::kStates> plus = start, minus = start;
    plus.mean(j) += h;
    minus.mean(j) -= h;
    WheelFilter a = make(), b = make();
    a.Reset(plus, speed[0]);
    b.Reset(minus, speed[0]);
    a.Predict(in, in);
    b.Predict(in, in);
    for (int r = 0; r < WheelFilter::kStates; ++r) {
      const double fd = (a.estimate().mean(r) - b.estimate().mean(r)) / (2.0 * h);
      EXPECT_NEAR(base.transition()(r, j), fd, 1e-6 + 1e-5 * std::abs(fd)) << r << ", " << j;
    }
  }
}

TEST(WheelFilterTest, OnACarTruthLogTheTpmsAndTemperaturesAreConsistentAndTheGasTracked) {
  const sim::SynthLog& log = CarTruthLaps();
  // The carcass starts 5 degC off the truth: the TPMS and the tread bring it back.
  ObserverStart start;
  start.carcass_temp = Gen7().initial.carcass_temp + 5.0;
  CarObserver car(Gen7(), DefaultConfig(), start, ObservedModels::kCar);
  CarObserver paper(Gen7(), DefaultConfig(), start, ObservedModels::kPaper);
  const std::vector<ObserverSample> samples = Samples(log, true);
  for (const ObserverSample& s : samples) {
    car.Step(s);
    paper.Step(s);
  }
  bool paper_consistent = true;
  for (Corner c : kAllCorners) {
    for (Sensor s : kAllSensors) {
      const SensorMonitor& m = car.monitor(c, s);
      EXPECT_GT(m.used, static_cast<long>(samples.size()) / 2) << CornerName(c) << " " << int(s);
      // About chi-square(1): the deterministic truth has no process noise, so a mean may run
      // slightly below 1, never above the bound.
      EXPECT_LT(m.MeanNis(), m.Bounds95().second) << CornerName(c) << " " << SensorQuantity(s);
      EXPECT_GT(m.MeanNis(), 0.85) << CornerName(c) << " " << SensorQuantity(s);
      EXPECT_EQ(m.rejected, 0) << CornerName(c) << " " << SensorQuantity(s);
      const SensorMonitor& p = paper.monitor(c, s);
      if (p.readings > 0) paper_consistent = paper_consistent && p.Consistent();
    }
    EXPECT_EQ(paper.monitor(c, Sensor::kPressure).readings, 0);  // no gas to read
    const CornerEstimate e = car.Estimate(c);
    const sim::CornerHistory& truth = log.truth.corners[CornerIndex(c)];
    EXPECT_NEAR(e.gas_temp, truth.gas_temp.back(), 3.0 * e.gas_temp_sd + 0.02) << CornerName(c);
    EXPECT_NEAR(e.pressure, truth.pressure.back(), 3.0 * e.pressure_sd + 30.0) << CornerName(c);
    EXPECT_NEAR(e.carcass_temp, truth.carcass_temp.back(), 0.5) << CornerName(c);
    EXPECT_NEAR(e.rim_temp, truth.rim_temp.back(), 0.5) << CornerName(c);
    EXPECT_GT(e.pressure_sd, 0.0);
  }
  // The paper's models miss the rim's and the bulk's heat: their own readings say so.
  EXPECT_FALSE(paper_consistent);
}

TEST(WheelFilterTest, RefusesANoiseFileWithoutItsSectionAndTheP5State) {
  ObserverConfig config = DefaultConfig();
  config.car_models.reset();
  const std::string e =
      test::InputErrorOf([&] { CarObserver(Gen7(), config, {}, ObservedModels::kCar); });
  EXPECT_TRUE(test::Contains(e, "default.yaml")) << e;
  EXPECT_TRUE(test::Contains(e, "car_models")) << e;
  config = DefaultConfig();
  config.p5_scale.estimate = true;
  EXPECT_TRUE(test::Contains(
      test::InputErrorOf([&] { CarObserver(Gen7(), config, {}, ObservedModels::kCar); }),
      "paper's models only"));
  // The paper's observer needs no such section.
  config = DefaultConfig();
  config.car_models.reset();
  EXPECT_FALSE(CarObserver(Gen7(), config).observes_gas(Corner::kFrontLeft));
}

TEST(WheelFilterTest, ANoiseFileWithABadCarModelsValueIsRefusedNamingIt) {
  test::TempDir dir;
  std::string text = test::ReadTextFile(test::SourcePath("data/observer/default.yaml"));
  const size_t at = text.find("tpms_tau_s: 2.0");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 15, "tpms_tau_s: 0.0");
  const auto path = dir.path() / "noise.yaml";
  test::WriteTextFile(path, text);
  const std::string e = test::InputErrorOf([&] { LoadObserverConfig(path); });
  EXPECT_TRUE(test::Contains(e, "noise.yaml")) << e;
  EXPECT_TRUE(test::Contains(e, "tpms_tau_s")) << e;
}

}  // namespace
}  // namespace hotlap::observe
