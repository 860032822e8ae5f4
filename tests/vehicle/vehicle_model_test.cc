#include "hotlap/vehicle/vehicle_model.h"

#include <cmath>
#include <numeric>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "hotlap/common/units.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::vehicle {
namespace {

const VehicleParams& Gen7() {
  static const Car car = LoadCar(test::Gen7Dir() / "car.yaml");
  return *car.vehicle;
}

double Sum(const std::array<double, 4>& a) { return std::accumulate(a.begin(), a.end(), 0.0); }

constexpr int kFl = 0, kFr = 1, kRl = 2, kRr = 3;

TEST(VehicleModelTest, StaticLoadsSumToWeightWithTheStaticSplit) {
  const VehicleParams& p = Gen7();
  const double w = p.chassis.mass * kGravity;
  const auto fz = CalcNormalLoads<double>(p, {0.0, 0.0, 0.0, 0.0}, {}, 0.0, 0.0);
  EXPECT_NEAR(Sum(fz), w, 1e-9 * w);
  const double f = p.chassis.front_weight_fraction, l = p.chassis.left_weight_fraction;
  EXPECT_NEAR(fz[kFl], w * f * l, 1e-9 * w);
  EXPECT_NEAR(fz[kFr], w * f * (1 - l), 1e-9 * w);
  EXPECT_NEAR(fz[kRl], w * (1 - f) * l, 1e-9 * w);
  EXPECT_NEAR(fz[kRr], w * (1 - f) * (1 - l), 1e-9 * w);
}

TEST(VehicleModelTest, DownforceAddsWithItsBalance) {
  const VehicleParams& p = Gen7();
  const double u = 80.0;
  const double down = 0.5 * p.aero.air_density * p.aero.downforce_area * u * u;
  const auto still = CalcNormalLoads<double>(p, {0.0, 0.0, 0.0, 0.0}, {}, 0.0, 0.0);
  const auto fast = CalcNormalLoads<double>(p, {u, 0.0, 0.0, 0.0}, {}, 0.0, 0.0);
  EXPECT_NEAR(Sum(fast) - Sum(still), down, 1e-6 * down);
  const double front = fast[kFl] + fast[kFr] - still[kFl] - still[kFr];
  EXPECT_NEAR(front, p.aero.front_downforce_share * down, 1e-6 * down);
  EXPECT_NEAR(fast[kFl] - still[kFl], fast[kFr] - still[kFr], 1e-9 * down);  // centred
}

// Driving moves h sum_fx / L from the front to the rear axle; cornering left moves
// share h sum_fy / track from each axle's left wheel to its right wheel. Totals unchanged.
TEST(VehicleModelTest, LoadTransferFollowsThePitchAndRollBalance) {
  const VehicleParams& p = Gen7();
  const ChassisMotion<double> m{40.0, 0.0, 0.0, 0.0};
  const auto base = CalcNormalLoads<double>(p, m, {}, 0.0, 0.0);
  const double fx = 6000.0, fy = 12000.0;
  const auto drive = CalcNormalLoads<double>(p, m, {}, fx, 0.0);
  const double pitch = p.chassis.cog_height * fx / p.chassis.wheelbase;
  EXPECT_NEAR(drive[kFl] - base[kFl], -0.5 * pitch, 1e-9);
  EXPECT_NEAR(drive[kRr] - base[kRr], 0.5 * pitch, 1e-9);
  EXPECT_NEAR(Sum(drive), Sum(base), 1e-9);
  const auto turn = CalcNormalLoads<double>(p, m, {}, 0.0, fy);
  const double roll = p.chassis.cog_height * fy;
  const double lf = p.chassis.roll_stiffness_front_share;
  EXPECT_NEAR(turn[kFl] - base[kFl], -lf * roll / p.chassis.track_front, 1e-9);
  EXPECT_NEAR(turn[kFr] - base[kFr], lf * roll / p.chassis.track_front, 1e-9);
  EXPECT_NEAR(turn[kRl] - base[kRl], -(1 - lf) * roll / p.chassis.track_rear, 1e-9);
  EXPECT_NEAR(Sum(turn), Sum(base), 1e-9);
  // The total roll moment of the transfer is h sum_fy.
  const double moment =
      (turn[kFr] - turn[kFl] - base[kFr] + base[kFl]) * 0.5 * p.chassis.track_front +
      (turn[kRr] - turn[kRl] - base[kRr] + base[kRl]) * 0.5 * p.chassis.track_rear;
  EXPECT_NEAR(moment, roll, 1e-9 * roll);
}

// Spec section 10: sum Fz = m g cos(theta) + m u^2 kappa_n + downforce on a banked turn.
TEST(VehicleModelTest, BankingAndNormalCurvatureLoadTheRoad) {
  const VehicleParams& p = Gen7();
  const double u = 70.0, bank = DegToRad(25.0), kappa_h = 1.0 / 183.0;
  const RoadGeometry<double> road{bank, 0.0, kappa_h * std::sin(bank)};
  const auto fz = CalcNormalLoads<double>(p, {u, 0.0, 0.0, 0.0}, road, 0.0, 0.0);
  const double expected =
      p.chassis.mass * (kGravity * std::cos(bank) + u * u * kappa_h * std::sin(bank)) +
      0.5 * p.aero.air_density * p.aero.downforce_area * u * u;
  EXPECT_NEAR(Sum(fz), expected, 1e-9 * expected);
  // Gravity: g sin(theta) to the left (the right edge is up), g cos(theta) into the road.
  const auto g = CalcGravity<double>(road, 0.0);
  EXPECT_NEAR(g[0], 0.0, 1e-12);
  EXPECT_NEAR(g[1], kGravity * std::sin(bank), 1e-12);
  EXPECT_NEAR(g[2], kGravity * std::cos(bank), 1e-12);
  // Uphill grade pulls backwards; a heading error turns the components.
  const auto climb = CalcGravity<double>({0.0, 0.05, 0.0}, 0.0);
  EXPECT_NEAR(climb[0], -kGravity * std::sin(0.05), 1e-12);
  const auto turned = CalcGravity<double>(road, 0.1);
  EXPECT_NEAR(std::hypot(turned[0], turned[1]), std::hypot(g[0], g[1]), 1e-12);
  EXPECT_NEAR(turned[0], kGravity * std::sin(bank) * std::sin(0.1), 1e-12);
}

// Rigid-body kinematics at the contact points, front wheels turned by the steer angle.
TEST(VehicleModelTest, WheelKinematicsByHand) {
  const VehicleParams& p = Gen7();
  const ChassisMotion<double> m{30.0, 0.5, 0.2, 0.05};
  const auto w = CalcWheelKinematics(p, m);
  const double a = p.chassis.a(), b = p.chassis.b(), tf = p.chassis.track_front;
  // Front left at (a, tf/2): body velocity (u - r tf/2, v + r a), turned by -steer.
  const double vx = 30.0 - 0.2 * tf / 2, vy = 0.5 + 0.2 * a;
  EXPECT_NEAR(w[kFl].vx, vx * std::cos(0.05) + vy * std::sin(0.05), 1e-12);
  EXPECT_NEAR(w[kFl].vy, -vx * std::sin(0.05) + vy * std::cos(0.05), 1e-12);
  EXPECT_NEAR(w[kFl].slip_angle, std::atan(w[kFl].vy / w[kFl].vx), 1e-12);
  // Rear right at (-b, -tr/2), not steered.
  EXPECT_NEAR(w[kRr].vx, 30.0 + 0.2 * p.chassis.track_rear / 2, 1e-12);
  EXPECT_NEAR(w[kRr].vy, 0.5 - 0.2 * b, 1e-12);
}

// Steady cornering on a circle: solve steer, lateral speed and the rear slip ratio so that the
// chassis accelerations vanish (the loads iterated to match the forces), then check the force
// balance of spec section 10: the tyres' lateral force is m u^2 kappa_g - m g sin(theta).
struct SteadyState {
  double steer, v, kappa_rear;
  std::array<CornerForces<double>, 4> forces;
  std::array<double, 4> fz;
};

SteadyState SolveSteadyCornering(const VehicleParams& p, double u, double radius, double bank) {
  const double kappa_h = 1.0 / radius;
  const double kappa_g = kappa_h * std::cos(bank);
  const RoadGeometry<double> road{bank, 0.0, kappa_h * std::sin(bank)};
  const double r = u * kappa_g;
  SteadyState s{0.02, 0.0, 0.0, {}, CalcNormalLoads<double>(p, {u, 0, r, 0}, road, 0, 0)};
  // Accelerations at (steer, v, rear slip ratio), with the loads iterated to match the forces.
  const auto accelerations = [&](const Eigen::Vector3d& x, bool keep) {
    const ChassisMotion<double> m{u, x[1], r, x[0]};
    const auto wheels = CalcWheelKinematics(p, m);
    std::array<double, 4> fz = s.fz;
    std::array<CornerForces<double>, 4> forces;
    for (int it = 0; it < 100; ++it) {
      std::array<CornerState<double>, 4> corners;
      for (int i = 0; i < 4; ++i) corners[i] = {fz[i], i >= 2 ? x[2] : 0.0, 330.0, 1.0};
      forces = CalcCornerForces(p, m, wheels, corners);
      double fx = 0, fy = 0;
      for (const auto& f : forces) {
        fx += f.fx_body;
        fy += f.fy_body;
      }
      const auto next = CalcNormalLoads(p, m, road, fx, fy);
      double change = 0.0;
      for (int i = 0; i < 4; ++i) change = std::max(change, std::abs(next[i] - fz[i]));
      fz = next;
      if (change < 1e-10) break;
    }
    if (keep) {
      s.fz = fz;
      s.forces = forces;
    }
    const auto a = CalcChassisAccelerations(p, m, road, 0.0, forces);
    return Eigen::Vector3d(a.du, a.dv, a.dr);
  };
  // Damped Newton (steps limited to 0.02 rad, 0.5 m/s, 0.01 slip; halved until the residual
  // falls), loads refreshed from the forces at every iterate.
  Eigen::Vector3d x(p.chassis.wheelbase / radius, 0.0, 0.0);
  for (int it = 0; it < 200; ++it) {
    const Eigen::Vector3d f = accelerations(x, true);
    if (f.norm() < 1e-11) break;
    Eigen::Matrix3d jac;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d h = x;
      h[j] += 1e-7;
      jac.col(j) = (accelerations(h, false) - f) / 1e-7;
    }
    Eigen::Vector3d step = -jac.partialPivLu().solve(f);
    const Eigen::Vector3d limit(0.02, 0.5, 0.01);
    const double scale = std::max(1.0, (step.cwiseAbs().cwiseQuotient(limit)).maxCoeff());
    step /= scale;
    for (int k = 0; k < 20 && accelerations(x + step, false).norm() >= f.norm(); ++k) step *= 0.5;
    x += step;
  }
  accelerations(x, true);
  EXPECT_LT(accelerations(x, false).norm(), 1e-9);
  s.steer = x[0];
  s.v = x[1];
  s.kappa_rear = x[2];
  return s;
}

