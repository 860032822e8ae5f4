// The corner filters: the prediction is replay's integration (same means), the Jacobian from Jets
// is the discrete map's (against central differences), the Jet2 path equals the Jet5 path, and
// the scalar update against its closed form and gate; the sensor-lag states: their means are
// synth's first-order sensor over the predicted states, their covariance the linear map's, and
// with a zero time constant a filter is the same as without the lag.

#include "hotlap/observe/corner_filter.h"

#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/logs/telemetry.h"
#include "hotlap/observe/car_observer.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/synth_sensor.h"
#include "test_util.h"

namespace hotlap::observe {
namespace {

using test::SourcePath;

struct Fixture {
  vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  ObserverConfig config = LoadObserverConfig(SourcePath("data/observer/default.yaml"));
  sim::ReplayInputs in;
  Fixture() {
    const Telemetry log = Telemetry::Read(SourcePath("data/telemetry/darlington_example.csv"));
    in = sim::ReplayInputsFromTelemetry(log, {});
  }
};

// Two samples k, k+1 of corner c as CornerSamples over the given arrays.
struct Interval {
  std::array<double, 2> time, speed, fx, fy, fz, slip_angle, slip_ratio, ambient, track;
  Interval(const sim::ReplayInputs& in, int c, size_t k) {
    const auto pair = [&](const std::vector<double>& v) {
      return std::array<double, 2>{v[k], v[k + 1]};
    };
    const sim::CornerChannels& ch = in.corners[c];
    time = pair(in.time);
    speed = pair(ch.speed);
    fx = pair(ch.fx);
    fy = pair(ch.fy);
    fz = pair(ch.fz);
    slip_angle = pair(ch.slip_angle);
    slip_ratio = pair(ch.slip_ratio);
    ambient = pair(in.ambient_temp);
    track = pair(in.track_temp);
  }
  sim::CornerSamples Samples() const {
    return {time, speed, fx, fy, fz, slip_angle, slip_ratio, ambient, track};
  }
};

// The index of a sample where corner c brakes hard (the largest -fx), so every heat flow is on.
size_t BrakingSample(const sim::ReplayInputs& in, int c) {
  size_t best = 0;
  for (size_t k = 0; k + 1 < in.time.size(); ++k) {
    if (in.corners[c].fx[k] < in.corners[c].fx[best]) best = k;
  }
  return best;
}

TEST(CornerFilterTest, WithoutReadingsTheMeansAreReplays) {
  const Fixture f;
  const sim::ReplayInputs& in = f.in;
  // The filters run the paper's models (docs/observer.md): their means are that replay's.
  const vehicle::Car paper = vehicle::PaperModelsOf(f.car);
  const sim::ReplayInitialState initial = sim::CarStartState(paper);
  sim::ReplayOptions options;
  options.max_step_s = f.config.max_step_s;
  const sim::ReplayResult replay = sim::RunReplay(paper, in, initial, options);

  CarObserver observer(f.car, f.config);
  double worst = 0.0;
  for (size_t k = 0; k < in.time.size(); ++k) {
    ObserverSample s;
    s.time = in.time[k];
    s.ambient_temp = in.ambient_temp[k];
    s.track_temp = in.track_temp[k];
    for (int c = 0; c < 4; ++c) {
      const sim::CornerChannels& ch = in.corners[c];
      s.inputs[c] = {ch.speed[k], ch.fx[k], ch.fy[k], ch.fz[k], ch.slip_angle[k], ch.slip_ratio[k]};
      if (!ch.brake_fx.empty()) s.inputs[c].brake_fx = ch.brake_fx[k];  // the rear spool's share
    }
    observer.Step(s);
    for (Corner c : kAllCorners) {
      const CornerEstimate e = observer.Estimate(c);
      const sim::CornerHistory& h = replay.corners[CornerIndex(c)];
      worst = std::max({worst, std::abs(e.tread_temp - h.tread_temp[k]),
                        std::abs(e.carcass_temp - h.carcass_temp[k]),
                        1e3 * std::abs(e.wear - h.wear[k]), std::abs(e.disc_temp - h.disc_temp[k]),
                        std::abs(e.calliper_temp - h.calliper_temp[k])});
    }
  }
  // Same integrator, same stages: equal to rounding (the input-term series aside, 1e-15).
  EXPECT_LT(worst, 1e-9);
  // The uncertainty grows without readings.
  EXPECT_GT(observer.Estimate(Corner::kFrontLeft).wear_sd, 2.0 * f.config.initial_sd.wear);
}

// The predicted mean of a tyre filter from `mean` over `interval` (zero covariance).
Eigen::Vector4d PredictTyre(const Fixture& f, int c, bool with_p5, const Interval& interval,
                            const Eigen::Vector4d& mean) {
  P5Scale p5;
  p5.estimate = with_p5;
  TyreFilter filter(f.car.tyres[c].params, f.car.tyres[c].compound, f.config.process, p5,
                    f.config.max_step_s);
  Gaussian<4> g;
  g.mean = mean;
  filter.Reset(g);
  filter.Predict(interval.Samples());
  return filter.estimate().mean;
}

TEST(CornerFilterTest, TyreJacobianIsTheDiscreteMapsAndBothPathsAgree) {
  const Fixture f;
  for (int c : {0, 3}) {
    const size_t k = BrakingSample(f.in, c);
    const Interval interval(f.in, c, k);
    // A hot tyre, part worn, p5 off its nominal value.
    const Eigen::Vector4d mean(380.0, 360.0, 0.4, 1.1);
    P5Scale p5;
    p5.estimate = true;
    TyreFilter full(f.car.tyres[c].params, f.car.tyres[c].compound, f.config.process, p5,
                    f.config.max_step_s);
    Gaussian<4> g;
    g.mean = mean;
    full.Reset(g);
    full.Predict(interval.Samples());
    const Eigen::Matrix4d F = full.transition();
    for (int j = 0; j < 4; ++j) {
      Eigen::Vector4d up = mean, down = mean;
      // A relative step of 1e-5: the p5 column's derivatives are 1e-3 of the temperatures, so a
      // smaller step leaves rounding (1e-16 * 360 K / h) comparable with the tolerance.
      const double h = 1e-5 * std::abs(mean(j));
      up(j) += h;
      down(j) -= h;
      const Eigen::Vector4d fd =
          (PredictTyre(f, c, true, interval, up) - PredictTyre(f, c, true, interval, down)) /
          (2 * h);
      for (int i = 0; i < 3; ++i) {
        test::ExpectNearDerivative(F(i, j), fd(i), std::abs(mean(i) / mean(j)),
                                   "corner " + std::to_string(c) + " F(" + std::to_string(i) + "," +
                                       std::to_string(j) + ")");
      }
    }
    // Wear enters no derivative: its column is e_wear.
    EXPECT_EQ(F(0, 2), 0.0);
    EXPECT_EQ(F(1, 2), 0.0);
    EXPECT_EQ(F(2, 2), 1.0);
    EXPECT_NE(F(0, 3), 0.0);  // p5 moves the tread temperature
    // The Jet2 path (no p5 state) gives the same mean and the same first three columns.
    p5.estimate = false;
    TyreFilter small(f.car.tyres[c].params, f.car.tyres[c].compound, f.config.process, p5,
                     f.config.max_step_s);
    g.mean(3) = 1.0;
    small.Reset(g);
    small.Predict(interval.Samples());
    full.Reset(g);
    full.Predict(interval.Samples());
    for (int i = 0; i < 3; ++i) {
      EXPECT_DOUBLE_EQ(small.estimate().mean(i), full.estimate().mean(i));
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(small.transition()(i, j), full.transition()(i, j), 1e-14);
      }
      EXPECT_EQ(small.transition()(i, 3), 0.0);
    }
  }
}

TEST(CornerFilterTest, BrakeJacobianIsTheDiscreteMaps) {
  const Fixture f;
  const int c = 0;
  const Interval interval(f.in, c, BrakingSample(f.in, c));
  const auto predict = [&](const Eigen::Vector2d& mean) {
    BrakeFilter filter(f.car.brakes[c].params, f.config.process, f.config.max_step_s);
    Gaussian<2> g;
    g.mean = mean;
    filter.Reset(g);
    filter.Predict(interval.Samples());
    return std::make_pair(filter.estimate().mean, Eigen::Matrix2d(filter.transition()));
  };
  const Eigen::Vector2d mean(700.0, 450.0);
  const Eigen::Matrix2d F = predict(mean).second;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d up = mean, down = mean;
    const double h = 1e-6 * mean(j);
    up(j) += h;
    down(j) -= h;
    const Eigen::Vector2d fd = (predict(up).first - predict(down).first) / (2 * h);
    for (int i = 0; i < 2; ++i) test::ExpectNearDerivative(F(i, j), fd(i), 1.0, "brake F");
  }
  EXPECT_GT(F(0, 0), 0.0);
  EXPECT_LT(F(0, 0), 1.0);  // the disc cools towards the air and the calliper
}

