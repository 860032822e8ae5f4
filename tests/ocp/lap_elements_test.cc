// Exact first and second derivatives of every element of the lap problem against central
// differences, at a realistic operating point of the Gen-7-like car at Darlington.

#include "hotlap/ocp/lap_elements.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/ocp/element.h"
#include "hotlap/ocp/tyre_force_element.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

using internal::NodeRoad;

const vehicle::Car& Gen7() {
  static const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  return car;
}

// Jacobian and Hessian (with weights 1, -0.7, 0.4, ...) of `e` at x against differences,
// relative per entry: 1e-5 (Jacobian) and 1e-4 (Hessian) of the larger of the two, with a floor
// at the central difference's rounding level, 1e-10 of the size of the terms that make the output
// (|value| + sum_i |d out / d x_i x_i|) over the step. So small derivatives (a wear rate's, about
// 2e-7 m/s per unit) are checked as closely as large ones, not hidden under an absolute
// tolerance.
void CheckElement(const Element& e, std::vector<double> x, const std::vector<double>& step,
                  const std::string& what) {
  const int n = e.inputs(), m = e.outputs();
  ASSERT_EQ(static_cast<int>(x.size()), n) << what;
  std::vector<double> out(m), jac(n * m), w(m), hess(n * n);
  for (int o = 0; o < m; ++o) w[o] = o == 0 ? 1.0 : (o % 2 ? -0.7 : 0.4);
  e.Jacobian(x.data(), out.data(), jac.data());
  e.Hessian(x.data(), w.data(), hess.data());
  std::vector<double> values(m);
  e.Values(x.data(), values.data());
  for (int o = 0; o < m; ++o) EXPECT_NEAR(values[o], out[o], 1e-9 * (1 + std::abs(out[o]))) << what;
  // The size of each output's terms, and of the weighted sum's.
  std::vector<double> terms(m);
  double weighted_terms = 0.0;
  for (int o = 0; o < m; ++o) {
    terms[o] = std::abs(out[o]);
    for (int i = 0; i < n; ++i) terms[o] += std::abs(jac[o * n + i] * x[i]);
    weighted_terms += std::abs(w[o]) * terms[o];
  }
  for (int i = 0; i < n; ++i) {
    std::vector<double> xp = x, xm = x;
    xp[i] += step[i];
    xm[i] -= step[i];
    std::vector<double> op(m), om(m), jp(n * m), jm(n * m), dummy(m);
    e.Values(xp.data(), op.data());
    e.Values(xm.data(), om.data());
    e.Jacobian(xp.data(), dummy.data(), jp.data());
    e.Jacobian(xm.data(), dummy.data(), jm.data());
    for (int o = 0; o < m; ++o) {
      const double fd = (op[o] - om[o]) / (2 * step[i]);
      const double ad = jac[o * n + i];
      const double floor = 1e-10 * terms[o] / step[i];
      EXPECT_NEAR(ad, fd, 1e-5 * std::max(std::abs(ad), std::abs(fd)) + floor)
          << what << " d out" << o << "/d in" << i;
    }
    for (int j = 0; j < n; ++j) {
      double fd = 0.0;
      for (int o = 0; o < m; ++o) fd += w[o] * (jp[o * n + j] - jm[o * n + j]) / (2 * step[i]);
      const double ad = hess[i * n + j];
      const double floor = 1e-10 * weighted_terms / (step[i] * std::max(std::abs(x[j]), step[j]));
      EXPECT_NEAR(ad, fd, 1e-4 * std::max(std::abs(ad), std::abs(fd)) + floor)
          << what << " H" << i << j;
    }
  }
}

const NodeRoad kTurn{1.0 / 183.0, DegToRad(25.0), 0.0};

