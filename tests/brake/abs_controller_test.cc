// The ABS state machine, one transition at a time: every transition of the Bosch cycle
// (docs/abs.md's table), the pressure command of every state, the exit conditions, the
// a_w filter. The wheel is driven directly: each tick's wheel speed is chosen so that the
// controller measures the wheel acceleration and slip a test needs.

#include "hotlap/brake/abs_controller.h"

#include <gtest/gtest.h>

namespace {

using hotlap::brake::AbsCommand;
using hotlap::brake::AbsController;
using hotlap::brake::AbsControllerParams;
using hotlap::brake::AbsControllerState;
using hotlap::brake::AbsHoldPhase;
using hotlap::brake::AbsState;
using hotlap::brake::AbsStateName;

constexpr double kMPa = 1e6;
constexpr double kG = 9.80665;

// Round numbers, so that each threshold is easy to straddle.
AbsControllerParams TestParams() {
  AbsControllerParams p;
  p.period_s = 0.005;
  p.wheel_radius_m = 0.3;
  p.decel_threshold_mps2 = 1.6 * kG;
  p.accel_threshold_mps2 = 1.0 * kG;
  p.high_accel_threshold_mps2 = 5.0 * kG;
  p.accel_filter_time_constant_s = 0.0;  // a_w exactly as commanded below
  p.slip_threshold = 0.10;
  p.exit_speed_mps = 2.0;
  p.release_pressure_Pa = 0.05 * kMPa;
  p.decrease_rate_Pa_per_s = 100 * kMPa;
  p.fast_increase_rate_Pa_per_s = 60 * kMPa;
  p.step_increase_Pa = 0.4 * kMPa;
  p.step_increase_interval_s = 0.02;  // 4 ticks
  p.step_decrease_Pa = 0.3 * kMPa;
  p.step_decrease_interval_s = 0.015;  // 3 ticks
  p.first_hold_max_s = 0.05;           // 10 ticks
  p.low_grip_hold_s = 0.04;            // 8 ticks
  return p;
}

// Drives the controller (through the pure StepAbsController and its plain state) with a chosen
// wheel acceleration and slip each tick: the slip sets this tick's wheel speed, and the
// remembered previous wheel speed is set so that the difference gives a_w exactly.
class Wheel {
 public:
  explicit Wheel(AbsControllerParams params = TestParams()) : p_(params) {}

  AbsCommand Tick(double a_w, double lambda, double driver = 10 * kMPa, double vx = 20.0) {
    const double omega = vx * (1.0 - lambda) / p_.wheel_radius_m;
    if (s_.has_previous) s_.previous_wheel_speed = omega - a_w * p_.period_s / p_.wheel_radius_m;
    return hotlap::brake::StepAbsController(p_, s_, {vx, omega, driver});
  }

  const AbsControllerState& state() const { return s_; }

