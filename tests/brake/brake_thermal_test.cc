#include "hotlap/brake/brake_thermal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "brake/paper_brake_params.h"
#include "hotlap/common/rk4.h"
#include "hotlap/common/scalar.h"
#include "test_util.h"

namespace hotlap::brake {
namespace {

constexpr double kSigma = 5.670374e-8;  // spec section 0

// z' P z with z = [1, u/100, (T - 273.15)/1000], written out term by term.
double Quadratic(const std::array<std::array<double, 3>, 3>& m, double u, double temp) {
  const double z[3] = {1.0, u / 100.0, (temp - 273.15) / 1000.0};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) sum += z[i] * m[i][j] * z[j];
  }
  return sum;
}
constexpr std::array<std::array<double, 3>, 3> kDiscCubic = {{{6, 3, 2}, {3, 12, 2}, {2, 2, 10}}};
constexpr std::array<std::array<double, 3>, 3> kCalliperCubic = {
    {{1, .5, .2}, {.5, 4, .2}, {.2, .2, 2}}};

// The worked point: u = 70 m/s, Fx = -3000 N (braking), T_d = 600 K, T_k = 400 K, T_0 = 298.15 K.
BrakeInput<double> WorkedInput() { return {70.0, -3000.0, 298.15}; }
BrakeState<double> WorkedState() { return {600.0, 400.0}; }

// Every flow and both temperature rates against a hand computation of spec section 5, using P
// itself (not its factor). Relative 1e-12: only rounding separates the two orders of arithmetic.
TEST(BrakeThermalTest, HeatFlowsMatchHandComputation) {
  const BrakeThermalParams<double> p = test::PaperFrontBrakeParams();
  const double t0_4 = 298.15 * 298.15 * 298.15 * 298.15;
  const double q1 = 70.0 * 3000.0;                                    // 210 kW
  const double q2 = 2.0 * 0.5 * (9472e-6) / 0.025 * (600.0 - 400.0);  // 75.776 W
  const double q3 = 0.48 * kSigma * 0.6302 * (600.0 * 600.0 * 600.0 * 600.0 - t0_4);
  const double ha_d = Quadratic(kDiscCubic, 70.0, 600.0);  // 19.3709 W/K
  const double q4 = ha_d * (600.0 - 298.15);
  const double q5 = 0.25 * kSigma * 12.81e-4 * (400.0 * 400.0 * 400.0 * 400.0 - t0_4);
  const double ha_k = Quadratic(kCalliperCubic, 70.0, 400.0);  // 3.77844 W/K
  const double q6 = ha_k * (400.0 - 298.15);
  const double dtd = (0.95 * q1 - q2 - q3 - q4) / (0.1 * 8.8 * 480.0);
  const double dtk = (0.05 * q1 + q2 - q5 - q6) / (5.0312 * 921.1);
  // Pinned values from the same formulas evaluated once in Python.
  EXPECT_NEAR(ha_d, 19.370889225, 1e-9);
  EXPECT_NEAR(ha_k, 3.778439845, 1e-9);
  EXPECT_NEAR(dtd, 453.3373059460338, 1e-9);

  const auto rel = [](double v) { return 1e-12 * std::abs(v); };
  EXPECT_NEAR(p.disc_convection.Conductance(70.0, 600.0), ha_d, rel(ha_d));
  EXPECT_NEAR(p.calliper_convection.Conductance(70.0, 400.0), ha_k, rel(ha_k));
  EXPECT_NEAR(CalcBrakePower(70.0, -3000.0), q1, rel(q1));
  BrakeHeatFlows<double> q;
  const BrakeState<double> dx = CalcBrakeDerivatives(p, WorkedState(), WorkedInput(), &q);
  EXPECT_NEAR(q.q1, q1, rel(q1));
  EXPECT_NEAR(q.q2, q2, rel(q2));
  EXPECT_NEAR(q.q3, q3, rel(q3));
  EXPECT_NEAR(q.q4, q4, rel(q4));
  EXPECT_NEAR(q.q5, q5, rel(q5));
  EXPECT_NEAR(q.q6, q6, rel(q6));
  EXPECT_NEAR(dx.disc_temp, dtd, 1e-12 * q1 / 422.4);
  EXPECT_NEAR(dx.calliper_temp, dtk, 1e-12 * q1 / 4634.0);
  const BrakeHeatFlows<double> direct = CalcBrakeHeatFlows(p, WorkedState(), WorkedInput());
  EXPECT_EQ(direct.q4, q.q4);
}