TEST(LapElementsTest, ChassisElements) {
  const vehicle::VehicleParams& p = *Gen7().vehicle;
  CheckElement(*MakeElement<6, 2>(internal::KinematicsFn{&p, Corner::kFrontRight}),
               {75.0, 0.4, 0.41, 0.03, -0.02, 76.0}, {1e-3, 1e-4, 1e-5, 1e-6, 1e-6, 1e-3},
               "kinematics fr");
  CheckElement(*MakeElement<6, 2>(internal::KinematicsFn{&p, Corner::kRearLeft}),
               {75.0, 0.4, 0.41, 0.03, -0.02, 74.0}, {1e-3, 1e-4, 1e-5, 1e-6, 1e-6, 1e-3},
               "kinematics rl");
  CheckElement(*MakeElement<4, 1>(internal::SpoolFn{1.007}), {0.02, 74.0, 0.015, 75.0},
               {1e-6, 1e-3, 1e-6, 1e-3}, "spool");
  CheckElement(*MakeElement<6, 1>(internal::RearDriveFn{0.4}),
               {2000.0, 3000.0, 500.0, 75.0, 0.02, 4e5}, {1.0, 1.0, 1.0, 1e-3, 1e-6, 10.0},
               "rear drive");
  CheckElement(*MakeElement<9, 3>(internal::TotalsFn{&p}),
               {0.03, -100.0, -120.0, 2000.0, 2500.0, 6000.0, 9000.0, 5000.0, 8000.0},
               {1e-6, 1, 1, 1, 1, 1, 1, 1, 1}, "totals");
  CheckElement(*MakeElement<5, 4>(internal::LoadsFn{&p, kTurn}), {75.0, 0.4, 3.0, 4000.0, 30000.0},
               {1e-3, 1e-4, 1e-3, 1.0, 1.0}, "loads");
  CheckElement(*MakeElement<5, 1>(internal::TimeFn{kTurn.kappa_g()}),
               {0.0134, 75.0, 0.4, 3.0, 0.01}, {1e-7, 1e-3, 1e-4, 1e-3, 1e-6}, "time");
  CheckElement(*MakeElement<10, 1>(internal::LongitudinalFn{&p, kTurn, {0.01, 0.01, 0.01, 0.01}}),
               {0.0134, 4000.0, 75.0, 0.4, 0.41, 0.01, 5000.0, 11000.0, 6000.0, 10000.0},
               {1e-7, 1, 1e-3, 1e-4, 1e-5, 1e-6, 1, 1, 1, 1}, "longitudinal");
  CheckElement(*MakeElement<5, 1>(internal::LateralFn{&p, kTurn}),
               {0.0134, 30000.0, 75.0, 0.41, 0.01}, {1e-7, 1, 1e-3, 1e-5, 1e-6}, "lateral");
  CheckElement(*MakeElement<4, 1>(internal::OffsetFn{}), {0.0134, 75.0, 0.4, 0.01},
               {1e-7, 1e-3, 1e-4, 1e-6}, "offset");
  CheckElement(*MakeElement<2, 1>(internal::ScaledProductFn{1.0 / 2900.0}), {0.0134, 4500.0},
               {1e-7, 1.0}, "yaw");
}

// The pedal: drive and brake never on together beyond the smoothing's eps^2 / (4 |p|), the
// split's values by hand, and its derivatives on both sides and at the switch.
TEST(LapElementsTest, PedalSplitsIntoDriveOrBrake) {
  const internal::PedalSplitFn split{450e3, 30e3, 5e-3};
  for (const double pedal : {-0.7, -0.02, 0.0, 0.02, 0.9}) {
    CheckElement(*MakeElement<3, 2>(split), {pedal, 1e5, 1e4}, {1e-5, 1.0, 1.0}, "pedal split");
  }
  double out[2];
  const double at_zero[3] = {0.0, 0.0, 0.0};
  split(at_zero, out);
  EXPECT_NEAR(-out[0], 450e3 * 2.5e-3, 1e-6);  // P = P_max eps / 2 at p = 0
  EXPECT_NEAR(-out[1], 30e3 * 2.5e-3, 1e-6);
  const double drive[3] = {0.5, 0.0, 0.0};
  split(drive, out);
  EXPECT_NEAR(-out[0], 450e3 * 0.5 * (0.5 + std::sqrt(0.25 + 25e-6)), 1e-6);
  EXPECT_LT(-out[1], 30e3 * 25e-6 / (4 * 0.5) * 1.001);  // brake at most B_max eps^2 / (4 p)
  EXPECT_GT(-out[1], 0.0);
  const double brake[3] = {-0.02, 0.0, 0.0};
  split(brake, out);
  EXPECT_LT(-out[0], 450e3 * 25e-6 / (4 * 0.02) * 1.001);  // 141 W of drive at 0.02 braking
}

TEST(LapElementsTest, ThermalAndTyreForceElements) {
  const vehicle::Car& car = Gen7();
  const int fr = CornerIndex(Corner::kFrontRight);
  tyre::TyreThermalParams<double> params = car.tyres[fr].params;
  params.smoothing = {10.0, 1e-3};
  const auto so = params.Cast<SecondOrder<10>>();
  const auto jet = params.Cast<Jet10>();
  CheckElement(*MakeElement<10, 3>(internal::TyreThermalFn{
                   &params, &so, &jet, car.tyres[fr].compound.get(), 298.15, 313.15}),
               {0.0134, 370.0, 340.0, 0.01, 76.0, -500.0, 9000.0, 11000.0, -0.05, -0.01},
               {1e-7, 1e-3, 1e-3, 1e-6, 1e-3, 1e-2, 1e-2, 1e-2, 1e-6, 1e-6}, "tyre thermal");
  const brake::BrakeThermalParams<double>& bp = car.brakes[fr].params;
  const auto bso = bp.Cast<SecondOrder<5>>();
  const auto bjet = bp.Cast<Jet5>();
  CheckElement(*MakeElement<5, 2>(internal::BrakeFn{&bp, &bso, &bjet, 0.3, 298.15}),
               {0.0134, 700.0, 400.0, 76.0, 8000.0}, {1e-7, 1e-3, 1e-3, 1e-3, 1e-1}, "brake");
  const TyreForceElement tyre(car.vehicle->corner(Corner::kFrontRight), *car.tyres[fr].compound,
                              50.0);
  CheckElement(tyre, {11000.0, -0.02, -0.05, 370.0, 0.01, -1000.0, 10000.0},
               {1e-1, 1e-7, 1e-7, 1e-3, 1e-6, 1.0, 1.0}, "tyre forces");
}