double SumFy(const SteadyState& s) {
  double fy = 0.0;
  for (const auto& f : s.forces) fy += f.fy_body;
  return fy;
}

TEST(VehicleModelTest, FlatCircleLateralForcesBalanceCentripetal) {
  const VehicleParams& p = Gen7();
  const double u = 30.0, radius = 120.0;  // 0.76 g, inside the tyres' grip
  const SteadyState s = SolveSteadyCornering(p, u, radius, 0.0);
  // m u r with r = u / R: the lateral speed's own centripetal share, m (dv + u r), is zero at
  // steady state, so the tyres carry m u^2 / R exactly.
  EXPECT_NEAR(SumFy(s), p.chassis.mass * u * u / radius, 1e-6 * p.chassis.mass);
  EXPECT_GT(s.steer, p.chassis.wheelbase / radius * 0.5);  // some steer to the left
}

TEST(VehicleModelTest, BankedCircleTyresMakeWhatBankingDoesNot) {
  // 70 m/s on Darlington's banking is near the grip: the tyres at their settled hot pressures
  // (the .tir's NOMPRES), as they are there in a run; at the cold set they have 2-4% less.
  VehicleParams p = Gen7();
  for (CornerSetup& c : p.corners) {
    c.pressure = std::get<tyre::MagicFormulaModel<double>>(c.forces.params).params.NOMPRES;
  }
  const double u = 70.0, radius = 183.0, bank = DegToRad(25.0);
  const SteadyState s = SolveSteadyCornering(p, u, radius, bank);
  const double needed =
      p.chassis.mass * (u * u * std::cos(bank) / radius - kGravity * std::sin(bank));
  EXPECT_NEAR(SumFy(s), needed, 1e-6 * p.chassis.mass);
  double fz = 0.0;
  for (double f : s.fz) fz += f;
  // The path's speed is (u, v): the normal curvature loads with u^2 + v^2.
  const double normal =
      p.chassis.mass * (kGravity * std::cos(bank) + (u * u + s.v * s.v) * std::sin(bank) / radius) +
      0.5 * p.aero.air_density * p.aero.downforce_area * u * u;
  EXPECT_NEAR(fz, normal, 1e-6 * normal);
}