 private:
  AbsControllerParams p_;
  AbsControllerState s_;
};

// A controller taken through initialise into the driver's build-up.
Wheel Braking() {
  Wheel w;
  w.Tick(0.0, 0.0);  // initialise: no a_w yet
  EXPECT_EQ(w.Tick(-3.0, 0.01).state, AbsState::kIncrease);
  return w;
}

// ... and on into the first cycle's release.
Wheel Releasing() {
  Wheel w = Braking();
  EXPECT_EQ(w.Tick(-20.0, 0.05).state, AbsState::kHold);
  EXPECT_EQ(w.Tick(-20.0, 0.12).state, AbsState::kDecrease);
  return w;
}

// ... and holding after the release (phase 4).
Wheel HoldingAfterRelease() {
  Wheel w = Releasing();
  EXPECT_EQ(w.Tick(-5.0, 0.14).state, AbsState::kHold);
  EXPECT_EQ(w.state().hold_phase, AbsHoldPhase::kAfterDecrease);
  return w;
}

TEST(AbsStateNameTest, NamesEveryState) {
  EXPECT_EQ(AbsStateName(AbsState::kInitialise), "initialise");
  EXPECT_EQ(AbsStateName(AbsState::kHold), "hold");
  EXPECT_EQ(AbsStateName(AbsState::kIncrease), "increase");
  EXPECT_EQ(AbsStateName(AbsState::kFastIncrease), "fast_increase");
  EXPECT_EQ(AbsStateName(AbsState::kDecrease), "decrease");
  EXPECT_EQ(AbsStateName(AbsState::kStepIncrease), "step_increase");
  EXPECT_EQ(AbsStateName(AbsState::kStepDecrease), "step_decrease");
  EXPECT_EQ(AbsStateName(AbsState::kExit), "exit");
}

TEST(AbsControllerTest, InitialiseWaitsForASecondSampleThenFollowsTheDriver) {
  Wheel w;
  const AbsCommand first = w.Tick(0.0, 0.0, 3 * kMPa);
  EXPECT_EQ(first.state, AbsState::kInitialise);
  EXPECT_DOUBLE_EQ(first.pressure_target, 3 * kMPa);  // passed through
  const AbsCommand second = w.Tick(0.0, 0.0, 3.5 * kMPa);
  EXPECT_EQ(second.state, AbsState::kIncrease);
  EXPECT_DOUBLE_EQ(second.pressure_target, 3.5 * kMPa);
}

TEST(AbsControllerTest, InitialiseStaysWhileReleasedOrSlow) {
  Wheel w;
  w.Tick(0.0, 0.0, 0.0);
  EXPECT_EQ(w.Tick(0.0, 0.0, 0.0).state, AbsState::kInitialise);            // released
  EXPECT_EQ(w.Tick(0.0, 0.0, 5 * kMPa, 1.0).state, AbsState::kInitialise);  // below exit speed
  EXPECT_EQ(w.Tick(0.0, 0.0, 5 * kMPa, 20.0).state, AbsState::kIncrease);
}

TEST(AbsControllerTest, IncreaseHoldsOnMinusAInTheFirstCycle) {
  Wheel w = Braking();
  EXPECT_EQ(w.Tick(-15.0, 0.03).state, AbsState::kIncrease);  // -1.53 g: not yet
  const AbsCommand c = w.Tick(-16.0, 0.04);                   // -1.63 g
  EXPECT_EQ(c.state, AbsState::kHold);
  EXPECT_EQ(w.state().hold_phase, AbsHoldPhase::kFirst);
  EXPECT_EQ(w.state().cycles, 0);
  // Held at the last built pressure even as the driver presses harder.
  EXPECT_DOUBLE_EQ(w.Tick(-16.0, 0.05, 12 * kMPa).pressure_target, 10 * kMPa);
}

TEST(AbsControllerTest, IncreaseReleasesWhenSlipPassesLambda1) {
  Wheel w = Braking();
  const AbsCommand c = w.Tick(-5.0, 0.11);
  EXPECT_EQ(c.state, AbsState::kDecrease);
  EXPECT_EQ(w.state().cycles, 1);
  EXPECT_DOUBLE_EQ(c.pressure_target, 10 * kMPa - 100 * kMPa * 0.005);
}

TEST(AbsControllerTest, FirstHoldReleasesWhenSlipPassesLambda1) {
  Wheel w = Braking();
  w.Tick(-20.0, 0.05);
  EXPECT_EQ(w.Tick(-20.0, 0.09).state, AbsState::kHold);
  const AbsCommand c = w.Tick(-20.0, 0.101);
  EXPECT_EQ(c.state, AbsState::kDecrease);
  EXPECT_EQ(w.state().cycles, 1);
}

TEST(AbsControllerTest, FirstHoldTimesOutIntoStepIncreaseWhileSlipStaysLow) {
  Wheel w = Braking();
  w.Tick(-20.0, 0.05);
  for (int k = 0; k < 9; ++k) EXPECT_EQ(w.Tick(-2.0, 0.05).state, AbsState::kHold) << k;
  const AbsCommand c = w.Tick(-2.0, 0.05);  // 10 ticks = first_hold_max_s
  EXPECT_EQ(c.state, AbsState::kStepIncrease);
  EXPECT_EQ(w.state().cycles, 0);
}

TEST(AbsControllerTest, DecreaseReleasesAtItsRateUntilTheWheelStopsSlowingPastMinusA) {
  Wheel w = Releasing();
  const double after_first = w.state().pressure_command;
  EXPECT_DOUBLE_EQ(after_first, 10 * kMPa - 0.5 * kMPa);
  EXPECT_EQ(w.Tick(-16.0, 0.15).state, AbsState::kDecrease);
  EXPECT_DOUBLE_EQ(w.state().pressure_command, 9.0 * kMPa);
  const AbsCommand c = w.Tick(-15.0, 0.16);  // a_w above -a
  EXPECT_EQ(c.state, AbsState::kHold);
  EXPECT_EQ(w.state().hold_phase, AbsHoldPhase::kAfterDecrease);
  EXPECT_DOUBLE_EQ(c.pressure_target, 9.0 * kMPa);
}

TEST(AbsControllerTest, HoldAfterReleaseFastIncreasesAbovePlusBigA) {
  Wheel w = HoldingAfterRelease();
  const double held = w.state().pressure_command;
  EXPECT_EQ(w.Tick(40.0, 0.10).state, AbsState::kHold);  // above +a, below +A
  const AbsCommand c = w.Tick(50.0, 0.08);               // above +A (49.0)
  EXPECT_EQ(c.state, AbsState::kFastIncrease);
  EXPECT_DOUBLE_EQ(c.pressure_target, held + 60 * kMPa * 0.005);
}

TEST(AbsControllerTest, HoldAfterReleaseStepIncreasesOnceTheWheelHasReaccelerated) {
  Wheel w = HoldingAfterRelease();
  EXPECT_EQ(w.Tick(5.0, 0.12).state, AbsState::kHold);   // not yet above +a
  EXPECT_EQ(w.Tick(12.0, 0.10).state, AbsState::kHold);  // above +a: seen
  EXPECT_TRUE(w.state().seen_accel_above_a);
  EXPECT_EQ(w.Tick(10.0, 0.08).state, AbsState::kHold);  // still above +a (9.8)
  const double held = w.state().pressure_command;
  const AbsCommand c = w.Tick(9.0, 0.06);  // back below +a
  EXPECT_EQ(c.state, AbsState::kStepIncrease);
  EXPECT_DOUBLE_EQ(c.pressure_target, held + 0.4 * kMPa);  // the first step at once
}

TEST(AbsControllerTest, HoldAfterReleaseReleasesAgainWhenTheWheelKeepsSlipping) {
  Wheel w = HoldingAfterRelease();
  const AbsCommand c = w.Tick(-17.0, 0.2);
  EXPECT_EQ(c.state, AbsState::kDecrease);
  EXPECT_EQ(w.state().cycles, 1);  // the same cycle
}

TEST(AbsControllerTest, HoldAfterReleaseStepDecreasesOnLowGrip) {
  Wheel w = HoldingAfterRelease();
  for (int k = 0; k < 7; ++k) EXPECT_EQ(w.Tick(2.0, 0.2).state, AbsState::kHold) << k;
  const double held = w.state().pressure_command;
  const AbsCommand c = w.Tick(2.0, 0.2);  // low_grip_hold_s without +a, slip above lambda_1
  EXPECT_EQ(c.state, AbsState::kStepDecrease);
  EXPECT_DOUBLE_EQ(c.pressure_target, held - 0.3 * kMPa);
}

TEST(AbsControllerTest, HoldAfterReleaseStepIncreasesAfterTheTimerWhenSlipRecovered) {
  Wheel w = HoldingAfterRelease();
  for (int k = 0; k < 7; ++k) w.Tick(2.0, 0.05);
  EXPECT_EQ(w.Tick(2.0, 0.05).state, AbsState::kStepIncrease);
}

TEST(AbsControllerTest, FastIncreaseRisesUntilBelowPlusBigAThenHolds) {
  Wheel w = HoldingAfterRelease();
  const double held = w.state().pressure_command;
  w.Tick(60.0, 0.08, 12 * kMPa);
  EXPECT_EQ(w.Tick(55.0, 0.06, 12 * kMPa).state, AbsState::kFastIncrease);
  EXPECT_DOUBLE_EQ(w.state().pressure_command, held + 2 * 0.3 * kMPa);
  const AbsCommand c = w.Tick(30.0, 0.04, 12 * kMPa);
  EXPECT_EQ(c.state, AbsState::kHold);
  EXPECT_EQ(w.state().hold_phase, AbsHoldPhase::kAfterFastIncrease);
  EXPECT_DOUBLE_EQ(c.pressure_target, held + 2 * 0.3 * kMPa);
}

TEST(AbsControllerTest, HoldAfterFastIncreaseEndsBelowPlusAOrReturnsAbovePlusBigA) {
  Wheel w = HoldingAfterRelease();
  w.Tick(60.0, 0.08);
  w.Tick(30.0, 0.06);
  EXPECT_EQ(w.Tick(60.0, 0.05).state, AbsState::kFastIncrease);
  w.Tick(30.0, 0.04);
  EXPECT_EQ(w.Tick(20.0, 0.04).state, AbsState::kHold);
  EXPECT_EQ(w.Tick(5.0, 0.04).state, AbsState::kStepIncrease);
}

TEST(AbsControllerTest, StepIncreaseStepsEveryIntervalAndStartsTheNextCycleOnMinusA) {
  Wheel w = HoldingAfterRelease();
  w.Tick(12.0, 0.08);
  w.Tick(0.0, 0.06, 12 * kMPa);  // step increase, first step
  const double p0 = w.state().pressure_command;
  EXPECT_DOUBLE_EQ(w.Tick(0.0, 0.05, 12 * kMPa).pressure_target, p0);
  EXPECT_DOUBLE_EQ(w.Tick(0.0, 0.05, 12 * kMPa).pressure_target, p0);
  EXPECT_DOUBLE_EQ(w.Tick(0.0, 0.05, 12 * kMPa).pressure_target, p0);
  EXPECT_DOUBLE_EQ(w.Tick(0.0, 0.05, 12 * kMPa).pressure_target, p0 + 0.4 * kMPa);  // 4 ticks
  EXPECT_EQ(w.state().state, AbsState::kStepIncrease);
  const AbsCommand c = w.Tick(-16.0, 0.07);  // -a: the second cycle releases at once
  EXPECT_EQ(c.state, AbsState::kDecrease);
  EXPECT_EQ(w.state().cycles, 2);
}

TEST(AbsControllerTest, StepIncreaseFirstReturnsNearTheLastReleasePressure) {
  AbsControllerParams p = TestParams();
  p.reapply_fraction = 0.9;
  Wheel w(p);
  w.Tick(0.0, 0.0);
  w.Tick(-3.0, 0.01);
  w.Tick(-20.0, 0.05);
  w.Tick(-20.0, 0.12);  // the release begins from 10 MPa
  EXPECT_DOUBLE_EQ(w.state().release_pressure, 10 * kMPa);
  for (int k = 0; k < 10; ++k) w.Tick(-20.0, 0.2);  // 10 more ticks of release: 4.5 MPa
  w.Tick(12.0, 0.1);                                // hold
  w.Tick(12.0, 0.1);                                // +a seen
  const AbsCommand c = w.Tick(0.0, 0.05);           // below +a: step increase
  EXPECT_EQ(c.state, AbsState::kStepIncrease);
  EXPECT_DOUBLE_EQ(c.pressure_target, 9 * kMPa);  // 0.9 x 10 MPa, more than one 0.4 MPa step
}

TEST(AbsControllerTest, StepIncreaseReachingTheDriverFollowsTheDriverAndLaterReleasesAtOnce) {
  Wheel w = HoldingAfterRelease();
  w.Tick(12.0, 0.08);
  EXPECT_EQ(w.Tick(0.0, 0.06, 9.6 * kMPa).state, AbsState::kStepIncrease);
  AbsCommand c;
  for (int k = 0; k < 8 && c.state != AbsState::kIncrease; ++k) c = w.Tick(0.0, 0.03, 9.6 * kMPa);
  EXPECT_EQ(c.state, AbsState::kIncrease);
  EXPECT_DOUBLE_EQ(c.pressure_target, 9.6 * kMPa);
  // Not the first cycle any more: -a releases without the first hold.
  EXPECT_EQ(w.Tick(-20.0, 0.05, 9.6 * kMPa).state, AbsState::kDecrease);
  EXPECT_EQ(w.state().cycles, 2);
}

TEST(AbsControllerTest, StepDecreaseStepsUntilTheWheelReaccelerates) {
  Wheel w = HoldingAfterRelease();
  for (int k = 0; k < 8; ++k) w.Tick(2.0, 0.2);
  ASSERT_EQ(w.state().state, AbsState::kStepDecrease);
  const double p0 = w.state().pressure_command;
  w.Tick(2.0, 0.2);
  w.Tick(2.0, 0.2);
  EXPECT_DOUBLE_EQ(w.Tick(2.0, 0.2).pressure_target, p0 - 0.3 * kMPa);  // 3 ticks
  const AbsCommand c = w.Tick(12.0, 0.15);
  EXPECT_EQ(c.state, AbsState::kHold);
  EXPECT_EQ(w.state().hold_phase, AbsHoldPhase::kAfterDecrease);
  EXPECT_TRUE(w.state().seen_accel_above_a);
  EXPECT_EQ(w.Tick(5.0, 0.1).state, AbsState::kStepIncrease);  // then below +a
}

TEST(AbsControllerTest, StepDecreaseEndsWhenSlipRecovers) {
  Wheel w = HoldingAfterRelease();
  for (int k = 0; k < 8; ++k) w.Tick(2.0, 0.2);
  ASSERT_EQ(w.state().state, AbsState::kStepDecrease);
  EXPECT_EQ(w.Tick(2.0, 0.09).state, AbsState::kStepIncrease);
}

TEST(AbsControllerTest, EveryActiveStateExitsBelowTheExitSpeed) {
  Wheel w = HoldingAfterRelease();
  const AbsCommand c = w.Tick(0.0, 0.05, 10 * kMPa, 1.9);
  EXPECT_EQ(c.state, AbsState::kExit);
  EXPECT_DOUBLE_EQ(c.pressure_target, 10 * kMPa);  // the driver's pressure: the wheel may lock
}

TEST(AbsControllerTest, ExitsWhenTheDriverReleasesAndRestartsAfterwards) {
  Wheel w = Releasing();
  EXPECT_EQ(w.Tick(-20.0, 0.2, 0.0).state, AbsState::kExit);
  EXPECT_EQ(w.state().cycles, 1);
  // Released: a new braking event begins from initialise, cycles counted afresh.
  EXPECT_EQ(w.Tick(0.0, 0.0, 0.0).state, AbsState::kInitialise);
  EXPECT_EQ(w.state().cycles, 0);
  EXPECT_EQ(w.Tick(0.0, 0.0, 5 * kMPa).state, AbsState::kIncrease);
}

TEST(AbsControllerTest, ExitStaysWhilePressedAtLowSpeed) {
  Wheel w = Braking();
  EXPECT_EQ(w.Tick(0.0, 0.5, 10 * kMPa, 1.0).state, AbsState::kExit);
  EXPECT_EQ(w.Tick(0.0, 0.5, 10 * kMPa, 1.0).state, AbsState::kExit);
  EXPECT_EQ(w.Tick(0.0, 0.5, 10 * kMPa, 3.0).state, AbsState::kExit);  // no re-entry while pressed
}

TEST(AbsControllerTest, CommandStaysBetweenZeroAndTheDriversPressure) {
  Wheel w = HoldingAfterRelease();
  // A long release at 100 MPa/s from 9.5 MPa reaches zero and stays there.
  w.Tick(-30.0, 0.3);
  for (int k = 0; k < 40; ++k) {
    const AbsCommand c = w.Tick(-30.0, 0.3);
    EXPECT_GE(c.pressure_target, 0.0);
  }
  EXPECT_DOUBLE_EQ(w.state().pressure_command, 0.0);
  // A driver easing off lowers even a held command.
  Wheel h = HoldingAfterRelease();
  EXPECT_DOUBLE_EQ(h.Tick(0.0, 0.12, 2 * kMPa).pressure_target, 2 * kMPa);
}

TEST(AbsControllerTest, FiltersTheWheelAcceleration) {
  AbsControllerParams p = TestParams();
  p.accel_filter_time_constant_s = 0.015;  // k = dt / (tau + dt) = 0.25
  Wheel w(p);
  w.Tick(0.0, 0.0);
  w.Tick(0.0, 0.0);
  EXPECT_DOUBLE_EQ(w.state().wheel_accel, 0.0);
  w.Tick(-40.0, 0.01);
  EXPECT_NEAR(w.state().wheel_accel, -10.0, 1e-9);
  w.Tick(-40.0, 0.02);
  EXPECT_NEAR(w.state().wheel_accel, -17.5, 1e-9);
  // The filtered value, not the raw one, is what crosses -a.
  EXPECT_EQ(w.state().state, AbsState::kHold);
}

TEST(AbsControllerTest, TheObjectIsThePureStepWithItsOwnStateAndResets) {
  AbsControllerParams p = TestParams();
  AbsController abs(p);
  AbsControllerState s;
  for (int k = 0; k < 30; ++k) {
    const double omega = 60.0 - 1.5 * k * k / 10.0;  // a wheel slowing ever faster
    const hotlap::brake::AbsSensors in{20.0, omega, 8 * kMPa};
    const AbsCommand a = abs.Step(in);
    const AbsCommand b = hotlap::brake::StepAbsController(p, s, in);
    EXPECT_EQ(a.state, b.state) << k;
    EXPECT_DOUBLE_EQ(a.pressure_target, b.pressure_target) << k;
  }
  EXPECT_GT(abs.state().cycles, 0);
  abs.Reset();
  EXPECT_EQ(abs.state().state, AbsState::kInitialise);
  EXPECT_EQ(abs.state().cycles, 0);
  EXPECT_FALSE(abs.state().has_previous);
}

}  // namespace
