#include "hotlap/tyre/temperature_cubic.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "hotlap/common/scalar.h"
#include "hotlap/common/units.h"
#include "hotlap/tyre/tyre_params_io.h"
#include "test_util.h"

namespace hotlap::tyre {
namespace {

using test::Contains;

// A spec written in degC, as the files are.
TemperatureCubicSpec SpecC(CubicKind kind, double opt, double low, double low_value, double high,
                           double high_value, double valid_min, double valid_max) {
  TemperatureCubicSpec s;
  s.kind = kind;
  s.optimal_temp = CelsiusToKelvin(opt);
  s.low_temp = CelsiusToKelvin(low);
  s.low_value = low_value;
  s.high_temp = CelsiusToKelvin(high);
  s.high_value = high_value;
  s.valid_min_temp = CelsiusToKelvin(valid_min);
  s.valid_max_temp = CelsiusToKelvin(valid_max);
  return s;
}

// Spec section 1 defaults, as shipped in data/cars/gen7/tyres/compound.yaml.
TemperatureCubicSpec DefaultGrip() {
  return SpecC(CubicKind::kGripMaximum, 98, 60, 0.90, 140, 0.90, 0, 200);
}
TemperatureCubicSpec DefaultWear() {
  return SpecC(CubicKind::kWearMinimum, 95, 60, 1.5, 140, 1.5, 0, 200);
}
// One more, chosen here: an asymmetric grip cubic on a wider range (positive there: its minimum,
// at -20 degC, is about 0.14).
TemperatureCubicSpec AsymmetricGrip() {
  return SpecC(CubicKind::kGripMaximum, 90, 40, 0.80, 130, 0.85, -20, 180);
}

// Message of the InputError that Create throws for `spec`; fails the test if none is thrown.
std::string CreateError(const TemperatureCubicSpec& spec) {
  try {
    TemperatureCubic::Create(spec, "cubic.yaml: grip_cubic");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

class ShippedAndChosenCubics : public ::testing::TestWithParam<int> {
 protected:
  TemperatureCubic Cubic() const {
    switch (GetParam()) {
      case 0:
        return compound_.grip;
      case 1:
        return compound_.wear_rate;
      default:
        return TemperatureCubic::Create(AsymmetricGrip(), "test");
    }
  }
  const TyreCompound compound_ = LoadTyreCompound(test::Gen7Dir() / "tyres" / "compound.yaml");
};

// The four defining conditions of (000:6). The values are O(1) and the system is solved in the
// shifted variable, so only rounding (~1e-16) separates them from the targets: 1e-12 is generous.
TEST_P(ShippedAndChosenCubics, MeetsItsFourConditions) {
  const TemperatureCubic g = Cubic();
  const TemperatureCubicSpec& s = g.spec();
  EXPECT_NEAR(g.Evaluate(s.optimal_temp), 1.0, 1e-12);
  EXPECT_NEAR(g.Slope(s.optimal_temp), 0.0, 1e-12);
  EXPECT_NEAR(g.Evaluate(s.low_temp), s.low_value, 1e-12);
  EXPECT_NEAR(g.Evaluate(s.high_temp), s.high_value, 1e-12);
  // In the shifted variable the conditions read d = 1, c = 0.
  EXPECT_NEAR(g.d(), 1.0, 1e-12);
  EXPECT_NEAR(g.c(), 0.0, 1e-12);
}

// Forward-mode AD through Evaluate gives the analytic slope, and the analytic slope matches a
// central difference (step 1e-3 K: truncation ~ a h^2 ~ 1e-12, rounding ~ 1e-16/1e-3 = 1e-13).
TEST_P(ShippedAndChosenCubics, JetDerivativeMatchesSlope) {
  const TemperatureCubic g = Cubic();
  const TemperatureCubicSpec& s = g.spec();
  for (double t = s.valid_min_temp + 1.0; t < s.valid_max_temp; t += 7.3) {
    const Jet2 jt(t, 0);
    const Jet2 value = g.Evaluate(jt);
    EXPECT_DOUBLE_EQ(value.a, g.Evaluate(t)) << "at " << t << " K";
    EXPECT_NEAR(value.v[0], g.Slope(t), 1e-14) << "at " << t << " K";
    EXPECT_EQ(value.v[1], 0.0);
    const double h = 1e-3;
    const double fd = (g.Evaluate(t + h) - g.Evaluate(t - h)) / (2 * h);
    EXPECT_NEAR(fd, g.Slope(t), 1e-10) << "at " << t << " K";
  }
}

// Outside [T_min, T_max] the value is held at the end value and the slope is zero.
TEST_P(ShippedAndChosenCubics, ClampsOutsideTheValidRange) {
  const TemperatureCubic g = Cubic();
  const TemperatureCubicSpec& s = g.spec();
  const double at_min = g.Evaluate(s.valid_min_temp);
  const double at_max = g.Evaluate(s.valid_max_temp);
  // The end values differ from their neighbours inside, so clamping is observable.
  EXPECT_NE(at_min, g.Evaluate(s.valid_min_temp + 5.0));
  EXPECT_NE(at_max, g.Evaluate(s.valid_max_temp - 5.0));
  for (double outside : {1.0, 30.0, 500.0}) {
    EXPECT_EQ(g.Evaluate(s.valid_min_temp - outside), at_min);
    EXPECT_EQ(g.Evaluate(s.valid_max_temp + outside), at_max);
    EXPECT_EQ(g.Slope(s.valid_min_temp - outside), 0.0);
    EXPECT_EQ(g.Slope(s.valid_max_temp + outside), 0.0);
    const Jet2 below = g.Evaluate(Jet2(s.valid_min_temp - outside, 0));
    const Jet2 above = g.Evaluate(Jet2(s.valid_max_temp + outside, 1));
    EXPECT_EQ(below.a, at_min);
    EXPECT_EQ(above.a, at_max);
    EXPECT_EQ(below.v[0], 0.0);
    EXPECT_EQ(above.v[1], 0.0);
  }
}

// Positive on the whole range and 1 at the optimum as the extremum of the right kind.
TEST_P(ShippedAndChosenCubics, OptimumIsTheExtremumAndCubicIsPositive) {
  const TemperatureCubic g = Cubic();
  const TemperatureCubicSpec& s = g.spec();
  for (double t = s.valid_min_temp; t <= s.valid_max_temp; t += 0.5) {
    const double v = g.Evaluate(t);
    EXPECT_GT(v, 0.0) << "at " << t << " K";
    if (s.kind == CubicKind::kGripMaximum) {
      EXPECT_LE(v, 1.0 + 1e-12) << "at " << t << " K";
    } else {
      EXPECT_GE(v, 1.0 - 1e-12) << "at " << t << " K";
    }
  }
}

std::string CubicName(const ::testing::TestParamInfo<int>& info) {
  switch (info.param) {
    case 0:
      return "ShippedGrip";
    case 1:
      return "ShippedWear";
    default:
      return "AsymmetricGrip";
  }
}
INSTANTIATE_TEST_SUITE_P(Cubics, ShippedAndChosenCubics, ::testing::Values(0, 1, 2), CubicName);

TEST(TemperatureCubicTest, ShippedFileHoldsTheSpecDefaults) {
  const TyreCompound c = LoadTyreCompound(test::Gen7Dir() / "tyres" / "compound.yaml");
  const TemperatureCubicSpec g = c.grip.spec();
  const TemperatureCubicSpec w = c.wear_rate.spec();
  const TemperatureCubicSpec dg = DefaultGrip();
  const TemperatureCubicSpec dw = DefaultWear();
  EXPECT_EQ(g.kind, CubicKind::kGripMaximum);
  EXPECT_EQ(w.kind, CubicKind::kWearMinimum);
  // degC -> K adds 273.15: exact to rounding.
  EXPECT_NEAR(g.optimal_temp, dg.optimal_temp, 1e-12);
  EXPECT_NEAR(g.low_temp, dg.low_temp, 1e-12);
  EXPECT_NEAR(g.high_temp, dg.high_temp, 1e-12);
  EXPECT_EQ(g.low_value, 0.90);
  EXPECT_EQ(g.high_value, 0.90);
  EXPECT_NEAR(w.optimal_temp, dw.optimal_temp, 1e-12);
  EXPECT_EQ(w.low_value, 1.5);
  EXPECT_EQ(w.high_value, 1.5);
  EXPECT_NEAR(w.valid_min_temp, 273.15, 1e-12);
  EXPECT_NEAR(w.valid_max_temp, 473.15, 1e-12);
}

// The coefficients of the symmetric-valued default grip cubic solved by hand in x = T - T_opt:
// g = a x^3 + b x^2 + 1 with a xl^3 + b xl^2 = g_low - 1 and a xh^3 + b xh^2 = g_high - 1,
// xl = -38 K, xh = 42 K (Cramer's rule). Tolerances: relative 1e-12 of each coefficient.
TEST(TemperatureCubicTest, CoefficientsMatchHandSolution) {
  const TemperatureCubic g = TemperatureCubic::Create(DefaultGrip(), "test");
  const double xl = -38.0, xh = 42.0, rl = -0.1, rh = -0.1;
  const double det = xl * xl * xl * xh * xh - xh * xh * xh * xl * xl;
  const double a = (rl * xh * xh - rh * xl * xl) / det;
  const double b = (xl * xl * xl * rh - xh * xh * xh * rl) / det;
  EXPECT_NEAR(g.a(), a, 1e-9 * std::abs(a));  // xl, xh carry ~1e-13 K of 273.15 rounding
  EXPECT_NEAR(g.b(), b, 1e-9 * std::abs(b));
  EXPECT_LT(g.b(), 0.0);  // a maximum at T_opt
}

TEST(TemperatureCubicTest, RejectsTemperaturesThatAreNotDistinctAndOrdered) {
  const std::string phrase = "distinct and ordered";
  EXPECT_TRUE(Contains(  // low == optimal
      CreateError(SpecC(CubicKind::kGripMaximum, 98, 98, 0.9, 140, 0.9, 0, 200)), phrase));
  EXPECT_TRUE(Contains(  // high == optimal
      CreateError(SpecC(CubicKind::kGripMaximum, 98, 60, 0.9, 98, 0.9, 0, 200)), phrase));
  EXPECT_TRUE(Contains(  // low above optimal
      CreateError(SpecC(CubicKind::kGripMaximum, 98, 110, 0.9, 140, 0.9, 0, 200)), phrase));
  EXPECT_TRUE(Contains(  // low and high swapped
      CreateError(SpecC(CubicKind::kWearMinimum, 95, 140, 1.5, 60, 1.5, 0, 200)), phrase));
  // The message starts with what the caller passed, so the file and field are named.
  EXPECT_TRUE(Contains(CreateError(SpecC(CubicKind::kGripMaximum, 98, 98, 0.9, 140, 0.9, 0, 200)),
                       "cubic.yaml: grip_cubic: "));
}

TEST(TemperatureCubicTest, RejectsPointsOutsideTheValidRangeOrAnEmptyRange) {
  EXPECT_TRUE(Contains(CreateError(SpecC(CubicKind::kGripMaximum, 98, 60, 0.9, 140, 0.9, 70, 200)),
                       "inside the valid range"));
  EXPECT_TRUE(Contains(CreateError(SpecC(CubicKind::kGripMaximum, 98, 60, 0.9, 140, 0.9, 200, 0)),
                       "is empty"));
}

// low_value 0.1 on [0, 200] degC: the cubic reaches about -9 at 0 degC.
TEST(TemperatureCubicTest, RejectsACubicThatIsNotPositiveOnItsRange) {
  const std::string message =
      CreateError(SpecC(CubicKind::kGripMaximum, 98, 60, 0.1, 140, 0.9, 0, 200));
  EXPECT_TRUE(Contains(message, "not positive on its valid range"));
  EXPECT_TRUE(Contains(message, "cubic.yaml: grip_cubic"));
  // A wear cubic whose values dip below zero is rejected for the same reason.
  EXPECT_TRUE(Contains(CreateError(SpecC(CubicKind::kWearMinimum, 95, 60, 0.8, 140, 0.8, 0, 200)),
                       "not positive"));
}

TEST(TemperatureCubicTest, RejectsAGripCubicWhoseOptimumIsNotTheMaximum) {
  // Values above 1 at both ends: T_opt is a minimum.
  EXPECT_TRUE(Contains(CreateError(SpecC(CubicKind::kGripMaximum, 98, 60, 1.2, 140, 1.2, 0, 200)),
                       "not the grip maximum"));
  // Values below 1, T_opt a local maximum, but g = 1 - 1e-4 x^2 + 1e-6 x^3 climbs back to about
  // 1.29 at the top of the range (x = 120 K).
  EXPECT_TRUE(
      Contains(CreateError(SpecC(CubicKind::kGripMaximum, 90, 60, 0.883, 130, 0.904, 40, 210)),
               "not the grip maximum"));
}

TEST(TemperatureCubicTest, RejectsAWearCubicWhoseOptimumIsNotTheMinimum) {
  // Values below 1 (positive on the narrower range): T_opt is a maximum.
  EXPECT_TRUE(Contains(CreateError(SpecC(CubicKind::kWearMinimum, 95, 60, 0.9, 140, 0.9, 50, 150)),
                       "not the wear-rate minimum"));
  // Values above 1, T_opt a local minimum, but w = 1 + 1e-4 x^2 - 1e-6 x^3 falls to about 0.71
  // at the top of the range.
  EXPECT_TRUE(
      Contains(CreateError(SpecC(CubicKind::kWearMinimum, 90, 60, 1.117, 130, 1.096, 40, 210)),
               "not the wear-rate minimum"));
}

// A grip spec used as a wear spec (and the reverse) is rejected: the kind matters.
TEST(TemperatureCubicTest, KindIsChecked) {
  TemperatureCubicSpec grip_as_wear = DefaultGrip();
  grip_as_wear.kind = CubicKind::kWearMinimum;
  EXPECT_TRUE(Contains(CreateError(grip_as_wear), "not the wear-rate minimum"));
  TemperatureCubicSpec wear_as_grip = DefaultWear();
  wear_as_grip.kind = CubicKind::kGripMaximum;
  EXPECT_TRUE(Contains(CreateError(wear_as_grip), "not the grip maximum"));
}

}  // namespace
}  // namespace hotlap::tyre