// Jet derivatives of the loads and accelerations against central differences.
TEST(VehicleModelTest, DerivativesMatchCentralDifferences) {
  const VehicleParams& p = Gen7();
  const RoadGeometry<Jet2> road{Jet2(0.3), Jet2(0.01), Jet2(0.002)};
  const auto loads = [&](double u, double fy) {
    ChassisMotion<Jet2> m{Jet2(u, 0), Jet2(0.3), Jet2(0.2), Jet2(0.01)};
    return CalcNormalLoads<Jet2>(p, m, road, Jet2(1000.0), Jet2(fy, 1));
  };
  const auto value = [&](double u, double fy) {
    const RoadGeometry<double> r{0.3, 0.01, 0.002};
    return CalcNormalLoads<double>(p, {u, 0.3, 0.2, 0.01}, r, 1000.0, fy);
  };
  const auto jet = loads(60.0, 9000.0);
  const double h = 1e-4;
  for (int i = 0; i < 4; ++i) {
    const double du = (value(60.0 + h, 9000.0)[i] - value(60.0 - h, 9000.0)[i]) / (2 * h);
    const double dfy = (value(60.0, 9000.0 + h)[i] - value(60.0, 9000.0 - h)[i]) / (2 * h);
    EXPECT_NEAR(jet[i].v[0], du, 1e-6 * (1 + std::abs(du)));
    EXPECT_NEAR(jet[i].v[1], dfy, 1e-6);
    EXPECT_NEAR(jet[i].a, value(60.0, 9000.0)[i], 1e-9 * jet[i].a);
  }
  // Tyre forces through the steer angle: d(sum Fy)/d(steer) by Jets and by differences.
  const auto sum_fy = [&](auto steer) {
    using T = std::decay_t<decltype(steer)>;
    ChassisMotion<T> m{T(60.0), T(0.0), T(0.3), steer};
    const auto wheels = CalcWheelKinematics(p, m);
    std::array<CornerState<T>, 4> c;
    for (auto& x : c) x = {T(5000.0), T(0.01), T(350.0), T(1.0)};
    const auto f = CalcCornerForces(p, m, wheels, c);
    T s(0.0);
    for (const auto& x : f) s += x.fy_body;
    return s;
  };
  const Jet2 d = sum_fy(Jet2(0.02, 0));
  const double fd = (sum_fy(0.02 + 1e-6) - sum_fy(0.02 - 1e-6)) / 2e-6;
  EXPECT_NEAR(d.v[0], fd, 1e-5 * std::abs(fd));
}

}  // namespace
}  // namespace hotlap::vehicle