TEST(CornerFilterTest, ScalarUpdateMatchesTheClosedFormAndGates) {
  Gaussian<2> g;
  g.mean << 10.0, 5.0;
  g.cov << 4.0, 2.0, 2.0, 3.0;
  // Reading 12 of state 0 with variance 1: gain = P(:,0) / 5.
  UpdateOutcome u = UpdateScalar(g, 0, 12.0, 1.0, 25.0);
  EXPECT_TRUE(u.used);
  EXPECT_DOUBLE_EQ(u.nis, 4.0 / 5.0);
  EXPECT_NEAR(g.mean(0), 10.0 + 0.8 * 2.0, 1e-12);
  EXPECT_NEAR(g.mean(1), 5.0 + 0.4 * 2.0, 1e-12);
  EXPECT_NEAR(g.cov(0, 0), 4.0 - 16.0 / 5.0, 1e-12);
  EXPECT_NEAR(g.cov(0, 1), 2.0 - 8.0 / 5.0, 1e-12);
  EXPECT_NEAR(g.cov(1, 1), 3.0 - 4.0 / 5.0, 1e-12);
  // A reading 20 sigma away is rejected and changes nothing.
  const Gaussian<2> before = g;
  u = UpdateScalar(g, 0, g.mean(0) + 20.0 * std::sqrt(g.cov(0, 0) + 1.0), 1.0, 25.0);
  EXPECT_TRUE(u.rejected);
  EXPECT_FALSE(u.used);
  EXPECT_NEAR(u.nis, 400.0, 1e-9);
  EXPECT_EQ(g.mean, before.mean);
  EXPECT_EQ(g.cov, before.cov);
}

