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

}  // namespace
}  // namespace hotlap::ocp
