#include "hotlap/sim/qss_slips.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"
#include "vehicle/corner_forces.h"

namespace hotlap::sim {
namespace {

const vehicle::VehicleParams& Gen7Params() {
  static const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  return *car.vehicle;
}

const std::vector<vehicle::InvertibleTyre>& Tyres() {
  static const std::vector<vehicle::InvertibleTyre> tyres = [] {
    std::vector<vehicle::InvertibleTyre> t;
    for (Corner c : kAllCorners) t.emplace_back(Gen7Params().corner(c));
    return t;
  }();
  return tyres;
}

// The forces a corner's model makes at given slips (grip factor applied).
std::pair<double, double> Forces(Corner corner, const vehicle::TyreConditions& c, double kappa,
                                 double alpha) {
  return vehicle::testing::CornerForces(Gen7Params().corner(corner), c, kappa, alpha);
}

// A point mid-turn: the forces the four tyres make at a slip angle of about 2 degrees (the
// fronts braking a little, the rears on the spool driving), `load_scale` times the loads.
PointTargets MidTurn(double load_scale = 1.0) {
  PointTargets t;
  const std::array<double, 4> fz = {4500.0, 8000.0, 4200.0, 7800.0};
  const std::array<double, 4> vx = {60.6, 61.4, 60.6, 61.4};
  for (int k = 0; k < 4; ++k) {
    t.conditions[k] = {load_scale * fz[k], vx[k], CelsiusToKelvin(90.0), 0.95};
  }
  for (Corner c : {Corner::kFrontLeft, Corner::kFrontRight}) {
    const int k = CornerIndex(c);
    std::tie(t.fx[k], t.fy[k]) = Forces(c, t.conditions[k], -0.01, -0.035);
  }
  const double rl = Gen7Params().corner(Corner::kRearLeft).rolling_radius;
  const double rr = Gen7Params().corner(Corner::kRearRight).rolling_radius;
  const double omega = 1.01 * 61.0 / (0.5 * (rl + rr));
  for (const auto& [c, r] : {std::pair{Corner::kRearLeft, rl}, std::pair{Corner::kRearRight, rr}}) {
    const int k = CornerIndex(c);
    const double kappa = omega * r / t.conditions[k].vx - 1.0;
    std::tie(t.fx[k], t.fy[k]) = Forces(c, t.conditions[k], kappa, -0.03);
  }
  return t;
}

// `t` with every lateral force `lateral` times and every longitudinal one moved by `dx` N.
PointTargets Moved(PointTargets t, double lateral, double dx) {
  for (int k = 0; k < 4; ++k) {
    t.fy[k] *= lateral;
    t.fx[k] += dx;
  }
  return t;
}

void ExpectTargetsMet(const PointSlips& s, const PointTargets& t, double tolerance) {
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(s.wheels[k].fx, t.fx[k], tolerance) << k;
    EXPECT_NEAR(s.wheels[k].fy, t.fy[k], tolerance) << k;
  }
  EXPECT_NEAR(s.wheels[2].fy, t.fy[2], tolerance);
  EXPECT_NEAR(s.wheels[3].fy, t.fy[3], tolerance);
  EXPECT_NEAR(s.wheels[2].fx + s.wheels[3].fx, t.fx[2] + t.fx[3], tolerance);
}

// A profile later, the forces a few newtons off: the first-order update needs no tyre model and
// agrees with a solve at the new targets to well within the solve's tolerance.
TEST(QssSlipsTest, UpdateFollowsASolveToNearbyTargets) {
  const PointTargets before = MidTurn();
  PointSlips base = SolvePointSlips(Tyres(), before, {});
  ASSERT_TRUE(base.Reached());
  const PointTargets after = Moved(MidTurn(1.001), 1.003, -15.0);
  const PointSlips updated = UpdatePointSlips(Tyres(), after, base);
  for (int unit = 0; unit < 3; ++unit) EXPECT_FALSE(updated.solved[unit]) << unit;
  EXPECT_TRUE(updated.Reached());
  ExpectTargetsMet(updated, after, 1e-6);  // the targets, by construction
  const PointSlips solved = SolvePointSlips(Tyres(), after, base);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(updated.wheels[k].slip_angle, solved.wheels[k].slip_angle, 2e-5) << k;
    EXPECT_NEAR(updated.wheels[k].slip_ratio, solved.wheels[k].slip_ratio, 2e-5) << k;
  }
  // The update does not move its base: the next profile's update starts from the same solve.
  EXPECT_EQ(base.wheels[0].slip_angle, SolvePointSlips(Tyres(), before, {}).wheels[0].slip_angle);
}

// Further off (slips moving by several milliradians), each unit is checked against the force
// model or solved: the targets are met to the solve's tolerance, and the slips agree with a solve.
TEST(QssSlipsTest, LargerStepsAreCheckedAgainstTheModel) {
  PointSlips base = SolvePointSlips(Tyres(), MidTurn(), {});
  ASSERT_TRUE(base.Reached());
  const PointTargets after = Moved(MidTurn(1.01), 1.04, -200.0);
  const PointSlips updated = UpdatePointSlips(Tyres(), after, base);
  EXPECT_TRUE(updated.Reached());
  ExpectTargetsMet(updated, after, 1.0);
  const PointSlips solved = SolvePointSlips(Tyres(), after, base);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(updated.wheels[k].slip_angle, solved.wheels[k].slip_angle, 2e-4) << k;
    EXPECT_NEAR(updated.wheels[k].slip_ratio, solved.wheels[k].slip_ratio, 2e-4) << k;
  }
  EXPECT_LE(updated.force_deficit, 1.0);
}

// A base that missed its targets (beyond the tyres' envelope) is no base: the unit is solved, and
// the solve becomes the base the next update starts from.
TEST(QssSlipsTest, ABaseThatMissedItsTargetsIsSolvedAgain) {
  const PointTargets beyond = Moved(MidTurn(), 3.0, 0.0);
  PointSlips base = SolvePointSlips(Tyres(), beyond, {});
  ASSERT_FALSE(base.Reached());
  const PointTargets reachable = MidTurn();
  const PointSlips updated = UpdatePointSlips(Tyres(), reachable, base);
  EXPECT_TRUE(updated.Reached());
  ExpectTargetsMet(updated, reachable, 1.0);
  int solved_units = 0;
  for (int unit = 0; unit < 3; ++unit) {
    if (!updated.solved[unit]) continue;
    ++solved_units;
    EXPECT_TRUE(base.solved[unit] && base.reached[unit]) << unit;
  }
  EXPECT_GT(solved_units, 0);
  EXPECT_TRUE(base.Reached());  // the solves replaced the base's units that had missed
}

}  // namespace
}  // namespace hotlap::sim