// Without readings, the lag state's mean is exactly synth's sensor (sim::FirstOrderLag) reading the
// filter's own predicted means, for the tread and for both brake sensors; the states' means are
// those of a filter without the lag.
TEST(CornerFilterTest, TheLagStateIsTheFirstOrderSensorOfThePredictedState) {
  const Fixture f;
  const int c = 1;
  const double tau = 0.2;
  TyreFilter lagged(f.car.tyres[c].params, f.car.tyres[c].compound, f.config.process, {},
                    f.config.max_step_s, tau);
  TyreFilter plain(f.car.tyres[c].params, f.car.tyres[c].compound, f.config.process, {},
                   f.config.max_step_s);
  BrakeFilter brake(f.car.brakes[c].params, f.config.process, f.config.max_step_s, tau, 2.0 * tau);
  Gaussian<4> g;
  g.mean << 330.0, 335.0, 0.0, 1.0;
  g.cov.diagonal() << 1.0, 4.0, 1e-12, 0.0;
  lagged.Reset(g);
  plain.Reset(g);
  Gaussian<2> b;
  b.mean << 600.0, 400.0;
  b.cov.diagonal() << 4.0, 9.0;
  brake.Reset(b);
  ASSERT_TRUE(lagged.lag().Active());
  ASSERT_FALSE(plain.lag().Active());
  sim::FirstOrderLag<double> tread(tau), disc(tau), calliper(2.0 * tau);
  tread.Next(f.in.time[0], g.mean(0));
  disc.Next(f.in.time[0], b.mean(0));
  calliper.Next(f.in.time[0], b.mean(1));
  EXPECT_EQ(lagged.lag().mean(0), 330.0);
  EXPECT_EQ(lagged.lag().var(0), 1.0);  // settled: the state's variance
  double worst = 0.0, moved = 0.0;
  for (size_t k = 0; k + 1 < f.in.time.size(); ++k) {
    const Interval interval(f.in, c, k);
    lagged.Predict(interval.Samples());
    plain.Predict(interval.Samples());
    brake.Predict(interval.Samples());
    const double t = f.in.time[k + 1];
    worst =
        std::max({worst, std::abs(lagged.lag().mean(0) - tread.Next(t, lagged.estimate().mean(0))),
                  std::abs(brake.lag().mean(0) - disc.Next(t, brake.estimate().mean(0))),
                  std::abs(brake.lag().mean(1) - calliper.Next(t, brake.estimate().mean(1))),
                  std::abs(lagged.estimate().mean(0) - plain.estimate().mean(0))});
    moved = std::max(moved, std::abs(lagged.lag().mean(0) - lagged.estimate().mean(0)));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(moved, 0.1);  // the sensor does trail the state
  // The lag's variance stays a variance and below the state's plus its process noise.
  EXPECT_GT(lagged.lag().var(0), 0.0);
  EXPECT_GT(brake.lag().var(1), 0.0);
}

// The lag state's covariance is the linear map's: over one interval from a settled sensor and
// correlated states, compared with a central-difference Jacobian of the joint map (states by the
// filter's prediction, sensor by the first-order formula) applied to the same covariance; and a
// reading through the lag corrects the states through the cross
// covariance (a tread reading moves the carcass).
TEST(CornerFilterTest, TheLagCovarianceIsTheJointLinearMap) {
  const Fixture f;
  const int c = 0;
  const double tau = 0.3;
  const size_t k = BrakingSample(f.in, c);
  const Interval interval(f.in, c, k);
  const double dt = f.in.time[k + 1] - f.in.time[k];
  ObserverConfig config = f.config;
  config.process = {};  // no process noise: P1 = J P0 J' exactly
  // The joint map (tread, carcass, wear, sensor) -> the same, one interval.
  const auto map = [&](const Eigen::Vector4d& z) {
    TyreFilter filter(f.car.tyres[c].params, f.car.tyres[c].compound, config.process, {},
                      config.max_step_s);
    Gaussian<4> g;
    g.mean << z(0), z(1), z(2), 1.0;
    filter.Reset(g);
    filter.Predict(interval.Samples());
    const double a = std::exp(-dt / tau), b = 1.0 - tau * (1.0 - a) / dt;
    Eigen::Vector4d out;
    out << filter.estimate().mean(0), filter.estimate().mean(1), filter.estimate().mean(2),
        a * z(3) + (1.0 - a - b) * z(0) + b * filter.estimate().mean(0);
    return out;
  };
  const Eigen::Vector4d z0(345.0, 340.0, 0.1, 343.0);
  Eigen::Matrix4d jac;
  for (int j = 0; j < 4; ++j) {
    const double h = j == 2 ? 1e-6 : 1e-4;
    Eigen::Vector4d up = z0, down = z0;
    up(j) += h;
    down(j) -= h;
    jac.col(j) = (map(up) - map(down)) / (2.0 * h);
  }
  // A covariance of the states with correlations; the sensor starts settled on the tread.
  Eigen::Matrix3d root;
  root << 1.0, 0.0, 0.0, 0.5, 2.0, 0.0, 0.0, 0.0, 1e-3;
  const Eigen::Matrix3d p0 = root * root.transpose();
  Gaussian<4> states;
  states.mean << z0(0), z0(1), z0(2), 1.0;
  states.cov.topLeftCorner<3, 3>() = p0;
  // The joint covariance of the settled start, mapped by the central-difference Jacobian.
  TyreFilter filter(f.car.tyres[c].params, f.car.tyres[c].compound, config.process, {},
                    config.max_step_s, tau);
  filter.Reset(states);
  filter.Predict(interval.Samples());
  Eigen::Matrix4d settled = Eigen::Matrix4d::Zero();
  settled.topLeftCorner<3, 3>() = p0;
  settled.row(3).head<3>() = p0.row(0);
  settled.col(3).head<3>() = p0.col(0);
  settled(3, 3) = p0(0, 0);
  const Eigen::Matrix4d expect = jac * settled * jac.transpose();
  EXPECT_NEAR(filter.lag().var(0), expect(3, 3), 1e-6 * expect(3, 3));
  for (int i = 0; i < 3; ++i) {
    const double scale = std::sqrt(expect(i, i) * expect(3, 3));
    EXPECT_NEAR(filter.estimate().cov(i, i), expect(i, i), 1e-6 * expect(i, i) + 1e-15) << i;
    EXPECT_NEAR(filter.lag().cross(i, 0), expect(i, 3), 1e-6 * scale + 1e-15) << i;
  }
  // A tread reading 2 K above what the sensor should read moves the tread, the carcass and the
  // sensor state up, and shrinks the sensor's variance.
  const double before_carcass = filter.estimate().mean(1), before_var = filter.lag().var(0);
  const UpdateOutcome u = filter.UpdateTread(filter.lag().mean(0) + 2.0, 0.5, 25.0);
  EXPECT_TRUE(u.used);
  EXPECT_NEAR(u.innovation, 2.0, 1e-12);
  EXPECT_NEAR(u.nis, 4.0 / (before_var + 0.25), 1e-12);
  EXPECT_GT(filter.estimate().mean(1), before_carcass);
  EXPECT_LT(filter.lag().var(0), before_var);
}

// With every time constant zero the filters do not carry the lag and equal the plain ones.
TEST(CornerFilterTest, AZeroLagIsNoLag) {
  const Fixture f;
  BrakeFilter zero(f.car.brakes[2].params, f.config.process, f.config.max_step_s, 0.0, 0.0);
  BrakeFilter plain(f.car.brakes[2].params, f.config.process, f.config.max_step_s);
  EXPECT_FALSE(zero.lag().Active());
  Gaussian<2> b;
  b.mean << 500.0, 300.0;
  b.cov.diagonal() << 4.0, 9.0;
  zero.Reset(b);
  plain.Reset(b);
  for (size_t k = 0; k + 1 < 200; ++k) {
    const Interval interval(f.in, 2, k);
    zero.Predict(interval.Samples());
    plain.Predict(interval.Samples());
    const double z = plain.estimate().mean(0) + (k % 2 == 0 ? 0.4 : -0.3);
    zero.UpdateDisc(z, 0.5, 25.0);
    plain.UpdateDisc(z, 0.5, 25.0);
  }
  EXPECT_EQ(zero.estimate().mean, plain.estimate().mean);
  EXPECT_EQ(zero.estimate().cov, plain.estimate().cov);
}

}  // namespace
}  // namespace hotlap::observe
