#include "hotlap/tyre/rubber.h"

#include <cmath>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap::tyre {
namespace {

RubberParams<double> Rubber() {
  RubberParams<double> r;
  r.modulus_amplitude = 8.0e5;        // Pa
  r.modulus_decay = 0.02;             // 1/K
  r.modulus_reference_temp = 293.15;  // K
  r.modulus_limit = 4.0e5;            // Pa
  r.geometry_factor = 6.0;
  return r;
}

TEST(RubberTest, ShearModulusFollowsEquation1) {
  const RubberParams<double> r = Rubber();
  // At T_A the exponential is 1; one decay length later it is 1/e; far above, G -> G_lim.
  EXPECT_DOUBLE_EQ(CalcShearModulus(r, 293.15), 1.2e6);
  EXPECT_NEAR(CalcShearModulus(r, 293.15 + 50.0), 8.0e5 / std::exp(1.0) + 4.0e5, 1e-6);
  EXPECT_NEAR(CalcShearModulus(r, 293.15 + 2000.0), 4.0e5, 1e-6);
  // Colder is stiffer.
  EXPECT_GT(CalcShearModulus(r, 273.15), CalcShearModulus(r, 293.15));
}

TEST(RubberTest, BristleStiffnessIsGeometryTimesModulus) {
  const RubberParams<double> r = Rubber();
  EXPECT_DOUBLE_EQ(CalcBristleStiffness(r, 293.15), 7.2e6);
  EXPECT_DOUBLE_EQ(CalcBristleStiffness(r, 310.0), 6.0 * CalcShearModulus(r, 310.0));
}

TEST(RubberTest, TemperatureFactorIsExponentialAboutReference) {
  const TemperatureFactor<double> f{2000.0, 0.0137, 293.15};
  EXPECT_DOUBLE_EQ(CalcTemperatureFactor(f, 293.15), 2000.0);
  EXPECT_NEAR(CalcTemperatureFactor(f, 313.15), 2000.0 * std::exp(-0.274), 1e-9);
  EXPECT_NEAR(CalcTemperatureFactor(f, 273.15), 2000.0 * std::exp(0.274), 1e-9);
  // The printed k1 exp(k2 - k3 T / T0) (001:12) is this family: a = k1 exp(k2 - k3 Tref/T0),
  // b = k3 / T0.
  const double k1 = 1.3, k2 = 0.4, k3 = 2.5, t0 = 291.15;
  const TemperatureFactor<double> g{k1 * std::exp(k2 - k3 * 293.15 / t0), k3 / t0, 293.15};
  for (double t : {273.15, 300.0, 326.15}) {
    EXPECT_NEAR(CalcTemperatureFactor(g, t), k1 * std::exp(k2 - k3 * t / t0), 1e-12);
  }
}

template <class T>
class RubberScalarTest : public ::testing::Test {};
TYPED_TEST_SUITE(RubberScalarTest, test::AllScalarTypes);

// Instantiates for every scalar; for Jets, dG/dT and dG/dK_B match central differences.
TYPED_TEST(RubberScalarTest, DerivativesMatchCentralDifferences) {
  using T = TypeParam;
  const RubberParams<double> r = Rubber();
  const double temp = 305.0;
  RubberParams<T> rt;
  CastFields(r, rt);
  T t(temp);
  if constexpr (IsJet<T>::value) {
    t.v[0] = 1.0;
    rt.modulus_decay.v[T::DIMENSION - 1] = 1.0;
  }
  const T g = CalcShearModulus(rt, t);
  const T k = CalcBristleStiffness(rt, t);
  EXPECT_DOUBLE_EQ(ValueOf(g), CalcShearModulus(r, temp));
  EXPECT_DOUBLE_EQ(ValueOf(k), CalcBristleStiffness(r, temp));
  if constexpr (IsJet<T>::value) {
    const double fd_t = test::CentralDifference(
        temp, [](double& x) -> double& { return x; },
        [&](const double& x) { return CalcShearModulus(r, x); });
    const double fd_b = test::CentralDifference(
        r, [](RubberParams<double>& p) -> double& { return p.modulus_decay; },
        [&](const RubberParams<double>& p) { return CalcShearModulus(p, temp); });
    test::ExpectNearDerivative(g.v[0], fd_t, 1e6, "dG/dT");
    test::ExpectNearDerivative(g.v[T::DIMENSION - 1], fd_b, 1e6, "dG/dK_B");
  }
}

}  // namespace
}  // namespace hotlap::tyre