// A logged braking power back to the force the brake model takes: its power at the same speed
// is the logged one; where the speed says nothing, the tyre's own braking force.
TEST(BrakeThermalTest, BrakeForceFromALoggedPower) {
  EXPECT_DOUBLE_EQ(BrakeFxFromPower(50.0, 60000.0, -500.0), -1200.0);  // 60 kW at 50 m/s
  EXPECT_DOUBLE_EQ(CalcBrakePower(50.0, BrakeFxFromPower(50.0, 60000.0, -500.0)), 60000.0);
  EXPECT_DOUBLE_EQ(BrakeFxFromPower(-50.0, 60000.0, -500.0), -1200.0);  // |u|, as the power
  EXPECT_EQ(BrakeFxFromPower(50.0, 0.0, 3000.0), 0.0);      // no braking, whatever the tyre
  EXPECT_EQ(BrakeFxFromPower(0.05, 10.0, -700.0), -700.0);  // near standstill: the tyre's
  EXPECT_EQ(BrakeFxFromPower(0.05, 10.0, 700.0), 0.0);
}

TEST(BrakeThermalTest, BrakePowerIsExactMaxOfMinusFx) {
  EXPECT_EQ(CalcBrakePower(70.0, 2000.0), 0.0);  // driving: no braking power
  EXPECT_EQ(CalcBrakePower(70.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(CalcBrakePower(-70.0, -100.0), 7000.0);  // |u| is used
  // The Jet derivative is that of the active branch.
  const Jet2 power = CalcBrakePower(Jet2(70.0, 0), Jet2(-100.0, 1));
  EXPECT_DOUBLE_EQ(power.v[0], 100.0);
  EXPECT_DOUBLE_EQ(power.v[1], -70.0);
  const Jet2 none = CalcBrakePower(Jet2(70.0, 0), Jet2(100.0, 1));
  EXPECT_EQ(none.v[0], 0.0);
  EXPECT_EQ(none.v[1], 0.0);
}

// The conductance is a sum of squares: never negative, even where z is far from the fit.
TEST(BrakeThermalTest, ConductanceIsNeverNegative) {
  ConvectionPolynomial<double> l{1.0, -3.0, 0.5, 2.0, -1.0, 0.1};
  for (double u = -100; u <= 300; u += 7) {
    for (double t = 100; t <= 1500; t += 37) EXPECT_GE(l.Conductance(u, t), 0.0);
  }
}

struct Augmented {
  BrakeState<double> x;
  double energy_in = 0.0;  // integral of q1 - q3 - q4 - q5 - q6, J
  friend Augmented operator+(const Augmented& a, const Augmented& b) {
    return {a.x + b.x, a.energy_in + b.energy_in};
  }
  friend Augmented operator*(double k, const Augmented& a) { return {k * a.x, k * a.energy_in}; }
};

// xi m_d c_d dT_d + m_k c_k dT_k = integral of (q1 - q3 - q4 - q5 - q6): gamma splits q1 and q2
// moves heat between the masses. Holds to rounding under RK4; the bound asked is 1e-6 relative.
TEST(BrakeThermalTest, EnergyBalanceCloses) {
  const BrakeThermalParams<double> p = test::PaperFrontBrakeParams();
  const auto input = [](double t) {
    // Braking pulses (Fx < 0 half the time) at varying speed and cooling-air temperature.
    return BrakeInput<double>{60.0 + 20.0 * std::sin(0.4 * t), 4000.0 * std::sin(1.1 * t),
                              298.15 + 5.0 * std::sin(0.2 * t)};
  };
  const auto rhs = [&](double t, const Augmented& s) {
    BrakeHeatFlows<double> q;
    Augmented d;
    d.x = CalcBrakeDerivatives(p, s.x, input(t), &q);
    d.energy_in = q.q1 - q.q3 - q.q4 - q.q5 - q.q6;
    return d;
  };
  Augmented s{{500.0, 350.0}, 0.0};
  const Augmented start = s;
  const double h = 0.005;
  for (int i = 0; i < 1000; ++i) s = Rk4Step(rhs, i * h, s, h);
  const double stored =
      p.mass_participation * p.disc_mass * p.disc_heat_capacity *
          (s.x.disc_temp - start.x.disc_temp) +
      p.calliper_mass * p.calliper_heat_capacity * (s.x.calliper_temp - start.x.calliper_temp);
  EXPECT_GT(std::abs(s.x.disc_temp - start.x.disc_temp), 10.0);  // something happened
  EXPECT_NEAR(stored, s.energy_in, 1e-6 * std::abs(s.energy_in));
}

// No braking power: both masses relax toward the cooling air, never crossing it or turning back.
// Disc and calliper start equal, so the fast disc settles onto the slow calliper from the same
// side. Steps of 1 s are well inside RK4's stable, non-oscillating range (disc rate < 0.2 /s).
void ExpectBrakeRelaxesMonotonically(double start_temp, double speed, double fx) {
  const BrakeThermalParams<double> p = test::PaperFrontBrakeParams();
  const double air = 298.15;
  const BrakeInput<double> in{speed, fx, air};
  const auto rhs = [&](double, const BrakeState<double>& x) {
    return CalcBrakeDerivatives(p, x, in);
  };
  BrakeState<double> x{start_temp, start_temp};
  const double gap0 = start_temp - air;
  for (int i = 0; i < 30000; ++i) {
    const BrakeState<double> next = Rk4Step(rhs, i * 1.0, x, 1.0);
    for (auto [before, after] :
         {std::pair{x.disc_temp, next.disc_temp}, std::pair{x.calliper_temp, next.calliper_temp}}) {
      ASSERT_GE((after - air) * gap0, 0.0) << "crossed the air temperature at step " << i;
      ASSERT_LE(std::abs(after - air), std::abs(before - air)) << "step " << i;
    }
    x = next;
  }
  // Calliper time constant ~ 4634 J/K over ~1.4 W/K ~ 1 h; 30000 s is several of them.
  EXPECT_LT(std::abs(x.calliper_temp - air), 0.02 * std::abs(gap0));
  EXPECT_LT(std::abs(x.disc_temp - air), 0.02 * std::abs(gap0));
}

TEST(BrakeThermalTest, RelaxesAtRestFromAbove) { ExpectBrakeRelaxesMonotonically(700.0, 0, 0); }
TEST(BrakeThermalTest, RelaxesAtRestFromBelow) { ExpectBrakeRelaxesMonotonically(250.0, 0, 0); }
TEST(BrakeThermalTest, RelaxesWhileDrivingFromAbove) {
  ExpectBrakeRelaxesMonotonically(700.0, 60.0, 2000.0);
}
TEST(BrakeThermalTest, RelaxesWhileCoastingFromBelow) {
  ExpectBrakeRelaxesMonotonically(250.0, 60.0, 0.0);
}

using test::CentralDifference;
using test::ExpectNearDerivative;

// Both temperature rates {dT_d/dt, dT_k/dt} at the worked input.
std::array<double, 2> Rates(const BrakeThermalParams<double>& p, const BrakeState<double>& x) {
  const BrakeState<double> d = CalcBrakeDerivatives(p, x, WorkedInput());
  return {d.disc_temp, d.calliper_temp};
}

std::array<double*, 14> FittedFields(BrakeThermalParams<double>& p) {
  ConvectionPolynomial<double>& d = p.disc_convection;
  ConvectionPolynomial<double>& k = p.calliper_convection;
  return {&p.heat_partition,
          &p.mass_participation,
          &d.l11,
          &d.l21,
          &d.l22,
          &d.l31,
          &d.l32,
          &d.l33,
          &k.l11,
          &k.l21,
          &k.l22,
          &k.l31,
          &k.l32,
          &k.l33};
}

TEST(BrakeThermalTest, ParameterDerivativesMatchFiniteDifferences) {
  const BrakeThermalParams<double> p = test::PaperFrontBrakeParams();
  BrakeThermalParams<Jet14> pj = p.Cast<Jet14>();
  pj.heat_partition.v[0] = 1.0;
  pj.mass_participation.v[1] = 1.0;
  std::array<Jet14*, 12> l = {
      &pj.disc_convection.l11,     &pj.disc_convection.l21,     &pj.disc_convection.l22,
      &pj.disc_convection.l31,     &pj.disc_convection.l32,     &pj.disc_convection.l33,
      &pj.calliper_convection.l11, &pj.calliper_convection.l21, &pj.calliper_convection.l22,
      &pj.calliper_convection.l31, &pj.calliper_convection.l32, &pj.calliper_convection.l33};
  for (int i = 0; i < 12; ++i) l[i]->v[2 + i] = 1.0;
  const BrakeState<Jet14> xj{Jet14(600.0), Jet14(400.0)};
  const BrakeInput<Jet14> inj{Jet14(70.0), Jet14(-3000.0), Jet14(298.15)};
  const BrakeState<Jet14> d = CalcBrakeDerivatives(pj, xj, inj);
  for (int i = 0; i < 14; ++i) {
    const std::array<double, 2> fd = CentralDifference(
        p, [i](BrakeThermalParams<double>& q) -> double& { return *FittedFields(q)[i]; },
        [](const BrakeThermalParams<double>& q) { return Rates(q, WorkedState()); });
    ExpectNearDerivative(d.disc_temp.v[i], fd[0], 500.0, "dT_d/dt, parameter " + std::to_string(i));
    ExpectNearDerivative(d.calliper_temp.v[i], fd[1], 5.0,
                         "dT_k/dt, parameter " + std::to_string(i));
  }
  // The disc ignores the calliper's polynomial and vice versa; gamma moves both.
  EXPECT_EQ(d.disc_temp.v[8], 0.0);
  EXPECT_EQ(d.calliper_temp.v[2], 0.0);
  EXPECT_GT(d.disc_temp.v[0], 0.0);
  EXPECT_LT(d.calliper_temp.v[0], 0.0);
}

TEST(BrakeThermalTest, StateDerivativesMatchFiniteDifferences) {
  const BrakeThermalParams<double> p = test::PaperFrontBrakeParams();
  const BrakeState<Jet2> xj{Jet2(600.0, 0), Jet2(400.0, 1)};
  const BrakeInput<Jet2> inj{Jet2(70.0), Jet2(-3000.0), Jet2(298.15)};
  const BrakeState<Jet2> d = CalcBrakeDerivatives(p.Cast<Jet2>(), xj, inj);
  for (int i = 0; i < 2; ++i) {
    const std::array<double, 2> fd = CentralDifference(
        WorkedState(),
        [i](BrakeState<double>& x) -> double& { return i == 0 ? x.disc_temp : x.calliper_temp; },
        [&](const BrakeState<double>& x) { return Rates(p, x); });
    ExpectNearDerivative(d.disc_temp.v[i], fd[0], 1.0, "dT_d/dt, state " + std::to_string(i));
    ExpectNearDerivative(d.calliper_temp.v[i], fd[1], 0.01, "dT_k/dt, state " + std::to_string(i));
  }
  EXPECT_LT(d.disc_temp.v[0], 0.0);
  EXPECT_GT(d.calliper_temp.v[0], 0.0);  // a hotter disc feeds the calliper through the pads
}

template <class T>
class BrakeScalarTest : public ::testing::Test {};
using ScalarTypes = test::AllScalarTypes;
TYPED_TEST_SUITE(BrakeScalarTest, ScalarTypes);

// Every function instantiates for every scalar, gives the double value, and (for Jets) carries a
// derivative seeded on the disc temperature that matches a central difference.
TYPED_TEST(BrakeScalarTest, EveryFunctionInstantiatesAndAgreesWithDouble) {
  using T = TypeParam;
  const BrakeThermalParams<double> p = test::PaperFrontBrakeParams();
  const BrakeThermalParams<T> pt = p.template Cast<T>();
  T disc(600.0);
  if constexpr (IsJet<T>::value) disc.v[0] = 1.0;
  const BrakeState<T> xt{disc, T(400.0)};
  const BrakeInput<T> it{T(70.0), T(-3000.0), T(298.15)};
  const auto same = [](const T& got, double want) {
    EXPECT_NEAR(ValueOf(got), want, 1e-13 * std::abs(want));
  };
  same(pt.disc_convection.Conductance(T(70.0), xt.disc_temp),
       p.disc_convection.Conductance(70.0, 600.0));
  same(CalcBrakePower(it.speed, it.fx), 210000.0);
  const BrakeHeatFlows<T> qt = CalcBrakeHeatFlows(pt, xt, it);
  const BrakeHeatFlows<double> q = CalcBrakeHeatFlows(p, WorkedState(), WorkedInput());
  same(qt.q2, q.q2);
  same(qt.q3, q.q3);
  same(qt.q6, q.q6);
  const BrakeState<T> dt = CalcBrakeDerivatives(pt, xt, it);
  const BrakeState<double> d = CalcBrakeDerivatives(p, WorkedState(), WorkedInput());
  same(dt.disc_temp, d.disc_temp);
  same(dt.calliper_temp, d.calliper_temp);
  if constexpr (IsJet<T>::value) {
    const double fd = CentralDifference(
        WorkedState(), [](BrakeState<double>& x) -> double& { return x.disc_temp; },
        [&](const BrakeState<double>& x) { return Rates(p, x)[0]; });
    ExpectNearDerivative(dt.disc_temp.v[0], fd, 1.0, "d(dT_d/dt)/dT_d");
  }
}

}  // namespace
}  // namespace hotlap::brake
