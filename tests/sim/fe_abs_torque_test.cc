// The FE ABS stop's brake torque law (sim::FeAbsTorque): driven by a synthetic wheel that locks
// as the torque rises, the controller cycles; saved mid-run and loaded into a new law, it gives
// the same torques bit for bit; a damaged or mismatched saved law is refused.

#include "hotlap/sim/fe_abs_torque.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/sim/abs_config.h"

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

TEST(FeAbsTorque, SavedAndLoadedLawContinuesBitForBit) {
  const AbsConfig config = LoadAbsConfig(DefaultAbsConfigPath());
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
  ASSERT_GT(straight.state().cycles, 0) << "the synthetic wheel should make the ABS cycle";
  ASSERT_FALSE(straight.cycle_starts().empty());

  FeAbsTorque restored(config, Params(config));
  fe::BinaryReader r(saved.bytes(), "memory");
  restored.Load(r);
  r.ExpectEnd();
  wheel = wheel_at_save;
  for (int k = save_at; k < steps; ++k) {
    const double torque = restored(k * kDt, wheel.vx, wheel.spin);
    ASSERT_EQ(torque, torques[k]) << k;
    wheel.Step(torque);
  }
  EXPECT_EQ(restored.cycle_starts(), straight.cycle_starts());
  EXPECT_EQ(restored.abs_exit(), straight.abs_exit());
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

}  // namespace
}  // namespace hotlap::sim