// The gas-and-rim tyre with its rim and surface-and-bulk disc: one element, its derivatives
// exact, its rates those of the tyre and brake models coupled through the rim as replay couples
// them (the brake's heat into the rim is the tyre's brake_to_rim; the disc sees the rim).
TEST(LapElementsTest, WheelAndRollingElements) {
  const vehicle::Car& car = Gen7();
  const int fl = CornerIndex(Corner::kFrontLeft);
  ASSERT_TRUE(car.tyres[fl].params.HasGasAndRim());
  ASSERT_TRUE(car.brakes[fl].params.HasBulk());
  tyre::TyreThermalParams<double> tp = car.tyres[fl].params;
  tp.smoothing = {10.0, 1e-3};
  const internal::ParamsOn<tyre::TyreThermalParams, 15> tyre15(tp);
  const internal::ParamsOn<brake::BrakeThermalParams, 15> brake15(car.brakes[fl].params);
  const internal::WheelThermalFn fn{&tyre15, &brake15, car.tyres[fl].compound.get(),
                                    0.3,     298.15,   313.15};
  // w, T_t, T_c, wear, T_rim, vx, fx, fy, fz, alpha, kappa, T_d, T_k, T_bulk, B
  const std::vector<double> x = {0.0134,  370.0, 390.0, 0.01,  345.0, 60.0,  -6000.0, 9000.0,
                                 11000.0, -0.05, -0.04, 700.0, 420.0, 600.0, 20000.0};
  CheckElement(
      *MakeElement<15, 7>(fn), x,
      {1e-7, 1e-3, 1e-3, 1e-6, 1e-3, 1e-3, 1e-2, 1e-2, 1e-2, 1e-6, 1e-6, 1e-3, 1e-3, 1e-3, 1e-1},
      "wheel thermal");
  // The same rates from the models called one by one.
  double out[7];
  fn(x.data(), out);
  const brake::BrakeThermalParams<double>& bp = car.brakes[fl].params;
  brake::BrakeHeatFlows<double> bq;
  const brake::BrakeState<double> bd = brake::CalcBrakeDerivatives(
      bp, brake::BrakeState<double>{700.0, 420.0, 600.0},
      brake::CalcBrakeInputTerms(bp, brake::BrakeInput<double>{60.0, -0.3 * 20000.0, 298.15}), &bq,
      345.0);
  const tyre::TyreInput<double> in{60.0, -6000.0, 9000.0, 11000.0, -0.05, -0.04, 298.15, 313.15};
  tyre::TyreHeatFlows<double>* none = nullptr;
  const tyre::TyreState<double> td = tyre::CalcTyreDerivatives(
      tp, *car.tyres[fl].compound, tyre::TyreState<double>{370.0, 390.0, 0.01, 345.0},
      tyre::CalcTyreInputTerms(tp, *car.tyres[fl].compound, in), none, bq.ToRim());
  ASSERT_GT(bq.ToRim(), 10.0);  // the front disc at 600-700 K heats its rim
  const double expected[7] = {td.tread_temp, td.carcass_temp,  td.wear,     td.rim_temp,
                              bd.disc_temp,  bd.calliper_temp, bd.bulk_temp};
  for (int o = 0; o < 7; ++o) {
    EXPECT_NEAR(out[o], 0.0134 * expected[o], 1e-12 * (1.0 + std::abs(out[o]))) << o;
  }
  // The rim's rate rises with the disc bulk (hub conduction).
  std::vector<double> hotter = x;
  hotter[13] += 50.0;
  double out_hot[7];
  fn(hotter.data(), out_hot);
  EXPECT_GT(out_hot[3], out[3]);

  // Rolling resistance: F_rr - c_rr(T_c, p) Fz, c_rr from the gas at carcass and rim.
  const internal::ParamsOn<tyre::TyreThermalParams, 5> tyre5(tp);
  const internal::RollingForceFn roll{&tyre5};
  CheckElement(*MakeElement<5, 1>(roll), {390.0, 345.0, 60.0, 11000.0, 120.0},
               {1e-3, 1e-3, 1e-3, 1e-2, 1e-3}, "rolling force");
  const double r_in[5] = {390.0, 345.0, 60.0, 11000.0, 0.0};
  double r_out;
  roll(r_in, &r_out);
  const tyre::TyreGas<double> gas = tyre::CalcTyreGas(tp, 390.0, 345.0, 60.0);
  EXPECT_NEAR(-r_out, gas.rolling_resistance * 11000.0, 1e-9);
  EXPECT_GT(gas.rolling_resistance, 0.003);
  EXPECT_LT(gas.rolling_resistance, 0.03);
}

}  // namespace
}  // namespace hotlap::ocp
