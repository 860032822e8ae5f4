// The ABS plant: the power balance of its right-hand side at any state, the transient slip's
// steady state, the locked wheel, the road friction meeting each tyre model, every scalar type,
// and derivatives against central differences.

#include "hotlap/abs/abs_plant.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/abs/abs_config.h"
#include "test_util.h"

namespace {

using hotlap::sim::AbsPlantInput;
using hotlap::sim::AbsPlantModel;
using hotlap::sim::AbsPlantOutputs;
using hotlap::sim::AbsPlantState;
using hotlap::sim::AbsVehicleMode;
using hotlap::sim::CalcAbsPlantDerivatives;
using hotlap::sim::CalcAbsTyreForces;
using hotlap::sim::FrictionLaw;
using hotlap::sim::WheelMode;
namespace tyre = hotlap::tyre;

const hotlap::sim::AbsConfig& Config() {
  static const hotlap::sim::AbsConfig c =
      hotlap::sim::LoadAbsConfig(hotlap::test::SourcePath("data/abs/paper.yaml"));
  return c;
}

AbsPlantState<double> State(double speed, double lambda, double slip, double pressure) {
  AbsPlantState<double> x;
  x.speed = speed;
  x.wheel_speed = speed * (1.0 - lambda) / Config().plant.wheel.radius;
  x.slip = slip;
  x.pressure = pressure;
  return x;
}

// d/dt of the kinetic energy from the derivatives: m V dV/dt + J omega domega/dt.
double KineticPower(const AbsPlantModel<double>& m, const AbsPlantState<double>& x,
                    const AbsPlantState<double>& d) {
  return m.wheel.mass * x.speed * d.speed + m.wheel.inertia * x.wheel_speed * d.wheel_speed;
}

TEST(AbsPlantTest, PowersBalanceAtEveryStateInEveryMode) {
  const AbsPlantModel<double>& m = Config().plant;
  const FrictionLaw<double> road{0.9, 0.45, 0.5};
  for (AbsVehicleMode vehicle : {AbsVehicleMode::kFree, AbsVehicleMode::kDrum}) {
    for (double lambda : {0.0, 0.05, 0.2, 0.9}) {
      for (double slip : {0.0, -0.03, -0.15, -0.8}) {
        AbsPlantInput<double> in{.pressure_target = 6e6, .road = road, .vehicle = vehicle};
        const AbsPlantState<double> x = State(10.0, lambda, slip, 7e6);
        AbsPlantOutputs<double> o;
        const AbsPlantState<double> d = CalcAbsPlantDerivatives(m, x, in, &o);
        // d(KE)/dt + brake + slip + rolling = drum.
        const double balance = KineticPower(m, x, d) + d.brake_energy + d.slip_energy +
                               d.rolling_energy - d.drum_energy;
        EXPECT_NEAR(balance, 0.0, 1e-9 * (std::abs(d.slip_energy) + d.brake_energy + 1.0))
            << lambda << " " << slip;
        EXPECT_GE(d.brake_energy, 0.0);
        EXPECT_DOUBLE_EQ(o.brake_torque, 150e-6 * 7e6);
      }
    }
  }
}

TEST(AbsPlantTest, TransientSlipRestsAtTheKinematicSlip) {
  const AbsPlantModel<double>& m = Config().plant;
  AbsPlantInput<double> in{.road = {0.9, 0.45, 0.5}};
  // kappa' = (R omega - Vx) / Vx = -lambda: no change.
  const AbsPlantState<double> x = State(8.0, 0.07, -0.07, 0.0);
  EXPECT_NEAR(CalcAbsPlantDerivatives(m, x, in).slip, 0.0, 1e-12);
  // Otherwise it relaxes toward it at |Vx| / sigma.
  const AbsPlantState<double> y = State(8.0, 0.07, -0.02, 0.0);
  EXPECT_NEAR(CalcAbsPlantDerivatives(m, y, in).slip,
              -8.0 * (0.07 - 0.02) / m.wheel.relaxation_length, 1e-9);
}

TEST(AbsPlantTest, ALockedWheelIsHeldWithNoBrakePower) {
  const AbsPlantModel<double>& m = Config().plant;
  AbsPlantInput<double> in{.road = {0.9, 0.45, 0.5}, .wheel = WheelMode::kLocked};
  AbsPlantState<double> x = State(6.0, 1.0, -1.0, 12e6);
  AbsPlantOutputs<double> o;
  const AbsPlantState<double> d = CalcAbsPlantDerivatives(m, x, in, &o);
  EXPECT_EQ(d.wheel_speed, 0.0);
  EXPECT_EQ(d.brake_energy, 0.0);
  EXPECT_EQ(d.rolling_energy, 0.0);
  EXPECT_DOUBLE_EQ(o.brake_torque, o.holding_torque);
  EXPECT_DOUBLE_EQ(o.holding_torque, -m.wheel.radius * o.fx + o.my);
  EXPECT_LT(o.holding_torque, o.brake_capacity);  // 1800 N m holds it
  // Sliding: mu(v_s = 6 m/s) Fz backwards (the brush in full sliding), all into slip heat.
  EXPECT_NEAR(o.fx, -(0.45 + 0.45 * std::exp(-3.0)) * m.wheel.vertical_load, 1e-6);
  EXPECT_NEAR(d.slip_energy, -o.fx * 6.0, 1e-9);
  EXPECT_DOUBLE_EQ(d.speed, o.fx / m.wheel.mass);
}

TEST(AbsPlantTest, DrumModeHoldsTheSpeed) {
  const AbsPlantModel<double>& m = Config().plant;
  AbsPlantInput<double> in{.road = {0.9, 0.45, 0.5}, .vehicle = AbsVehicleMode::kDrum};
  AbsPlantOutputs<double> o;
  const AbsPlantState<double> d = CalcAbsPlantDerivatives(m, State(10, 0.1, -0.1, 5e6), in, &o);
  EXPECT_EQ(d.speed, 0.0);
  EXPECT_NEAR(d.drum_energy, -o.fx * 10.0, 1e-9);
}

// The road scales each model's friction, and leaves its slip stiffness.
void ExpectFrictionScaling(const tyre::TyreForceModel<double>& model, double fz) {
  tyre::TyreOperatingPoint<double> op{.fz = fz, .speed = 10.0, .tread_temp = 293.15};
  const auto fx = [&](double kappa, double scale) {
    op.slip_ratio = kappa;
    return CalcAbsTyreForces(model, op, scale).fx;
  };
  // The slope at small slip (Magic Formula shifts make Fx itself non-zero at zero slip).
  const auto slope = [&](double scale) { return (fx(-4e-4, scale) - fx(-2e-4, scale)) / 2e-4; };
  EXPECT_NEAR(slope(0.5), slope(1.0), 0.05 * std::abs(slope(1.0))) << model.name;
  double peak1 = 0.0, peak05 = 0.0;
  for (double k = -0.005; k > -1.0; k -= 0.005) {
    peak1 = std::max(peak1, -fx(k, 1.0));
    peak05 = std::max(peak05, -fx(k, 0.5));
  }
  EXPECT_NEAR(peak05 / peak1, 0.5, 0.01) << model.name;
}

TEST(AbsPlantTest, RoadFrictionScalesThePeakOfEveryTyreModel) {
  ExpectFrictionScaling(Config().plant.tyre, 4314.0);  // brush
  ExpectFrictionScaling(
      tyre::LoadTyreForceModel(hotlap::test::SourcePath("tests/data/tir/mfeval/"
                                                        "MagicFormula61_Parameters.tir")),
      4000.0);
  ExpectFrictionScaling(
      tyre::LoadTyreForceModel(hotlap::test::SourcePath("data/tyres/unitire_example.yaml")),
      4000.0);
}

template <class T>
class AbsPlantScalarTest : public ::testing::Test {};
TYPED_TEST_SUITE(AbsPlantScalarTest, hotlap::test::AllScalarTypes);

TYPED_TEST(AbsPlantScalarTest, InstantiatesAndAgreesWithDouble) {
  using T = TypeParam;
  const AbsPlantModel<T> m = Config().plant.template Cast<T>();
  const AbsPlantState<double> xd = State(9.0, 0.08, -0.06, 8e6);
  AbsPlantState<T> x;
  x.speed = T(xd.speed);
  x.wheel_speed = T(xd.wheel_speed);
  x.slip = T(xd.slip);
  x.pressure = T(xd.pressure);
  AbsPlantInput<T> in{.pressure_target = T(7e6),
                      .road = FrictionLaw<double>{0.9, 0.45, 0.5}.Cast<T>()};
  AbsPlantInput<double> ind{.pressure_target = 7e6, .road = {0.9, 0.45, 0.5}};
  const AbsPlantState<T> d = CalcAbsPlantDerivatives(m, x, in);
  const AbsPlantState<double> dd = CalcAbsPlantDerivatives(Config().plant, xd, ind);
  EXPECT_DOUBLE_EQ(hotlap::ValueOf(d.wheel_speed), dd.wheel_speed);
  EXPECT_DOUBLE_EQ(hotlap::ValueOf(d.speed), dd.speed);
  EXPECT_DOUBLE_EQ(hotlap::ValueOf(d.slip_energy), dd.slip_energy);
}

TEST(AbsPlantTest, DerivativesMatchCentralDifferences) {
  using J = hotlap::Jet2;
  const AbsPlantModel<double>& md = Config().plant;
  const AbsPlantModel<J> m = md.Cast<J>();
  const AbsPlantState<double> xd = State(9.0, 0.08, -0.06, 8e6);
  const FrictionLaw<double> road{0.9, 0.45, 0.5};
  AbsPlantState<J> x;
  x.speed = J(xd.speed);
  x.wheel_speed = J(xd.wheel_speed);
  x.slip = J(xd.slip, 0);  // d/d(kappa')
  x.pressure = J(xd.pressure);
  AbsPlantInput<J> in{.pressure_target = J(7e6), .road = road.Cast<J>()};
  in.road.decay.v[1] = 1.0;  // d/d(d_c)
  const AbsPlantState<J> d = CalcAbsPlantDerivatives(m, x, in);
  const auto omega_dot = [&](const AbsPlantState<double>& s, const FrictionLaw<double>& r) {
    return CalcAbsPlantDerivatives(md, s, AbsPlantInput<double>{.pressure_target = 7e6, .road = r})
        .wheel_speed;
  };
  const double fd_slip = hotlap::test::CentralDifference(
      xd, [](AbsPlantState<double>& s) -> double& { return s.slip; },
      [&](const AbsPlantState<double>& s) { return omega_dot(s, road); });
  const double fd_decay = hotlap::test::CentralDifference(
      road, [](FrictionLaw<double>& r) -> double& { return r.decay; },
      [&](const FrictionLaw<double>& r) { return omega_dot(xd, r); });
  hotlap::test::ExpectNearDerivative(d.wheel_speed.v[0], fd_slip, 1e4, "domega_dot/dkappa'");
  hotlap::test::ExpectNearDerivative(d.wheel_speed.v[1], fd_decay, 1e3, "domega_dot/dd_c");
}

}  // namespace
