// Brake hydraulics: the lag toward the target, the rate and pressure limits, the torque gain, the
// delay line, every scalar type, and the derivative against central differences.

#include "hotlap/brake/brake_hydraulics.h"

#include <gtest/gtest.h>

#include "hotlap/common/rk4.h"
#include "test_util.h"

namespace {

using hotlap::brake::BrakeHydraulicsParams;
using hotlap::brake::CalcBrakeTorqueCapacity;
using hotlap::brake::CalcPressureRate;
using hotlap::brake::PressureDelayLine;

constexpr double kPaPerMPa = 1e6;

BrakeHydraulicsParams<double> Params() {
  return {.delay = 0.01,
          .time_constant = 0.01,
          .max_rise_rate = 80 * kPaPerMPa,
          .max_fall_rate = 150 * kPaPerMPa,
          .max_pressure = 13 * kPaPerMPa,
          .torque_gain = 150e-6};
}

TEST(BrakeHydraulicsTest, LagsTowardTheTargetWithinTheRateLimits) {
  const auto p = Params();
  // Small error: first order, (target - p) / tau.
  EXPECT_DOUBLE_EQ(CalcPressureRate(p, 5 * kPaPerMPa, 5.1 * kPaPerMPa), 0.1 * kPaPerMPa / 0.01);
  EXPECT_DOUBLE_EQ(CalcPressureRate(p, 5 * kPaPerMPa, 4.5 * kPaPerMPa), -0.5 * kPaPerMPa / 0.01);
  // Large errors: the rise and fall limits.
  EXPECT_DOUBLE_EQ(CalcPressureRate(p, 0.0, 10 * kPaPerMPa), 80 * kPaPerMPa);
  EXPECT_DOUBLE_EQ(CalcPressureRate(p, 10 * kPaPerMPa, 0.0), -150 * kPaPerMPa);
  // At the target: at rest.
  EXPECT_DOUBLE_EQ(CalcPressureRate(p, 7 * kPaPerMPa, 7 * kPaPerMPa), 0.0);
}

TEST(BrakeHydraulicsTest, TargetsAreClampedToWhatTheSystemDelivers) {
  const auto p = Params();
  EXPECT_DOUBLE_EQ(CalcPressureRate(p, 13 * kPaPerMPa, 20 * kPaPerMPa), 0.0);  // at p_max already
  EXPECT_DOUBLE_EQ(CalcPressureRate(p, 0.0, -3 * kPaPerMPa), 0.0);             // nothing below zero
}

TEST(BrakeHydraulicsTest, StepResponseRisesAtTheLimitThenSettlesExponentially) {
  const auto p = Params();
  // From 0 to a 4 MPa target: 80 MPa/s until the lag's rate falls below the limit at
  // 4 - 0.8 = 3.2 MPa (t = 0.04 s), then (4 - p) = 0.8 exp(-(t - 0.04) / tau).
  double x = 0.0;
  const double h = 1e-5;
  for (int i = 0; i < 6000; ++i) {
    x = hotlap::Rk4Step([&](double, double s) { return CalcPressureRate(p, s, 4 * kPaPerMPa); },
                        i * h, x, h);
    const double t = (i + 1) * h;
    if (i + 1 == 2000) {
      EXPECT_NEAR(x, 1.6 * kPaPerMPa, 1e-3 * kPaPerMPa);
    }
    if (i + 1 == 6000) {
      EXPECT_NEAR(x, 4 * kPaPerMPa - 0.8 * kPaPerMPa * std::exp(-(t - 0.04) / 0.01),
                  1e-3 * kPaPerMPa);
    }
  }
}

TEST(BrakeHydraulicsTest, TorqueIsTheGainTimesThePressure) {
  const auto p = Params();
  EXPECT_DOUBLE_EQ(CalcBrakeTorqueCapacity(p, 10 * kPaPerMPa), 1500.0);
  EXPECT_DOUBLE_EQ(CalcBrakeTorqueCapacity(p, -1.0), 0.0);
}

TEST(PressureDelayLineTest, ReturnsWhatWasPushedThatManyTicksAgo) {
  PressureDelayLine line(3, -1.0);
  EXPECT_EQ(line.delay_ticks(), 3);
  EXPECT_EQ(line.Push(1.0), -1.0);
  EXPECT_EQ(line.Push(2.0), -1.0);
  EXPECT_EQ(line.Push(3.0), -1.0);
  EXPECT_EQ(line.Push(4.0), 1.0);
  EXPECT_EQ(line.Push(5.0), 2.0);
  PressureDelayLine none(0, 0.0);
  EXPECT_EQ(none.Push(7.0), 7.0);
}

template <class T>
class BrakeHydraulicsScalarTest : public ::testing::Test {};
TYPED_TEST_SUITE(BrakeHydraulicsScalarTest, hotlap::test::AllScalarTypes);

TYPED_TEST(BrakeHydraulicsScalarTest, InstantiatesAndAgreesWithDouble) {
  using T = TypeParam;
  const auto pd = Params();
  const BrakeHydraulicsParams<T> p = pd.template Cast<T>();
  for (double pressure : {0.0, 3 * kPaPerMPa, 9 * kPaPerMPa}) {
    for (double target : {0.0, 3.05 * kPaPerMPa, 12 * kPaPerMPa}) {
      EXPECT_DOUBLE_EQ(hotlap::ValueOf(CalcPressureRate(p, T(pressure), T(target))),
                       CalcPressureRate(pd, pressure, target));
    }
  }
  EXPECT_DOUBLE_EQ(hotlap::ValueOf(CalcBrakeTorqueCapacity(p, T(5 * kPaPerMPa))), 750.0);
}

TEST(BrakeHydraulicsTest, DerivativesMatchCentralDifferences) {
  using J = hotlap::Jet2;
  const auto pd = Params();
  // In the linear part (small error) and on the rate limit.
  for (const auto& [pressure_case, target_case] :
       {std::pair{5 * kPaPerMPa, 5.2 * kPaPerMPa}, std::pair{5 * kPaPerMPa, 9 * kPaPerMPa}}) {
    // Copies: Clang 14 cannot capture structured bindings in the lambdas below.
    const double pressure = pressure_case, target = target_case;
    BrakeHydraulicsParams<J> p = pd.Cast<J>();
    p.time_constant.v[1] = 1.0;  // d/d(tau)
    const J rate = CalcPressureRate(p, J(pressure, 0), J(target));
    const double fd_p = hotlap::test::CentralDifference(
        pressure, [](double& x) -> double& { return x; },
        [&](const double& x) { return CalcPressureRate(pd, x, target); });
    const double fd_tau = hotlap::test::CentralDifference(
        pd, [](BrakeHydraulicsParams<double>& q) -> double& { return q.time_constant; },
        [&](const BrakeHydraulicsParams<double>& q) {
          return CalcPressureRate(q, pressure, target);
        });
    hotlap::test::ExpectNearDerivative(rate.v[0], fd_p, 100.0, "d rate / d p");
    hotlap::test::ExpectNearDerivative(rate.v[1], fd_tau, 1e8, "d rate / d tau");
  }
}

}  // namespace
