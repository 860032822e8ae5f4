// The FE ABS stop's brake torque law (sim::FeAbsTorque): driven by a synthetic wheel that locks
// as the torque rises, the controller cycles; saved mid-run and loaded into a new law, it gives
// the same torques bit for bit; a damaged or mismatched saved law is refused.

#include "hotlap/abs/fe_abs_torque.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/abs/abs_config.h"
#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::sim {
namespace {

constexpr double kDt = 1e-4, kRadius = 0.395;

// A quarter car at 11 m/s on a road whose friction peaks at 10% slip (load 4314 N, 440 kg,
// wheel inertia 1.2 kg m^2): the brake torque outgrows the road's, the wheel starts to lock and
// the controller releases, holds and applies again.
struct Wheel {
  double vx = 11.0, spin = 11.0 / kRadius;
  void Step(double torque) {
    const double slip = vx > 0.1 ? std::clamp((vx - kRadius * spin) / vx, 0.0, 1.0) : 0.0;
    const double fx = 4314.0 * std::sin(1.9 * std::atan(10.0 * slip));
    vx -= kDt * fx / 440.0;
    spin = std::max(0.0, spin + kDt * (fx * kRadius - torque) / 1.2);
  }
};

brake::AbsControllerParams Params(const AbsConfig& config) {
  brake::AbsControllerParams p = config.controller;
  p.wheel_radius_m = kRadius;
  return p;
}

// The torques of the law of `config` over the synthetic stop, saved at step `save_at` and
// continued from the save in a new law; both must agree bit for bit.
std::vector<double> CheckSavedAndLoaded(const AbsConfig& config) {
  FeAbsTorque straight(config, Params(config));
  Wheel wheel;
  std::vector<double> torques;
  fe::BinaryWriter saved;
  Wheel wheel_at_save;
  const int steps = 8000, save_at = 3000;
  for (int k = 0; k < steps; ++k) {
    if (k == save_at) {
      straight.Save(saved);
      wheel_at_save = wheel;
    }
    const double torque = straight(k * kDt, wheel.vx, wheel.spin);
    torques.push_back(torque);
    wheel.Step(torque);
  }
  EXPECT_GT(straight.state().cycles, 0) << "the synthetic wheel should make the ABS cycle";
  EXPECT_FALSE(straight.cycle_starts().empty());

  FeAbsTorque restored(config, Params(config));
  fe::BinaryReader r(saved.bytes(), "memory");
  restored.Load(r);
  r.ExpectEnd();
  wheel = wheel_at_save;
  for (int k = save_at; k < steps; ++k) {
    const double torque = restored(k * kDt, wheel.vx, wheel.spin);
    EXPECT_EQ(torque, torques[k]) << k;
    if (torque != torques[k]) break;
    wheel.Step(torque);
  }
  EXPECT_EQ(restored.cycle_starts(), straight.cycle_starts());
  EXPECT_EQ(restored.abs_exit(), straight.abs_exit());
  return torques;
}

TEST(FeAbsTorque, SavedAndLoadedLawContinuesBitForBit) {
  // The lumped tuning (no wheel-speed filter) and the FE tyre's (a notch, whose state the save
  // carries): the filter changes the torques.
  const std::vector<double> plain = CheckSavedAndLoaded(LoadAbsConfig(DefaultAbsConfigPath()));
  const std::vector<double> notched =
      CheckSavedAndLoaded(LoadAbsConfig(test::SourcePath("data/abs/fe_tyre.yaml")));
  EXPECT_NE(plain, notched);
}

TEST(FeAbsTorque, DamagedSavedLawIsRefusedAndChangesNothing) {
  const AbsConfig config = LoadAbsConfig(DefaultAbsConfigPath());
  FeAbsTorque law(config, Params(config));
  for (int k = 0; k < 500; ++k) law(k * kDt, 11.0, 11.0 / kRadius);
  fe::BinaryWriter w;
  law.Save(w);
  for (size_t len = 0; len < w.bytes().size(); len += 5) {
    FeAbsTorque target(config, Params(config));
    fe::BinaryReader r(std::string_view(w.bytes()).substr(0, len), "cut");
    EXPECT_THROW(target.Load(r), InputError) << len;
    EXPECT_EQ(target.state().ticks, 0);
  }
  std::string bad = w.bytes();
  bad[4] = 9;  // the controller state's enum
  FeAbsTorque target(config, Params(config));
  fe::BinaryReader r(bad, "bad");
  EXPECT_THROW(target.Load(r), InputError);
}

// The wheel-speed sensor (issue 27): a steady wheel with a 400 Hz spin ripple of 0.5 rad/s (two
// periods in the controller's 5 ms, as the contact's facets make it), stepped at 1e-5 s and at
// 0.37e-5 s: the controller reads the mean spin, within 5e-3 rad/s (1% of the ripple: the
// window's ends fall within a step of the ticks) of the steady spin and of each other, where
// the instantaneous spin at the ticks (phase 0.3 rad each time) is off by 0.15 rad/s.
TEST(FeAbsTorque, SensorReadsTheMeanSpinOverThePeriodWhateverTheStep) {
  const AbsConfig config = LoadAbsConfig(DefaultAbsConfigPath());
  const double w0 = 28.0, amp = 0.5, f = 400.0;
  std::vector<std::vector<double>> reads;
  for (const double dt : {1e-5, 0.37e-5}) {
    FeAbsTorque law(config, Params(config));
    std::vector<double> r;
    int ticks = 0;
    for (int k = 0; k * dt < 0.0975; ++k) {
      const double t = k * dt;
      const double phase = 2.0 * M_PI * f * t + 0.3;
      law(t, 11.0, w0 + amp * std::sin(phase));
      if (law.state().ticks != ticks) {
        ticks = law.state().ticks;
        r.push_back(law.state().previous_wheel_speed);
      }
    }
    ASSERT_GT(r.size(), 15u);
    for (size_t k = 1; k < r.size(); ++k) EXPECT_NEAR(r[k], w0, 5e-3) << k << " dt " << dt;
    reads.push_back(r);
  }
  ASSERT_EQ(reads[0].size(), reads[1].size());  // ticks at 0, 5, ..., 95 ms
  for (size_t k = 0; k < reads[0].size(); ++k) EXPECT_NEAR(reads[0][k], reads[1][k], 5e-3) << k;
}

}  // namespace
}  // namespace hotlap::sim
