#include "hotlap/tyre/unitire.h"

#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap::tyre {
namespace {

constexpr double kTref = 293.15;  // K

// The shipped example's values (data/tyres/unitire_example.yaml), with a sliding-speed effect.
UniTireParams<double> Params() {
  UniTireParams<double> p;
  p.nominal_load = 6000.0;
  p.cornering_stiffness_per_load = 20.0;
  p.cornering_stiffness_load_quad = -0.15;
  p.cornering_stiffness_load_lin = 0.70;
  p.cornering_stiffness_camber = 0.5;
  p.slip_stiffness_per_load = 25.0;
  p.slip_stiffness_load_quad = 0.0;
  p.slip_stiffness_load_lin = 0.30;
  p.friction_x = 1.05;
  p.friction_y = 1.0;
  p.friction_load_decay = 0.1;
  p.friction_sliding_ratio = 0.8;
  p.friction_peak_speed = 2.0;
  p.friction_speed_shape = 0.7;
  p.curvature_x = -0.2;
  p.curvature_y = 0.3;
  p.trail = 0.045;
  p.trail_load_exponent = 0.5;
  p.trail_offset = 0.01;
  p.trail_decay_lin = 0.6;
  p.trail_decay_quad = 0.2;
  p.stiffness_temperature = {1.1, 0.008, kTref};
  p.trail_temperature = {0.9, 0.004, kTref};
  p.friction_temperature = {1.0, 0.002, kTref};
  return p;
}

TyreOperatingPoint<double> Op(double alpha, double kappa = 0.0, double fz = 4000.0,
                              double temp = kTref, double speed = 10.0, double camber = 0.0) {
  TyreOperatingPoint<double> op;
  op.fz = fz;
  op.slip_angle = alpha;
  op.slip_ratio = kappa;
  op.speed = speed;
  op.tread_temp = temp;
  op.camber = camber;
  return op;
}

TEST(UniTireTest, CorneringStiffnessFollowsEquations11To13) {
  const UniTireParams<double> p = Params();
  // Fz = 4000 N: Fzn = 2/3, sech(-0.15 * 4/9 + 0.7 * 2/3) = sech(0.4); f_K(T_ref) = 1.1.
  const double expected = 20.0 * 4000.0 / std::cosh(0.4) * 1.1;
  EXPECT_NEAR(CalcUniTireCorneringStiffness(p, 4000.0, 0.0, kTref), expected, 1e-9);
  // Camber: times (1 - s14 sin^2 gamma).
  EXPECT_NEAR(CalcUniTireCorneringStiffness(p, 4000.0, 0.1, kTref),
              expected * (1.0 - 0.5 * std::sin(0.1) * std::sin(0.1)), 1e-9);
}

// Slopes at zero slip from a Jet seeded on slip angle (row 0) and slip ratio (row 1): exact.
std::array<TyreForces<double>, 2> ZeroSlipSlopes(const UniTireParams<double>& p, double fz,
                                                 double temp) {
  TyreOperatingPoint<Jet2> op;
  op.fz = Jet2(fz);
  op.slip_angle = Jet2(0.0, 0);
  op.slip_ratio = Jet2(0.0, 1);
  op.speed = Jet2(10.0);
  op.tread_temp = Jet2(temp);
  const TyreForces<Jet2> f = CalcUniTireForces(p.Cast<Jet2>(), op);
  std::array<TyreForces<double>, 2> out;
  for (int i = 0; i < 2; ++i) out[i] = {f.fx.v[i], f.fy.v[i], 0.0, 0.0, f.mz.v[i]};
  return out;
}

TEST(UniTireTest, SmallSlipSlopesAreTheStiffnesses) {
  const UniTireParams<double> p = Params();
  for (double fz : {2000.0, 6000.0, 11000.0}) {
    const double ky = CalcUniTireCorneringStiffness(p, fz, 0.0, kTref);
    const double kx = CalcUniTireSlipStiffness(p, fz, kTref);
    // Aligning stiffness K_y D_x(0): D_x0 = 0.045 (Fz/6000)^0.5, times f_D(T_ref) = 0.9.
    const double kz = ky * 0.045 * std::sqrt(fz / 6000.0) * 0.9;
    const auto jet = ZeroSlipSlopes(p, fz, kTref);
    EXPECT_NEAR(jet[0].fy, -ky, 1e-12 * ky) << fz;
    EXPECT_NEAR(jet[0].mz, kz, 1e-12 * kz) << fz;
    EXPECT_NEAR(jet[1].fx, kx, 1e-12 * kx) << fz;
    EXPECT_EQ(jet[0].fx, 0.0);
    EXPECT_EQ(jet[1].fy, 0.0);
    // The same from differences. Fbar(phi) ~ phi + (E - 1/2) phi |phi| is C1 but not C2 at zero
    // slip, so the central difference has an O(h) error: h = 1e-9 keeps it below 1e-8.
    const double h = 1e-9;
    const TyreForces<double> ya = CalcUniTireForces(p, Op(h, 0.0, fz));
    const TyreForces<double> yb = CalcUniTireForces(p, Op(-h, 0.0, fz));
    const TyreForces<double> xa = CalcUniTireForces(p, Op(0.0, h, fz));
    const TyreForces<double> xb = CalcUniTireForces(p, Op(0.0, -h, fz));
    EXPECT_NEAR((ya.fy - yb.fy) / (2 * h), -ky, 1e-6 * ky) << fz;
    EXPECT_NEAR((ya.mz - yb.mz) / (2 * h), kz, 1e-6 * kz) << fz;
    EXPECT_NEAR((xa.fx - xb.fx) / (2 * h), kx, 1e-6 * kx) << fz;
  }
}

TEST(UniTireTest, LargeSlipGivesFrictionForce) {
  const UniTireParams<double> p = Params();
  for (double alpha : {1.2, -1.3}) {
    for (double temp : {273.15, 320.0}) {
      const TyreOperatingPoint<double> op = Op(alpha, 0.0, 5000.0, temp);
      UniTireDetails<double> d;
      const TyreForces<double> f = CalcUniTireForces(p, op, &d);
      const double vs = 10.0 * std::abs(std::tan(alpha));
      EXPECT_NEAR(d.sliding_speed, vs, 1e-12);
      const double mu = CalcUniTireFriction(p, 5000.0, vs, temp).y;
      EXPECT_NEAR(std::abs(f.fy), mu * 5000.0, 1e-9 * 5000.0);
      EXPECT_LT(f.fy * alpha, 0.0);
      // Trail at large phi tends to -D_e f_D: the moment reverses.
      EXPECT_NEAR(f.mz, -f.fy * (-0.01 * CalcTemperatureFactor(p.trail_temperature, temp)), 1e-6);
    }
  }
  // Friction law: the peak mu0 at V_m and Fz_n; r mu0 far from V_m.
  EXPECT_NEAR(CalcUniTireFriction(p, 6000.0, 2.0, kTref).y, 1.0, 1e-15);
  EXPECT_NEAR(CalcUniTireFriction(p, 6000.0, 0.0, kTref).y, 0.8, 1e-9);
  EXPECT_NEAR(CalcUniTireFriction(p, 12000.0, 2.0, kTref).x, 1.05 * std::exp(-0.1), 1e-15);
  // Locked wheel: full sliding along (kappa, -tan alpha).
  const TyreForces<double> locked = CalcUniTireForces(p, Op(0.1, -1.0, 5000.0));
  const UniTireFriction<double> mu =
      CalcUniTireFriction(p, 5000.0, 10.0 * std::hypot(1.0, std::tan(0.1)), kTref);
  EXPECT_LT(locked.fx, 0.0);
  EXPECT_LT(locked.fy, 0.0);
  EXPECT_NEAR(std::hypot(locked.fx / mu.x, locked.fy / mu.y), 5000.0, 1e-9);
}

TEST(UniTireTest, CombinedSlipReducesEachForce) {
  // Without the sliding-speed friction law: friction that rises with sliding speed (r < 1) can
  // let a little combined slip raise a force, through mu rather than through the slip model.
  UniTireParams<double> p = Params();
  p.friction_sliding_ratio = 1.0;
  for (double alpha : {0.03, 0.07, 0.15}) {
    for (double kappa : {0.03, 0.1, -0.1, -0.3}) {
      const double fy_pure = CalcUniTireForces(p, Op(alpha, 0.0)).fy;
      const double fx_pure = CalcUniTireForces(p, Op(0.0, kappa)).fx;
      const TyreForces<double> f = CalcUniTireForces(p, Op(alpha, kappa));
      EXPECT_LT(std::abs(f.fy), std::abs(fy_pure)) << alpha << " " << kappa;
      EXPECT_LT(std::abs(f.fx), std::abs(fx_pure)) << alpha << " " << kappa;
      EXPECT_GT(f.fx * kappa, 0.0);
      EXPECT_LT(f.fy * alpha, 0.0);
    }
  }
}

TEST(UniTireTest, TemperatureFactorScalesStiffnessAndTrail) {
  const UniTireParams<double> p = Params();
  const auto ref = ZeroSlipSlopes(p, 6000.0, kTref);
  EXPECT_NEAR(-ref[0].fy, CalcUniTireCorneringStiffness(p, 6000.0, 0.0, kTref), 1e-9);
  for (double temp : {273.15, 283.15, 326.15}) {
    const auto s = ZeroSlipSlopes(p, 6000.0, temp);
    const double fk = std::exp(-0.008 * (temp - kTref));
    const double fd = std::exp(-0.004 * (temp - kTref));
    // Cornering and slip stiffness scale by f_K / f_K(T_ref) (001:13) ...
    EXPECT_NEAR(s[0].fy / ref[0].fy, fk, 1e-14) << temp;
    EXPECT_NEAR(s[1].fx / ref[1].fx, fk, 1e-14) << temp;
    // ... and the aligning stiffness K_y D_x0 by f_K f_D (001:9, 001:16).
    EXPECT_NEAR(s[0].mz / ref[0].mz, fk * fd, 1e-14) << temp;
  }
}

TEST(UniTireTest, OddInSlipAngle) {
  const UniTireParams<double> p = Params();
  for (double alpha : {0.001, 0.02, 0.1, 0.4}) {
    for (double kappa : {0.0, 0.05, -0.08}) {
      const TyreForces<double> a = CalcUniTireForces(p, Op(alpha, kappa));
      const TyreForces<double> b = CalcUniTireForces(p, Op(-alpha, kappa));
      EXPECT_NEAR(a.fy, -b.fy, 1e-9 * std::abs(a.fy) + 1e-12);
      EXPECT_NEAR(a.mz, -b.mz, 1e-9 * std::abs(a.mz) + 1e-12);
      EXPECT_NEAR(a.fx, b.fx, 1e-9 * std::abs(a.fx) + 1e-12);
    }
  }
}

TEST(UniTireTest, ResultantSeriesJoinsTheClosedForm) {
  for (double e : {-0.5, 0.0, 0.8}) {
    // phi at which g = phi (1 + E phi + ...) crosses the series switch 1e-3.
    double phi = 1e-3;
    for (int i = 0; i < 60; ++i) phi = 1e-3 / (1.0 + phi * (e + (e * e + 1.0 / 12.0) * phi));
    const double below = CalcUniTireResultantOverPhi(phi * (1 - 1e-12), e);
    const double above = CalcUniTireResultantOverPhi(phi * (1 + 1e-12), e);
    EXPECT_NEAR(below, above, 1e-14);
    EXPECT_EQ(CalcUniTireResultantOverPhi(0.0, e), 1.0);
    // A point well inside the closed form.
    const double p = 0.7;
    const double g = p + e * p * p + (e * e + 1.0 / 12.0) * p * p * p;
    EXPECT_NEAR(CalcUniTireResultantOverPhi(p, e) * p, 1.0 - std::exp(-g), 1e-15);
  }
}

TEST(UniTireTest, NoForceWithoutLoad) {
  const TyreForces<double> f = CalcUniTireForces(Params(), Op(0.1, 0.1, 0.0));
  EXPECT_EQ(f.fx, 0.0);
  EXPECT_EQ(f.fy, 0.0);
  EXPECT_EQ(f.mz, 0.0);
}

// --- every scalar -------------------------------------------------------------------------------

template <class T>
class UniTireScalarTest : public ::testing::Test {};
TYPED_TEST_SUITE(UniTireScalarTest, test::AllScalarTypes);

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

// Operating-point inputs seeded in the derivative tests, then every parameter.
constexpr int kOpVars = 6;  // slip_angle, slip_ratio, camber, fz, speed, tread_temp

template <class S>
S& OpRef(int i, TyreOperatingPoint<S>& o) {
  switch (i) {
    case 0:
      return o.slip_angle;
    case 1:
      return o.slip_ratio;
    case 2:
      return o.camber;
    case 3:
      return o.fz;
    case 4:
      return o.speed;
    default:
      return o.tread_temp;
  }
}

template <class S>
S& ParamRef(int i, UniTireParams<S>& p) {
  S* result = nullptr;
  int k = 0;
  std::apply([&](auto&... f) { ((result = (k++ == i ? &f : result)), ...); },
             UniTireParams<S>::FieldsOf(p));
  return *result;
}

// At zero slip (and zero speed) nothing is NaN, in value or in any derivative.
TYPED_TEST(UniTireScalarTest, ZeroSlipIsFinite) {
  using T = TypeParam;
  const UniTireParams<double> p = Params();
  for (double speed : {0.0, 10.0}) {
    for (int var = 0; var < kOpVars + static_cast<int>(kUniTireFieldNames.size()); ++var) {
      UniTireParams<T> pt = p.Cast<T>();
      TyreOperatingPoint<T> ot = CastOp<T>(Op(0.0, 0.0, 4000.0, kTref, speed));
      if constexpr (IsJet<T>::value) {
        (var < kOpVars ? OpRef(var, ot) : ParamRef(var - kOpVars, pt)).v[0] = 1.0;
      }
      UniTireDetails<T> d;
      const TyreForces<T> f = CalcUniTireForces(pt, ot, &d);
      EXPECT_EQ(ValueOf(f.fx), 0.0);
      EXPECT_EQ(ValueOf(f.fy), 0.0);
      EXPECT_EQ(ValueOf(f.mz), 0.0);
      if constexpr (IsJet<T>::value) {
        for (int i = 0; i < T::DIMENSION; ++i) {
          EXPECT_TRUE(std::isfinite(f.fx.v[i]) && std::isfinite(f.fy.v[i]) &&
                      std::isfinite(f.mz.v[i]) && std::isfinite(d.phi.v[i]) &&
                      std::isfinite(d.trail.v[i]))
              << var;
        }
        if (var == 0) {
          const double ky = CalcUniTireCorneringStiffness(p, 4000.0, 0.0, kTref);
          EXPECT_NEAR(f.fy.v[0], -ky, 1e-9 * ky);
        }
      }
    }
  }
}

TYPED_TEST(UniTireScalarTest, DerivativesMatchCentralDifferences) {
  using T = TypeParam;
  const UniTireParams<double> p = Params();
  for (const TyreOperatingPoint<double>& op0 :
       {Op(0.04, 0.02, 3500.0, 300.0, 8.0, 0.03), Op(-0.15, -0.06, 7000.0, 280.0, 12.0, -0.02),
        Op(0.01, 0.3, 5000.0, 330.0, 3.0, 0.01)}) {
    const TyreForces<double> ref = CalcUniTireForces(p, op0);
    for (int var = 0; var < kOpVars + static_cast<int>(kUniTireFieldNames.size()); ++var) {
      const std::string name = var < kOpVars ? "op " + std::to_string(var)
                                             : std::string(kUniTireFieldNames[var - kOpVars]);
      UniTireParams<T> pt = p.Cast<T>();
      TyreOperatingPoint<T> ot = CastOp<T>(op0);
      if constexpr (IsJet<T>::value) {
        (var < kOpVars ? OpRef(var, ot) : ParamRef(var - kOpVars, pt)).v[0] = 1.0;
      }
      const TyreForces<T> f = CalcUniTireForces(pt, ot);
      // Jet arithmetic may round differently in the last bits.
      EXPECT_NEAR(ValueOf(f.fy), ref.fy, 1e-13 * std::abs(ref.fy));
      EXPECT_NEAR(ValueOf(f.mz), ref.mz, 1e-13 * std::abs(ref.mz));
      EXPECT_NEAR(ValueOf(f.fx), ref.fx, 1e-13 * std::abs(ref.fx));
      if constexpr (IsJet<T>::value) {
        struct In {
          UniTireParams<double> p;
          TyreOperatingPoint<double> o;
        };
        In in{p, op0};
        const double x = var < kOpVars ? OpRef(var, in.o) : ParamRef(var - kOpVars, in.p);
        if (x == 0.0) continue;  // a relative step of 0
        // The differences' rounding error is about 1e-16 |F| / (1e-6 |x|): scale the floor by
        // |F| / |x| (ExpectNearDerivative's floor is 1e-9 scale).
        const double fscale = 5000.0 / std::abs(x);
        const double mscale = 200.0 / std::abs(x);
        const auto fd = test::CentralDifference(
            in,
            [&](In& x) -> double& {
              return var < kOpVars ? OpRef(var, x.o) : ParamRef(var - kOpVars, x.p);
            },
            [](const In& x) {
              const TyreForces<double> g = CalcUniTireForces(x.p, x.o);
              return std::array<double, 3>{g.fx, g.fy, g.mz};
            });
        test::ExpectNearDerivative(f.fx.v[0], fd[0], fscale, name + " fx");
        test::ExpectNearDerivative(f.fy.v[0], fd[1], fscale, name + " fy");
        test::ExpectNearDerivative(f.mz.v[0], fd[2], mscale, name + " mz");
      }
    }
  }
}

}  // namespace
}  // namespace hotlap::tyre
