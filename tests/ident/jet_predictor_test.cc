// Exact derivatives through the integrator: the Jacobian that JetPredictor gets from Jets carried
// through every RK4 step (and the sensor lag) matches central differences of the double model,
// for the tyre over a logged lap (7 parameters, one pass) and for a 16-parameter model (two
// passes: 14 lanes, then 2).

#include "hotlap/ident/jet_predictor.h"

#include <cmath>

#include <gtest/gtest.h>

#include "fit_test_util.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/sim/sampled_inputs.h"
#include "hotlap/sim/synth_sensor.h"

namespace hotlap::ident {
namespace {

// The tyre over a log as the tyre fit runs it: p1..p5 and the initial temperatures, lagged.
struct TyreModel {
  const tyre::TyreFile* tyre;
  sim::CornerSamples samples;
  size_t num_samples() const { return samples.time.size(); }
  int num_channels() const { return 2; }
  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    tyre::TyreThermalParams<T> p = tyre->params.Cast<T>();
    p.p1 = x[0];
    p.p2 = x[1];
    p.p3 = x[2];
    p.p4 = x[3];
    p.p5 = x[4];
    sim::FirstOrderLag<T> a(0.2), b(0.2);
    sim::IntegrateTyre<T>(p, *tyre->compound, samples, tyre::TyreState<T>{x[5], x[6], T(0.0)}, 0.02,
                          [&](size_t k, const tyre::TyreState<T>& s) {
                            emit(0, k, a.Next(samples.time[k], s.tread_temp));
                            emit(1, k, b.Next(samples.time[k], s.carcass_temp));
                          });
  }
};

// y_k = sum_i x_i^2 sin(i + k) + x_0 x_15, 16 parameters.
struct WideModel {
  size_t num_samples() const { return 20; }
  int num_channels() const { return 1; }
  template <Scalar T, class Emit>
  void Run(std::span<const T> x, Emit&& emit) const {
    for (size_t k = 0; k < 20; ++k) {
      T y = x[0] * x[15];
      for (size_t i = 0; i < 16; ++i) y += x[i] * x[i] * std::sin(double(i + k));
      emit(0, k, y);
    }
  }
};

template <class Model>
void ExpectJacobianMatchesDifferences(const JetPredictor<Model>& p, std::vector<double> x,
                                      double tolerance) {
  Predictions exact, up, down;
  ASSERT_TRUE(p.Predict(x, true, &exact));
  const size_t n = p.num_samples(), m = x.size();
  for (size_t i = 0; i < m; ++i) {
    std::vector<double> xu = x, xd = x;
    const double h = 1e-6 * std::max(std::abs(x[i]), 1e-3);
    xu[i] += h;
    xd[i] -= h;
    ASSERT_TRUE(p.Predict(xu, false, &up));
    ASSERT_TRUE(p.Predict(xd, false, &down));
    for (int c = 0; c < p.num_channels(); ++c) {
      double scale = 0.0;
      for (size_t k = 0; k < n; ++k)
        scale = std::max(scale, std::abs(exact.jacobian[c][k * m + i]));
      for (size_t k = 0; k < n; k += 7) {
        const double fd = (up.value[c][k] - down.value[c][k]) / (2 * h);
        EXPECT_NEAR(exact.jacobian[c][k * m + i], fd, tolerance * scale + 1e-12)
            << "parameter " << i << " channel " << c << " sample " << k;
      }
    }
  }
}

TEST(JetPredictorTest, TyreJacobianThroughTheIntegratorIsExact) {
  const vehicle::Car car = test::Gen7Car();
  sim::SynthOptions o;
  o.rate_hz = 20.0;
  const sim::SynthLog log = sim::SynthesizeLog(car, test::OvalRoad(), o);
  const TyreModel model{&car.tyres[3], CornerSamplesOf(log.inputs, Corner::kRearRight)};
  const auto& t = car.tyres[3].params;
  const std::vector<double> x = {t.p1, t.p2, t.p3, t.p4, t.p5, 335.0, 331.0};
  const JetPredictor<TyreModel> p(model, x, {0, 1, 2, 3, 4, 5, 6}, {0, 1});
  ExpectJacobianMatchesDifferences(p, x, 1e-5);
}

TEST(JetPredictorTest, SixteenParametersTakeTwoPasses) {
  const WideModel model;
  std::vector<double> x(16);
  for (int i = 0; i < 16; ++i) x[i] = 0.3 + 0.1 * i;
  std::vector<int> free(16);
  for (int i = 0; i < 16; ++i) free[i] = i;
  const JetPredictor<WideModel> p(model, x, free, {0});
  ExpectJacobianMatchesDifferences(p, x, 1e-7);
  // A subset in another order, with the rest held.
  const JetPredictor<WideModel> q(model, x, {15, 0, 7}, {0});
  Predictions out;
  ASSERT_TRUE(q.Predict(std::vector<double>{2.0, 0.3, 1.0}, true, &out));
  EXPECT_NEAR(out.jacobian[0][0], 0.3 + 2.0 * 2.0 * std::sin(15.0), 1e-12);  // d/dx15 at k = 0
  EXPECT_NEAR(out.jacobian[0][1], 2.0 + 2.0 * 0.3 * std::sin(0.0), 1e-12);   // d/dx0
  EXPECT_EQ(q.AllAt(std::vector<double>{2.0, 0.3, 1.0})[15], 2.0);
}

}  // namespace
}  // namespace hotlap::ident
