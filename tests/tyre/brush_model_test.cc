#include "hotlap/tyre/brush_model.h"

#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap::tyre {
namespace {

constexpr double kTa = 293.15;  // K, the rubber's T_A and the carcass reference temperature

// a = 0.05 m (load-independent), k = 6 (0.5 + 0.5) MPa = 6e6 N/m^2 at T_A, mu = 1, so at
// Fz = 4000 N: C_Fa = 2 k a^2 = 30000 N/rad and theta = C_Fa / (3 mu Fz) = 2.5 (full sliding
// from tan(alpha) = 0.4). `c_ct` in N m/rad.
BrushParams<double> Params(double c_ct) {
  BrushParams<double> p;
  p.contact_half_length = 0.05;
  p.reference_load = 4000.0;
  p.contact_length_exponent = 0.0;
  p.rubber = {5.0e5, 0.02, kTa, 5.0e5, 6.0};
  p.friction = 1.0;
  p.carcass_lateral_stiffness = {25000.0, 0.0106, kTa};
  p.carcass_torsional_stiffness = {c_ct, 0.0137, kTa};
  return p;
}

constexpr double kRigid = 1e15;  // c_ct -> infinity

TyreOperatingPoint<double> Op(double tan_alpha, double kappa = 0.0, double temp = kTa,
                              double fz = 4000.0) {
  TyreOperatingPoint<double> op;
  op.fz = fz;
  op.slip_angle = std::atan(tan_alpha);
  op.slip_ratio = kappa;
  op.speed = 20.0;
  op.tread_temp = temp;
  return op;
}

// Hand-computed textbook brush values (spec section 7) with mu Fz = 4000 N, theta = 2.5, a = 0.05:
// psi = 2.5 tan(alpha); Fy = -4000 (1 - (1 - psi)^3); Mz = 4000 * 0.05 * 2.5 tan(alpha) (1 -
// psi)^3.
struct HandValue {
  double tan_alpha, fy, mz;
};
constexpr std::array<HandValue, 3> kHandValues = {{
    {0.02, -570.5, 8.57375},    // psi 0.05: 1 - 0.95^3 = 0.142625; 10 * 0.857375
    {0.10, -2312.5, 21.09375},  // psi 0.25: 1 - 0.75^3 = 0.578125; 50 * 0.421875
    {0.20, -3500.0, 12.5},      // psi 0.5:  1 - 0.5^3 = 0.875;     100 * 0.125
}};

TEST(BrushModelTest, RigidCarcassGivesTheTextbookBrush) {
  const BrushParams<double> p = Params(kRigid);
  for (const HandValue& h : kHandValues) {
    const TyreForces<double> f = CalcBrushForces(p, Op(h.tan_alpha));
    EXPECT_NEAR(f.fy, h.fy, 1e-9 * std::abs(h.fy)) << h.tan_alpha;
    EXPECT_NEAR(f.mz, h.mz, 1e-9 * std::abs(h.mz)) << h.tan_alpha;
    EXPECT_NEAR(f.fx, 0.0, 1e-12);
    // The printed pneumatic trail (a/3)(1 - psi)^3 / (1 - psi + psi^2/3).
    const double psi = 2.5 * h.tan_alpha;
    EXPECT_NEAR(f.mz / -f.fy, 0.05 / 3.0 * std::pow(1.0 - psi, 3) / (1.0 - psi + psi * psi / 3.0),
                1e-12);
  }
  EXPECT_DOUBLE_EQ(CalcCorneringStiffness(p, 4000.0, kTa), 30000.0);
}

TEST(BrushModelTest, LongitudinalBrushUsesTheSameBristles) {
  const BrushParams<double> p = Params(kRigid);
  // sigma_x = kappa / (1 + kappa) = +-0.1 is psi = 0.25: |Fx| = 2312.5 N, no Fy or Mz.
  const TyreForces<double> drive = CalcBrushForces(p, Op(0.0, 1.0 / 9.0));
  const TyreForces<double> brake = CalcBrushForces(p, Op(0.0, -1.0 / 11.0));
  EXPECT_NEAR(drive.fx, 2312.5, 1e-9 * 2312.5);
  EXPECT_NEAR(brake.fx, -2312.5, 1e-9 * 2312.5);
  EXPECT_EQ(drive.fy, 0.0);
  EXPECT_EQ(drive.mz, 0.0);
}

TEST(BrushModelTest, CombinedSlipSharesTheResultant) {
  const BrushParams<double> p = Params(kRigid);
  // sigma = (0.06, 0.08) / 1 with kappa = 0.06 / 0.94... pick sigma_x = 0.06, sigma_y = 0.08:
  // kappa = 0.06 / 0.94, tan(alpha) = 0.08 (1 + kappa) = 0.08 / 0.94; |sigma| = 0.1, psi = 0.25.
  const double kappa = 0.06 / 0.94;
  const TyreForces<double> f = CalcBrushForces(p, Op(0.08 / 0.94, kappa));
  EXPECT_NEAR(f.fx, 2312.5 * 0.6, 1e-9 * 2312.5);
  EXPECT_NEAR(f.fy, -2312.5 * 0.8, 1e-9 * 2312.5);
  // Mz = mu Fz a theta sigma_y (1 - psi)^3 = 4000 * 0.05 * 2.5 * 0.08 * 0.421875.
  EXPECT_NEAR(f.mz, 16.875, 1e-9 * 16.875);
  // Each force is below its pure-slip value.
  EXPECT_LT(std::abs(f.fy), std::abs(CalcBrushForces(p, Op(0.08 / 0.94)).fy));
  EXPECT_LT(std::abs(f.fx), std::abs(CalcBrushForces(p, Op(0.0, kappa)).fx));
}

TEST(BrushModelTest, SmallSlipGivesCorneringStiffness) {
  const BrushParams<double> p = Params(kRigid);
  const double t = 1e-6;
  const TyreForces<double> f = CalcBrushForces(p, Op(t));
  EXPECT_NEAR(f.fy / t, -30000.0, 30000.0 * 1e-5);
  EXPECT_NEAR(f.mz / t, 30000.0 * 0.05 / 3.0, 500.0 * 1e-5);
}

TEST(BrushModelTest, FullSlidingGivesFrictionForceAndNoMoment) {
  for (double c_ct : {kRigid, 1000.0}) {
    const BrushParams<double> p = Params(c_ct);
    for (double t : {0.4, 0.5, 1.0, -3.0}) {
      const TyreForces<double> f = CalcBrushForces(p, Op(t));
      EXPECT_NEAR(f.fy, t > 0 ? -4000.0 : 4000.0, 1e-9) << t;
      EXPECT_NEAR(f.mz, 0.0, 1e-12) << t;
    }
    // Locked wheel: slides along (kappa, tan alpha) = (-1, 0.5).
    const TyreForces<double> locked = CalcBrushForces(p, Op(0.5, -1.0));
    EXPECT_NEAR(std::hypot(locked.fx, locked.fy), 4000.0, 1e-9);
    EXPECT_NEAR(locked.fy / locked.fx, 0.5, 1e-12);
  }
}

TEST(BrushModelTest, TorsionalComplianceLowersTheCorneringStiffness) {
  // C_Fa t0 / c_ct = 30000 * (0.05 / 3) / 1000 = 0.5: C'_Fa = 20000 N/rad and the aligning
  // stiffness C_Fa t0 / 1.5 = 333.33 N m/rad (001:3, 001:5).
  const BrushParams<double> p = Params(1000.0);
  EXPECT_NEAR(CalcEffectiveCorneringStiffness(p, 4000.0, kTa), 20000.0, 1e-9);
  EXPECT_NEAR(CalcAligningStiffness(p, 4000.0, kTa), 1000.0 / 3.0, 1e-9);
  const double h = 1e-7;
  const TyreForces<double> up = CalcBrushForces(p, Op(h));
  const TyreForces<double> down = CalcBrushForces(p, Op(-h));
  EXPECT_NEAR(-(up.fy - down.fy) / (2 * h), 20000.0, 20000.0 * 1e-6);
  EXPECT_NEAR((up.mz - down.mz) / (2 * h), 1000.0 / 3.0, 1000.0 / 3.0 * 1e-6);
  // Away from the linear range, the fixed point holds: tan(alpha') = tan(alpha) - Mz / c_ct.
  BrushDetails<double> d;
  const TyreForces<double> f = CalcBrushForces(p, Op(0.1, 0.03), &d);
  EXPECT_NEAR(d.tan_effective_slip_angle, 0.1 - f.mz / 1000.0, 1e-15);
  EXPECT_LT(d.tan_effective_slip_angle, 0.1);
  EXPECT_LT(std::abs(f.fy), std::abs(CalcBrushForces(Params(kRigid), Op(0.1, 0.03)).fy));
  EXPECT_GT(d.newton_iterations, 0);
  EXPECT_LT(d.newton_iterations, 20);
}

TEST(BrushModelTest, HotterTreadIsSofter) {
  const BrushParams<double> p = Params(1000.0);
  const double cold = 273.15, hot = 326.15;
  EXPECT_GT(CalcBristleStiffness(p.rubber, cold), CalcBristleStiffness(p.rubber, hot));
  EXPECT_GT(CalcCorneringStiffness(p, 4000.0, cold), CalcCorneringStiffness(p, 4000.0, hot));
  EXPECT_GT(CalcEffectiveCorneringStiffness(p, 4000.0, cold),
            CalcEffectiveCorneringStiffness(p, 4000.0, hot));
  // At a small slip angle the hot tyre makes less force.
  EXPECT_GT(std::abs(CalcBrushForces(p, Op(0.02, 0.0, cold)).fy),
            std::abs(CalcBrushForces(p, Op(0.02, 0.0, hot)).fy));
}

TEST(BrushModelTest, RelaxationLengthAndContactLength) {
  BrushParams<double> p = Params(1000.0);
  EXPECT_NEAR(CalcRelaxationLength(p, 4000.0, kTa), 30000.0 / 25000.0, 1e-12);
  EXPECT_NEAR(CalcRelaxationLength(p, 4000.0, kTa + 10.0),
              30000.0 * (0.5 * std::exp(-0.2) + 0.5) / (25000.0 * std::exp(-0.106)), 1e-12);
  p.contact_length_exponent = 0.5;
  EXPECT_NEAR(CalcContactHalfLength(p, 16000.0), 0.1, 1e-15);
  EXPECT_EQ(CalcContactHalfLength(p, 0.0), 0.0);
  const TyreForces<double> none = CalcBrushForces(p, Op(0.1, 0.0, kTa, -10.0));
  EXPECT_EQ(none.fy, 0.0);
  EXPECT_EQ(none.mz, 0.0);
}

TEST(BrushModelTest, OddInSlipAngle) {
  const BrushParams<double> p = Params(1000.0);
  for (double t : {0.01, 0.07, 0.2, 0.35}) {
    for (double kappa : {0.0, 0.04, -0.06}) {
      const TyreForces<double> a = CalcBrushForces(p, Op(t, kappa));
      const TyreForces<double> b = CalcBrushForces(p, Op(-t, kappa));
      EXPECT_NEAR(a.fy, -b.fy, 1e-9);
      EXPECT_NEAR(a.mz, -b.mz, 1e-10);
      EXPECT_NEAR(a.fx, b.fx, 1e-9);
    }
  }
}

// --- every scalar: instantiation and derivatives --------------------------------------------

template <class T>
class BrushScalarTest : public ::testing::Test {};
TYPED_TEST_SUITE(BrushScalarTest, test::AllScalarTypes);

// The inputs and parameters the derivative test varies, addressed in any scalar type.
enum class Var {
  kSlipAngle,
  kSlipRatio,
  kFz,
  kTreadTemp,
  kFriction,
  kModulusDecay,
  kTorsionalStiffness,
  kTorsionalDecay,
  kHalfLength,
  kLengthExponent,
};
constexpr std::array<Var, 10> kVars = {
    Var::kSlipAngle,          Var::kSlipRatio,      Var::kFz,
    Var::kTreadTemp,          Var::kFriction,       Var::kModulusDecay,
    Var::kTorsionalStiffness, Var::kTorsionalDecay, Var::kHalfLength,
    Var::kLengthExponent};

template <class S>
S& Ref(Var v, BrushParams<S>& p, TyreOperatingPoint<S>& o) {
  switch (v) {
    case Var::kSlipAngle:
      return o.slip_angle;
    case Var::kSlipRatio:
      return o.slip_ratio;
    case Var::kFz:
      return o.fz;
    case Var::kTreadTemp:
      return o.tread_temp;
    case Var::kFriction:
      return p.friction;
    case Var::kModulusDecay:
      return p.rubber.modulus_decay;
    case Var::kTorsionalStiffness:
      return p.carcass_torsional_stiffness.scale;
    case Var::kTorsionalDecay:
      return p.carcass_torsional_stiffness.decay;
    case Var::kHalfLength:
      return p.contact_half_length;
    case Var::kLengthExponent:
      return p.contact_length_exponent;
  }
  return o.fz;
}

template <Scalar T>
TyreOperatingPoint<T> CastOp(const TyreOperatingPoint<double>& o) {
  TyreOperatingPoint<T> t;
  t.fz = T(o.fz);
  t.slip_ratio = T(o.slip_ratio);
  t.slip_angle = T(o.slip_angle);
  t.camber = T(o.camber);
  t.speed = T(o.speed);
  t.pressure = T(o.pressure);
  t.tread_temp = T(o.tread_temp);
  return t;
}

TYPED_TEST(BrushScalarTest, DerivativesMatchCentralDifferences) {
  using T = TypeParam;
  BrushParams<double> p = Params(1000.0);
  p.contact_length_exponent = 0.4;
  for (const TyreOperatingPoint<double>& op0 :
       {Op(0.03, 0.02, 300.0, 3500.0), Op(-0.12, -0.05, 280.0, 4500.0), Op(0.6, 0.1)}) {
    const TyreForces<double> ref = CalcBrushForces(p, op0);
    for (Var v : kVars) {
      const std::string name = "variable " + std::to_string(static_cast<int>(v));
      BrushParams<T> pt = p.Cast<T>();
      TyreOperatingPoint<T> ot = CastOp<T>(op0);
      if constexpr (IsJet<T>::value) Ref(v, pt, ot).v[0] = 1.0;
      const TyreForces<T> f = CalcBrushForces(pt, ot);
      // Jet arithmetic may round differently in the last bits.
      EXPECT_NEAR(ValueOf(f.fy), ref.fy, 1e-13 * std::abs(ref.fy));
      EXPECT_NEAR(ValueOf(f.mz), ref.mz, 1e-13 * std::abs(ref.mz));
      EXPECT_NEAR(ValueOf(f.fx), ref.fx, 1e-13 * std::abs(ref.fx));
      if constexpr (IsJet<T>::value) {
        struct In {
          BrushParams<double> p;
          TyreOperatingPoint<double> o;
        };
        In in{p, op0};
        // The differences' rounding error is about 1e-16 |F| / (1e-6 |x|): scale the floor by
        // |F| / |x| (ExpectNearDerivative's floor is 1e-9 scale).
        const double x = std::abs(Ref(v, in.p, in.o));
        const auto fd = test::CentralDifference(
            in, [&](In& x) -> double& { return Ref(v, x.p, x.o); },
            [](const In& x) {
              const TyreForces<double> g = CalcBrushForces(x.p, x.o);
              return std::array<double, 3>{g.fx, g.fy, g.mz};
            });
        test::ExpectNearDerivative(f.fx.v[0], fd[0], 4000.0 / x, name + " fx");
        test::ExpectNearDerivative(f.fy.v[0], fd[1], 4000.0 / x, name + " fy");
        test::ExpectNearDerivative(f.mz.v[0], fd[2], 100.0 / x, name + " mz");
      }
    }
  }
}

// At zero slip the Jet derivatives are finite and equal the stiffnesses.
TYPED_TEST(BrushScalarTest, ZeroSlipDerivativesAreTheStiffnesses) {
  using T = TypeParam;
  const BrushParams<double> p = Params(1000.0);
  TyreOperatingPoint<T> op = CastOp<T>(Op(0.0));
  if constexpr (IsJet<T>::value) {
    op.slip_angle.v[0] = 1.0;
    op.slip_ratio.v[1] = 1.0;
  }
  const TyreForces<T> f = CalcBrushForces(p.Cast<T>(), op);
  EXPECT_EQ(ValueOf(f.fy), 0.0);
  if constexpr (IsJet<T>::value) {
    for (int i = 0; i < T::DIMENSION; ++i) {
      EXPECT_TRUE(std::isfinite(f.fx.v[i]) && std::isfinite(f.fy.v[i]) && std::isfinite(f.mz.v[i]));
    }
    EXPECT_NEAR(f.fy.v[0], -20000.0, 1e-9);
    EXPECT_NEAR(f.mz.v[0], 1000.0 / 3.0, 1e-9);
    EXPECT_NEAR(f.fx.v[1], 30000.0, 1e-9);  // no torsion in pure longitudinal slip
  }
}

}  // namespace
}  // namespace hotlap::tyre
