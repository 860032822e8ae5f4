#include "hotlap/tyre/tyre_thermal.h"

#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/rk4.h"
#include "hotlap/common/scalar.h"
#include "hotlap/tyre/compound.h"
#include "hotlap/tyre/temperature_cubic.h"
#include "test_util.h"
#include "tyre/paper_tyre_params.h"

namespace hotlap::tyre {
namespace {

constexpr double kPiHere = 3.14159265358979323846;
constexpr double kSigma = 5.670374e-8;  // spec section 0

TemperatureCubicSpec Spec(CubicKind kind, double opt_c, double low_c, double low_v, double high_c,
                          double high_v) {
  return {kind, opt_c + 273.15, low_c + 273.15, low_v, high_c + 273.15, high_v, 273.15, 473.15};
}

// Spec sections 1, 3 and 4 defaults.
TyreCompound DefaultCompound() {
  return TyreCompound{
      "test", TemperatureCubic::Create(Spec(CubicKind::kGripMaximum, 98, 60, 0.9, 140, 0.9), "g"),
      TemperatureCubic::Create(Spec(CubicKind::kWearMinimum, 95, 60, 1.5, 140, 1.5), "w"),
      GripWearTable{{0, 1, 3, 6}, {1.0, 0.98, 0.90, 0.75}}, 1000.0};
}

// The worked point of the tests: u = 70 m/s, Fx = 1500 N, Fy = 6000 N, Fz = 7000 N,
// alpha = -3 deg, kappa = 0.02, T_t = 380 K, T_c = 350 K, T_amb = 298.15 K, T_tra = 313.15 K.
TyreInput<double> WorkedInput() {
  return {70.0, 1500.0, 6000.0, 7000.0, -3.0 * kPiHere / 180.0, 0.02, 298.15, 313.15};
}
TyreState<double> WorkedState() { return {380.0, 350.0, 0.0}; }

// Every flow, the contact length, h_forc, the wear rate and both temperature rates against a hand
// computation of spec sections 1-3. The hand arithmetic is ordinary double arithmetic in a
// different order from the library's, so the two agree to a few ulps: 1e-12 relative.
TEST(TyreThermalTest, HeatFlowsMatchHandComputation) {
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  const TyreCompound compound = DefaultCompound();
  const TyreInput<double> in = WorkedInput();
  const TyreState<double> x = WorkedState();

  // Geometry.
  const double a_tot = kPiHere * 0.4572 * 0.2921;             // 0.419553... m^2
  const double c_l = 0.0001508 * std::pow(7000.0, 0.795321);  // 0.172380... m
  const double a_conv = a_tot - 0.2286 * c_l;                 // 0.380147... m^2
  const double c_s = (3.0 / 8.0) * (0.8 - 0.3) + 0.3;         // 0.4875
  const double a_cp = 0.2286 * c_s * c_l;                     // 0.0192105... m^2
  const double length = 1.0 / (1.0 / 0.4572 + 1.0 / 0.2921);  // 0.178230... m
  // Air at the film temperature (380 + 298.15)/2 = 339.075 K = 65.925 degC, between the 60 and
  // 70 degC rows of the table, fraction 0.5925 of the way.
  const double film_c = (380.0 + 298.15) / 2.0 - 273.15;
  const double frac = (film_c - 60.0) / 10.0;
  const double k_air = 0.02808 + frac * (0.02881 - 0.02808);      // 0.0285125 W/(m K)
  const double nu_air = (1.896 + frac * (1.995 - 1.896)) * 1e-5;  // 1.95466e-5 m^2/s
  const double h_forc = k_air / length * 0.0239 * std::pow(70.0 * length / nu_air, 0.805);
  // Flows.
  const double q1 = 0.328 * 70.0 * (1500.0 * 0.02 + 6000.0 * std::tan(3.0 * kPiHere / 180.0));
  const double q2 =
      70.0 * 11.0 / (kPiHere * 0.4572) * (0.0042 * 1500 + 1.641e-05 * 6000 + 1.797e-05 * 7000);
  const double q3 = h_forc * a_conv * (380.0 - 298.15);
  const double q4 = 1200.0 * a_cp * (380.0 - 313.15);
  const double q5 = 427.5 * a_tot * (350.0 - 380.0);
  const double amb4 = 298.15 * 298.15 * 298.15 * 298.15;
  const double q6 = 0.93 * kSigma * (a_tot - a_cp) * (std::pow(380.0, 4) - amb4);
  const double q7 =
      0.93 * kSigma * 2 * kPiHere * (0.3613 * 0.3613 - 0.229 * 0.229) * (std::pow(350.0, 4) - amb4);
  // Wear cubic w = a x^3 + b x^2 + 1 in x = T - 368.15 K through (-35, 1.5) and (45, 1.5).
  const double xl = -35.0, xh = 45.0;
  const double det = xl * xl * xl * xh * xh - xh * xh * xh * xl * xl;
  const double wa = (0.5 * xh * xh - 0.5 * xl * xl) / det;
  const double wb = (xl * xl * xl * 0.5 - xh * xh * xh * 0.5) / det;
  const double xw = 380.0 - 368.15;
  const double w = wa * xw * xw * xw + wb * xw * xw + 1.0;
  const double wear_rate = 5.506e-06 * w * std::pow(q1 / 1000.0, 1.785);
  const double dtt = (q1 - q3 - q4 + q5 - q6) / (0.9 * 900.0);
  const double dtc = (q2 - q5 - q7) / (11.0 * 1600.0);

  // Pinned values (the same formulas evaluated once in Python) guard the hand arithmetic itself.
  EXPECT_NEAR(q1, 7908.4956740317575, 1e-8);
  EXPECT_NEAR(q3, 5603.443772645211, 1e-8);
  EXPECT_NEAR(dtt, -6.03725810075171, 1e-11);

  const auto rel = [](double expected) { return 1e-12 * std::abs(expected); };
  EXPECT_NEAR(CalcContactLength(p, in.fz), c_l, rel(c_l));
  EXPECT_NEAR(CalcForcedConvectionCoefficient(p, in.speed, x.tread_temp, in.ambient_temp), h_forc,
              rel(h_forc));
  TyreHeatFlows<double> q;
  const TyreState<double> dx = CalcTyreDerivatives(p, compound, x, in, &q);
  EXPECT_NEAR(q.q1, q1, rel(q1));
  EXPECT_NEAR(q.q2, q2, rel(q2));
  EXPECT_NEAR(q.q3, q3, rel(q3));
  EXPECT_NEAR(q.q4, q4, rel(q4));
  EXPECT_NEAR(q.q5, q5, rel(q5));
  EXPECT_NEAR(q.q6, q6, rel(q6));
  EXPECT_NEAR(q.q7, q7, rel(q7));
  const TyreHeatFlows<double> q_direct = CalcTyreHeatFlows(p, x, in);
  EXPECT_EQ(q_direct.q3, q.q3);
  EXPECT_NEAR(compound.wear_rate.Evaluate(380.0), w, 1e-12);
  EXPECT_NEAR(CalcWearRate(p, compound, x.tread_temp, q1), wear_rate, 1e-10 * wear_rate);
  EXPECT_NEAR(dx.wear, wear_rate, 1e-10 * wear_rate);
  // The rates are differences of kW-sized flows: 1e-12 of the largest flow over the capacity.
  EXPECT_NEAR(dx.tread_temp, dtt, 1e-12 * q1 / 810.0);
  EXPECT_NEAR(dx.carcass_temp, dtc, 1e-12 * q1 / 17600.0);
}

// Edge cases the model handles specially: no speed, no load, no sliding.
TEST(TyreThermalTest, ZeroSpeedLoadAndSlidingGiveZeroFlows) {
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  EXPECT_EQ(CalcContactLength(p, 0.0), 0.0);
  EXPECT_EQ(CalcForcedConvectionCoefficient(p, 0.0, 380.0, 298.15), 0.0);
  // |Fz| and |u| are used: the sign does not matter.
  EXPECT_DOUBLE_EQ(CalcContactLength(p, -7000.0), CalcContactLength(p, 7000.0));
  EXPECT_DOUBLE_EQ(CalcForcedConvectionCoefficient(p, -70.0, 380.0, 298.15),
                   CalcForcedConvectionCoefficient(p, 70.0, 380.0, 298.15));
  EXPECT_EQ(CalcWearRate(p, DefaultCompound(), 380.0, 0.0), 0.0);
  TyreInput<double> in = WorkedInput();
  in.speed = 0.0;
  const TyreHeatFlows<double> q = CalcTyreHeatFlows(p, WorkedState(), in);
  EXPECT_EQ(q.q1, 0.0);
  EXPECT_EQ(q.q2, 0.0);
  EXPECT_EQ(q.q3, 0.0);
  EXPECT_GT(q.q4, 0.0);  // still conducting to the cooler track
}

// Integrates the tyre with an energy accumulator riding along in the same RK4 stages.
struct Augmented {
  TyreState<double> x;
  double energy_in = 0.0;  // integral of q1 + q2 - q3 - q4 - q6 - q7, J
  friend Augmented operator+(const Augmented& a, const Augmented& b) {
    return {a.x + b.x, a.energy_in + b.energy_in};
  }
  friend Augmented operator*(double k, const Augmented& a) { return {k * a.x, k * a.energy_in}; }
};

TyreInput<double> VaryingInput(double t) {
  const double deg = kPiHere / 180.0;
  return {60.0 + 15.0 * std::sin(0.7 * t),
          1500.0 * std::cos(1.3 * t),
          6000.0 + 2000.0 * std::sin(0.5 * t),
          7000.0 + 1000.0 * std::sin(2.0 * t),
          -3.0 * deg * (1.0 + 0.3 * std::sin(t)),
          0.02 * std::cos(1.3 * t),
          298.15,
          313.15 + 2.0 * std::sin(0.1 * t)};
}

// m_t c_t dT_t + m_c c_c dT_c = integral of (q1 + q2 - q3 - q4 - q6 - q7): q5 only moves heat
// between the masses. RK4 is linear in the stage slopes, so the balance holds to rounding; the
// acceptance bound is 1e-6 relative.
TEST(TyreThermalTest, EnergyBalanceCloses) {
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  const TyreCompound compound = DefaultCompound();
  const auto rhs = [&](double t, const Augmented& s) {
    TyreHeatFlows<double> q;
    Augmented d;
    d.x = CalcTyreDerivatives(p, compound, s.x, VaryingInput(t), &q);
    d.energy_in = q.q1 + q.q2 - q.q3 - q.q4 - q.q6 - q.q7;
    return d;
  };
  Augmented s{{330.0, 340.0, 0.0}, 0.0};
  const Augmented start = s;
  const double h = 0.01;
  for (int i = 0; i < 500; ++i) s = Rk4Step(rhs, i * h, s, h);
  const double stored =
      p.tread_mass * p.tread_heat_capacity * (s.x.tread_temp - start.x.tread_temp) +
      p.carcass_mass * p.carcass_heat_capacity * (s.x.carcass_temp - start.x.carcass_temp);
  EXPECT_GT(std::abs(s.x.tread_temp - start.x.tread_temp), 1.0);  // something happened
  EXPECT_GT(std::abs(s.energy_in), 1e3);
  EXPECT_NEAR(stored, s.energy_in, 1e-6 * std::abs(s.energy_in));
  EXPECT_GT(s.x.wear, 0.0);
}

// No heating (u = 0, no forces, track at ambient): both masses relax toward ambient without ever
// crossing it or turning back. Starting from equal temperatures the fast tread settles onto the
// slow carcass from the same side, so each step must move each temperature toward ambient.
void ExpectTyreRelaxesMonotonically(double start_temp) {
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  const TyreCompound compound = DefaultCompound();
  const double ambient = 298.15;
  const TyreInput<double> in{0.0, 0.0, 0.0, 0.0, 0.0, 0.0, ambient, ambient};
  const auto rhs = [&](double, const TyreState<double>& x) {
    return CalcTyreDerivatives(p, compound, x, in);
  };
  TyreState<double> x{start_temp, start_temp, 0.0};
  const double gap0 = start_temp - ambient;
  for (int i = 0; i < 30000; ++i) {
    const TyreState<double> next = Rk4Step(rhs, i * 1.0, x, 1.0);
    for (auto [before, after] :
         {std::pair{x.tread_temp, next.tread_temp}, std::pair{x.carcass_temp, next.carcass_temp}}) {
      ASSERT_GE((after - ambient) * gap0, 0.0) << "crossed ambient at step " << i;
      ASSERT_LE(std::abs(after - ambient), std::abs(before - ambient)) << "step " << i;
    }
    EXPECT_EQ(next.wear, 0.0);
    x = next;
  }
  // Carcass time constant ~ 18400 J/K over ~5 W/K ~ 1 h; 30000 s is several of them.
  EXPECT_LT(std::abs(x.carcass_temp - ambient), 0.02 * std::abs(gap0));
  EXPECT_LT(std::abs(x.tread_temp - ambient), 0.02 * std::abs(gap0));
}

TEST(TyreThermalTest, RelaxesTowardAmbientFromAbove) { ExpectTyreRelaxesMonotonically(380.0); }
TEST(TyreThermalTest, RelaxesTowardAmbientFromBelow) { ExpectTyreRelaxesMonotonically(260.0); }

// Central differences with a relative step of 1e-6, checked with a relative tolerance of 1e-5
// and an absolute floor of 1e-9 of the quantity's scale (error budget in test_util.h).
using test::CentralDifference;
using test::ExpectNearDerivative;

using Outputs = std::array<double, 3>;  // dT_t/dt, dT_c/dt, wear rate
Outputs Evaluate(const TyreThermalParams<double>& p, const TyreState<double>& x) {
  const TyreState<double> d = CalcTyreDerivatives(p, DefaultCompound(), x, WorkedInput());
  return {d.tread_temp, d.carcass_temp, d.wear};
}
constexpr std::array<double, 3> kOutputScale = {10.0, 1.0, 1e-3};

TEST(TyreThermalTest, ParameterDerivativesMatchFiniteDifferences) {
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  TyreThermalParams<Jet7> pj = p.Cast<Jet7>();
  std::array<Jet7*, 7> seeds = {&pj.p1, &pj.p2,         &pj.p3,           &pj.p4,
                                &pj.p5, &pj.wear_coeff, &pj.wear_exponent};
  for (int i = 0; i < 7; ++i) seeds[i]->v[i] = 1.0;
  const TyreState<double> x = WorkedState();
  const TyreInput<double> in = WorkedInput();
  const TyreState<Jet7> xj{Jet7(x.tread_temp), Jet7(x.carcass_temp), Jet7(0.0)};
  const TyreInput<Jet7> inj{Jet7(in.speed),        Jet7(in.fx),         Jet7(in.fy),
                            Jet7(in.fz),           Jet7(in.slip_angle), Jet7(in.slip_ratio),
                            Jet7(in.ambient_temp), Jet7(in.track_temp)};
  const TyreState<Jet7> d = CalcTyreDerivatives(pj, DefaultCompound(), xj, inj);
  const std::array<const Jet7*, 3> ad = {&d.tread_temp, &d.carcass_temp, &d.wear};
  const std::array<double TyreThermalParams<double>::*, 7> fields = {
      &TyreThermalParams<double>::p1,           &TyreThermalParams<double>::p2,
      &TyreThermalParams<double>::p3,           &TyreThermalParams<double>::p4,
      &TyreThermalParams<double>::p5,           &TyreThermalParams<double>::wear_coeff,
      &TyreThermalParams<double>::wear_exponent};
  for (int i = 0; i < 7; ++i) {
    const Outputs fd = CentralDifference(
        p, [&](TyreThermalParams<double>& q) -> double& { return q.*fields[i]; },
        [&](const TyreThermalParams<double>& q) { return Evaluate(q, x); });
    for (int k = 0; k < 3; ++k) {
      ExpectNearDerivative(ad[k]->v[i], fd[k], kOutputScale[k] / std::abs(p.*fields[i]),
                           "output " + std::to_string(k) + " parameter " + std::to_string(i));
    }
  }
  // The wear law's derivatives are non-zero and the carcass ignores p1: the seeds took effect.
  EXPECT_NE(d.wear.v[5], 0.0);
  EXPECT_NE(d.wear.v[6], 0.0);
  EXPECT_EQ(d.carcass_temp.v[0], 0.0);
}

// Input terms seeded from a nearby input's (the integrator's fast path, a binomial series for the
// three powers) equal those computed from scratch, in value and in parameter derivatives, both
// within the series' 2% reach and beyond it (where the direct power is used).
TEST(TyreThermalTest, InputTermsFromNearbyInputMatchDirect) {
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  TyreThermalParams<Jet7> pj = p.Cast<Jet7>();
  pj.contact_length_exponent.v[0] = 1.0;
  pj.wear_exponent.v[1] = 1.0;
  const TyreCompound compound = DefaultCompound();
  const TyreConstants<Jet7> constants = CalcTyreConstants(pj);
  const auto to_jet = [](const TyreInput<double>& in) {
    return TyreInput<Jet7>{Jet7(in.speed),        Jet7(in.fx),         Jet7(in.fy),
                           Jet7(in.fz),           Jet7(in.slip_angle), Jet7(in.slip_ratio),
                           Jet7(in.ambient_temp), Jet7(in.track_temp)};
  };
  const TyreInput<double> base = WorkedInput();
  const TyreInputTerms<Jet7> near = CalcTyreInputTerms(pj, constants, compound, to_jet(base));
  for (double change : {0.0, 0.001, -0.015, 0.019, 0.05, -0.3}) {
    TyreInput<double> in = base;
    in.speed *= 1.0 + change;
    in.fz *= 1.0 - change;
    in.fx *= 1.0 + 0.5 * change;
    const TyreInputTerms<Jet7> direct = CalcTyreInputTerms(pj, constants, compound, to_jet(in));
    const TyreInputTerms<Jet7> seeded =
        CalcTyreInputTerms(pj, constants, compound, to_jet(in), &near);
    const auto same = [&](const Jet7& a, const Jet7& b, const char* what) {
      EXPECT_NEAR(a.a, b.a, 1e-14 * std::abs(b.a)) << what << " change " << change;
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(a.v[i], b.v[i], 1e-12 * std::abs(b.v[i]) + 1e-300)
            << what << " derivative " << i << " change " << change;
      }
    };
    same(seeded.load_pow, direct.load_pow, "load power");
    same(seeded.speed_length_pow, direct.speed_length_pow, "speed power");
    same(seeded.wear_power_factor, direct.wear_power_factor, "wear power");
    same(seeded.convection_factor, direct.convection_factor, "convection factor");
  }
  // The derivative seeds reached the powers.
  EXPECT_NE(near.load_pow.v[0], 0.0);
  EXPECT_NE(near.wear_power_factor.v[1], 0.0);
}

TEST(TyreThermalTest, StateDerivativesMatchFiniteDifferences) {
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  const TyreState<double> x = WorkedState();
  const TyreInput<double> in = WorkedInput();
  const TyreState<Jet2> xj{Jet2(x.tread_temp, 0), Jet2(x.carcass_temp, 1), Jet2(0.0)};
  const TyreInput<Jet2> inj{Jet2(in.speed),        Jet2(in.fx),         Jet2(in.fy),
                            Jet2(in.fz),           Jet2(in.slip_angle), Jet2(in.slip_ratio),
                            Jet2(in.ambient_temp), Jet2(in.track_temp)};
  const TyreState<Jet2> d = CalcTyreDerivatives(p.Cast<Jet2>(), DefaultCompound(), xj, inj);
  const std::array<const Jet2*, 3> ad = {&d.tread_temp, &d.carcass_temp, &d.wear};
  for (int i = 0; i < 2; ++i) {
    const Outputs fd = CentralDifference(
        x, [i](TyreState<double>& s) -> double& { return i == 0 ? s.tread_temp : s.carcass_temp; },
        [&](const TyreState<double>& s) { return Evaluate(p, s); });
    for (int k = 0; k < 3; ++k) {
      ExpectNearDerivative(ad[k]->v[i], fd[k], kOutputScale[k] / 300.0,
                           "output " + std::to_string(k) + " state " + std::to_string(i));
    }
  }
  EXPECT_LT(d.tread_temp.v[0], 0.0);  // a hotter tread loses heat faster
  EXPECT_NE(d.wear.v[0], 0.0);        // through w(T_t)
}

// Every function instantiates for every scalar, gives the double value, and carries a derivative
// seeded on the tread temperature that matches a central difference.
template <class T>
class TyreScalarTest : public ::testing::Test {};
using ScalarTypes = test::AllScalarTypes;
TYPED_TEST_SUITE(TyreScalarTest, ScalarTypes);

TYPED_TEST(TyreScalarTest, EveryFunctionInstantiatesAndAgreesWithDouble) {
  using T = TypeParam;
  const TyreThermalParams<double> p = test::PaperRearRightParams();
  const TyreCompound compound = DefaultCompound();
  const TyreInput<double> in = WorkedInput();
  const TyreState<double> x = WorkedState();
  const TyreThermalParams<T> pt = p.template Cast<T>();
  T tread(x.tread_temp);
  if constexpr (IsJet<T>::value) tread.v[0] = 1.0;
  const TyreState<T> xt{tread, T(x.carcass_temp), T(0.5)};
  const TyreInput<T> it{T(in.speed),      T(in.fx),         T(in.fy),           T(in.fz),
                        T(in.slip_angle), T(in.slip_ratio), T(in.ambient_temp), T(in.track_temp)};
  const auto same = [](const T& got, double want) {
    EXPECT_NEAR(ValueOf(got), want, 1e-13 * std::abs(want));
  };
  same(CalcContactLength(pt, it.fz), CalcContactLength(p, in.fz));
  same(CalcForcedConvectionCoefficient(pt, it.speed, xt.tread_temp, it.ambient_temp),
       CalcForcedConvectionCoefficient(p, in.speed, x.tread_temp, in.ambient_temp));
  const TyreHeatFlows<T> qt = CalcTyreHeatFlows(pt, xt, it);
  const TyreHeatFlows<double> q = CalcTyreHeatFlows(p, x, in);
  same(qt.q1, q.q1);
  same(qt.q6, q.q6);
  same(CalcWearRate(pt, compound, xt.tread_temp, qt.q1),
       CalcWearRate(p, compound, x.tread_temp, q.q1));
  same(compound.GripFactor(xt.tread_temp, xt.wear), compound.GripFactor(x.tread_temp, 0.5));
  const TyreState<T> dt = CalcTyreDerivatives(pt, compound, xt, it);
  const TyreState<double> d = CalcTyreDerivatives(p, compound, x, in);
  same(dt.tread_temp, d.tread_temp);
  same(dt.carcass_temp, d.carcass_temp);
  same(dt.wear, d.wear);
  if constexpr (IsJet<T>::value) {
    const double fd = CentralDifference(
        x, [](TyreState<double>& s) -> double& { return s.tread_temp; },
        [&](const TyreState<double>& s) {
          return CalcTyreDerivatives(p, compound, s, in).tread_temp;
        });
    ExpectNearDerivative(dt.tread_temp.v[0], fd, 10.0 / 300.0, "d(dT_t/dt)/dT_t");
  }
}

}  // namespace
}  // namespace hotlap::tyre
