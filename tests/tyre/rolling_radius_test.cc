// The Magic Formula's effective rolling radius (tyre/rolling_radius.h): MF-Swift's form against
// hand-computed values, the pressure acting through the vertical stiffness, and its derivative in
// Jets against a central difference.

#include "hotlap/tyre/rolling_radius.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

namespace hotlap::tyre {
namespace {

MagicFormulaParams<double> Example() {
  MagicFormulaParams<double> p;
  p.UNLOADED_RADIUS = 0.36;
  p.Q_RE0 = 1.0;
  p.VERTICAL_STIFFNESS = 400e3;
  p.PFZ1 = 0.7;
  p.NOMPRES = 200e3;
  p.INFLPRES = 150e3;
  p.FNOMIN = 5000.0;
  p.LFZO = 1.0;
  p.BREFF = 8.4;
  p.DREFF = 0.27;
  p.FREFF = 0.07;
  return p;
}

TEST(RollingRadiusTest, HandComputedValues) {
  const MagicFormulaParams<double> p = Example();
  // At NOMPRES and FNOMIN: 0.36 - (5000 / 400e3) (0.27 atan(8.4) + 0.07).
  EXPECT_NEAR(CalcEffectiveRollingRadius(p, 5000.0, 200e3), 0.35422346600922594, 1e-15);
  // 30% over NOMPRES: C_z = 400e3 (1 + 0.7 * 0.3) = 484e3.
  EXPECT_NEAR(CalcEffectiveRollingRadius(p, 5000.0, 260e3), 0.3552260049663024, 1e-15);
  // 8 kN at 140 kPa: C_z = 400e3 (1 - 0.7 * 0.3) = 316e3, F_z / F_z0 = 1.6.
  EXPECT_NEAR(CalcEffectiveRollingRadius(p, 8000.0, 140e3), 0.35183445139630404, 1e-15);
  // Unloaded: the free radius; 0 pressure: the file's INFLPRES.
  EXPECT_DOUBLE_EQ(CalcEffectiveRollingRadius(p, 0.0, 260e3), 0.36);
  EXPECT_DOUBLE_EQ(CalcEffectiveRollingRadius(p, 5000.0, 0.0),
                   CalcEffectiveRollingRadius(p, 5000.0, 150e3));
}

TEST(RollingRadiusTest, ThePressureActsThroughTheVerticalStiffness) {
  MagicFormulaParams<double> p = Example();
  // Harder rolls larger, more load rolls smaller.
  EXPECT_GT(CalcRollingRadiusChange(p, 5000.0, 140e3, 200e3), 1e-3);
  EXPECT_LT(CalcEffectiveRollingRadius(p, 7000.0, 200e3),
            CalcEffectiveRollingRadius(p, 5000.0, 200e3));
  // The change is zero both ways without PFZ1, and antisymmetric in the two pressures.
  EXPECT_NEAR(CalcRollingRadiusChange(p, 5000.0, 140e3, 200e3),
              -CalcRollingRadiusChange(p, 5000.0, 200e3, 140e3), 1e-18);
  p.PFZ1 = 0.0;
  EXPECT_EQ(CalcRollingRadiusChange(p, 5000.0, 140e3, 200e3), 0.0);
}

TEST(RollingRadiusTest, JetDerivativeMatchesACentralDifference) {
  using J = ceres::Jet<double, 2>;
  const MagicFormulaParams<double> p = Example();
  const J r = CalcEffectiveRollingRadius(p.Cast<J>(), J(6000.0, 0), J(230e3, 1));
  const double hf = 1.0, hp = 10.0;
  const auto f = [&](double fz, double pr) { return CalcEffectiveRollingRadius(p, fz, pr); };
  EXPECT_NEAR(r.v[0], (f(6000.0 + hf, 230e3) - f(6000.0 - hf, 230e3)) / (2 * hf), 1e-12);
  EXPECT_NEAR(r.v[1], (f(6000.0, 230e3 + hp) - f(6000.0, 230e3 - hp)) / (2 * hp), 1e-13);
  EXPECT_LT(r.v[0], 0.0);
  EXPECT_GT(r.v[1], 0.0);
}

}  // namespace
}  // namespace hotlap::tyre
