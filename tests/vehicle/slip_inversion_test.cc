#include "hotlap/vehicle/slip_inversion.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"
#include "hotlap/vehicle/car.h"
#include "hotlap/vehicle/tyre_capacity.h"
#include "test_util.h"
#include "vehicle/corner_forces.h"

namespace hotlap::vehicle {
namespace {

const VehicleParams& SlipGen7() {
  static const Car car = LoadCar(test::Gen7Dir() / "car.yaml");
  return *car.vehicle;
}

// The slip angle (< 0: a left-pushing force) where the pure side force peaks, by a fine scan.
double PeakSlipAngle(const CornerSetup& s, const TyreConditions& c) {
  double best = 0.0, best_alpha = 0.0;
  for (int i = 1; i <= 4000; ++i) {
    const double alpha = -0.4 * i / 4000.0;
    const double fy = testing::CornerForces(s, c, 0.0, alpha).second;
    if (fy > best) {
      best = fy;
      best_alpha = alpha;
    }
  }
  return best_alpha;
}

TyreConditions Conditions() {
  return {.fz = 6000.0, .vx = 70.0, .tread_temp = CelsiusToKelvin(90.0), .grip_factor = 0.93};
}

TEST(SlipInversionTest, FreeWheelRecoversTheSlipsThatMadeTheForces) {
  const CornerSetup& fl = SlipGen7().corner(Corner::kFrontLeft);
  const InvertibleTyre tyre(fl);
  const TyreConditions c = Conditions();
  for (const auto& [kappa, alpha] : {std::pair{0.03, -0.04}, std::pair{-0.05, 0.02},
                                     std::pair{0.0, -0.06}, std::pair{-0.02, -0.03}}) {
    const auto [fx, fy] = testing::CornerForces(fl, c, kappa, alpha);
    const FreeWheelSolution s = SolveFreeWheelSlips(tyre, c, fx, fy, {});
    ASSERT_TRUE(s.reached) << kappa << " " << alpha;
    EXPECT_NEAR(s.wheel.slip_ratio, kappa, 1e-4);
    EXPECT_NEAR(s.wheel.slip_angle, alpha, 1e-4);
    EXPECT_NEAR(s.wheel.fx, fx, 1.0);
    EXPECT_NEAR(s.wheel.fy, fy, 1.0);
  }
}

// A side force below the peak is made at two slip angles; the continuation from a previous
// solution beyond the peak (a sliding tyre) must come back to the one before it.
TEST(SlipInversionTest, FreeWheelLeavesThePostPeakBranch) {
  const CornerSetup& fl = SlipGen7().corner(Corner::kFrontLeft);
  const InvertibleTyre tyre(fl);
  const TyreConditions c = Conditions();
  const double peak_alpha = PeakSlipAngle(fl, c);
  ASSERT_LT(peak_alpha, -0.03);
  const double peak_fy = testing::CornerForces(fl, c, 0.0, peak_alpha).second;
  // A force 92% of the way up, and a guess beyond the peak that makes about it too.
  const double target = 0.92 * peak_fy;
  double post = peak_alpha;
  while (testing::CornerForces(fl, c, 0.0, post).second > target && post > -0.5) post -= 0.001;
  ASSERT_GT(post, -0.5) << "the side force does not fall to 92% of its peak by 0.5 rad";
  const FreeWheelSolution s =
      SolveFreeWheelSlips(tyre, c, 0.0, target, {.slip_ratio = 0.0, .slip_angle = post});
  ASSERT_TRUE(s.reached);
  EXPECT_GT(s.wheel.slip_angle, peak_alpha) << "stayed beyond the peak at " << s.wheel.slip_angle;
  EXPECT_NEAR(s.wheel.fy, target, 1.0);
}

TEST(SlipInversionTest, FreeWheelBeyondTheEnvelopeGivesTheClosestForce) {
  const CornerSetup& fl = SlipGen7().corner(Corner::kFrontLeft);
  const InvertibleTyre tyre(fl);
  const TyreConditions c = Conditions();
  const double peak_fy = testing::CornerForces(fl, c, 0.0, PeakSlipAngle(fl, c)).second;
  const FreeWheelSolution s = SolveFreeWheelSlips(tyre, c, 0.0, 1.3 * peak_fy, {});
  EXPECT_FALSE(s.reached);
  EXPECT_NEAR(s.wheel.fy, peak_fy, 0.01 * peak_fy);
}

TEST(SlipInversionTest, SpoolAxleRecoversOneWheelSpeedAndBothSlipAngles) {
  const CornerSetup& rl = SlipGen7().corner(Corner::kRearLeft);
  const CornerSetup& rr = SlipGen7().corner(Corner::kRearRight);
  const InvertibleTyre left(rl), right(rr);
  TyreConditions cl = Conditions(), cr = Conditions();
  cl.fz = 6500.0;
  cr.fz = 11000.0;
  cl.vx = 69.0;  // the left wheel runs on the inside of the turn
  cr.vx = 69.6;
  const double omega = 1.02 * 69.3 / (0.5 * (rl.rolling_radius + rr.rolling_radius));
  const double kl = omega * rl.rolling_radius / cl.vx - 1.0;
  const double kr = omega * rr.rolling_radius / cr.vx - 1.0;
  const auto [fxl, fyl] = testing::CornerForces(rl, cl, kl, -0.035);
  const auto [fxr, fyr] = testing::CornerForces(rr, cr, kr, -0.03);
  const SpoolAxleSolution s = SolveSpoolAxleSlips(left, right, cl, cr, fyl, fyr, fxl + fxr, {});
  ASSERT_TRUE(s.reached);
  EXPECT_NEAR(s.wheel_speed, omega, 1e-4 * omega);
  EXPECT_NEAR(s.wheels[0].slip_angle, -0.035, 1e-4);
  EXPECT_NEAR(s.wheels[1].slip_angle, -0.03, 1e-4);
  EXPECT_NEAR(s.wheels[0].slip_ratio, kl, 1e-4);
  EXPECT_NEAR(s.wheels[1].slip_ratio, kr, 1e-4);
  // The spool, not the targets, splits the axle's drive: the two wheels' Fx are the model's.
  EXPECT_NEAR(s.wheels[0].fx, fxl, 2.0);
  EXPECT_NEAR(s.wheels[1].fx, fxr, 2.0);
}

// A check from a solve's Jacobian: from the solve at nearby targets, chord steps meet the new
// targets to a tenth of the solve's tolerance, on the branch below the peak, and agree with a
// solve.
TEST(SlipInversionTest, FreeWheelRefineMeetsNearbyTargetsFromASolvesJacobian) {
  const CornerSetup& fl = SlipGen7().corner(Corner::kFrontLeft);
  const InvertibleTyre tyre(fl);
  const TyreConditions c = Conditions();
  const auto [fx0, fy0] = testing::CornerForces(fl, c, -0.02, -0.04);
  const FreeWheelSolution base = SolveFreeWheelSlips(tyre, c, fx0, fy0, {});
  ASSERT_TRUE(base.reached);
  const double fx = fx0 - 150.0, fy = 1.02 * fy0;  // a step of about 2e-3 rad
  WheelSlips refined = base.wheel;
  ASSERT_TRUE(RefineFreeWheelSlips(tyre, c, fx, fy, base.jacobian, &refined));
  EXPECT_NEAR(refined.fx, fx, 0.1);
  EXPECT_NEAR(refined.fy, fy, 0.1);
  const auto [check_fx, check_fy] =
      testing::CornerForces(fl, c, refined.slip_ratio, refined.slip_angle);
  EXPECT_NEAR(check_fx, refined.fx, 1e-9 * std::abs(fx));  // the forces it reports are its slips'
  EXPECT_NEAR(check_fy, refined.fy, 1e-9 * std::abs(fy));
  const FreeWheelSolution solved = SolveFreeWheelSlips(tyre, c, fx, fy, base.wheel);
  EXPECT_NEAR(refined.slip_angle, solved.wheel.slip_angle, 1e-4);
  EXPECT_NEAR(refined.slip_ratio, solved.wheel.slip_ratio, 1e-4);
  // Beyond the envelope no check passes: the caller solves.
  const double peak_fy = testing::CornerForces(fl, c, 0.0, PeakSlipAngle(fl, c)).second;
  WheelSlips beyond = base.wheel;
  EXPECT_FALSE(RefineFreeWheelSlips(tyre, c, 0.0, 1.3 * peak_fy, base.jacobian, &beyond));
}

TEST(SlipInversionTest, SpoolAxleRefineMeetsNearbyTargetsFromASolvesJacobian) {
  const CornerSetup& rl = SlipGen7().corner(Corner::kRearLeft);
  const CornerSetup& rr = SlipGen7().corner(Corner::kRearRight);
  const InvertibleTyre left(rl), right(rr);
  TyreConditions cl = Conditions(), cr = Conditions();
  cl.fz = 6500.0;
  cr.fz = 11000.0;
  cl.vx = 69.0;
  cr.vx = 69.6;
  const double omega = 1.02 * 69.3 / (0.5 * (rl.rolling_radius + rr.rolling_radius));
  const auto [fxl, fyl] =
      testing::CornerForces(rl, cl, omega * rl.rolling_radius / cl.vx - 1.0, -0.035);
  const auto [fxr, fyr] =
      testing::CornerForces(rr, cr, omega * rr.rolling_radius / cr.vx - 1.0, -0.03);
  const SpoolAxleSolution base = SolveSpoolAxleSlips(left, right, cl, cr, fyl, fyr, fxl + fxr, {});
  ASSERT_TRUE(base.reached);
  const double fy_left = 1.02 * fyl, fy_right = 1.015 * fyr, fx_total = fxl + fxr + 200.0;
  SpoolAxleSolution refined = base;
  ASSERT_TRUE(RefineSpoolAxleSlips(left, right, cl, cr, fy_left, fy_right, fx_total, base.jacobian,
                                   &refined));
  EXPECT_NEAR(refined.wheels[0].fy, fy_left, 0.2);
  EXPECT_NEAR(refined.wheels[1].fy, fy_right, 0.2);
  EXPECT_NEAR(refined.wheels[0].fx + refined.wheels[1].fx, fx_total, 0.2);
  const SpoolAxleSolution solved =
      SolveSpoolAxleSlips(left, right, cl, cr, fy_left, fy_right, fx_total, base);
  ASSERT_TRUE(solved.reached);
  EXPECT_NEAR(refined.wheel_speed, solved.wheel_speed, 1e-4 * omega);
  EXPECT_NEAR(refined.wheels[0].slip_angle, solved.wheels[0].slip_angle, 1e-4);
  EXPECT_NEAR(refined.wheels[1].slip_angle, solved.wheels[1].slip_angle, 1e-4);
}

}  // namespace
}  // namespace hotlap::vehicle
