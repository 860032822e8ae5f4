// The pieces both rig fits use: value groups (temperatures in kelvin, loads within 2 %) and the
// zero-slip slope of a curve, exact on a straight line and extrapolated on a saturating one.

#include "hotlap/ident/rig_fit_common.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap::ident::internal {
namespace {

TEST(RigFitCommon, GroupValuesAbsoluteAndRelative) {
  const ValueGroups t =
      GroupValues({300.0, 273.5, 301.0, 274.0, 305.0}, 1.5, GroupTolerance::kAbsolute);
  EXPECT_EQ(t.index, (std::vector<int>{1, 0, 1, 0, 2}));
  ASSERT_EQ(t.mean.size(), 3u);
  EXPECT_DOUBLE_EQ(t.mean[0], 273.75);
  EXPECT_DOUBLE_EQ(t.mean[1], 300.5);
  const ValueGroups f =
      GroupValues({4000.0, 2000.0, 4050.0, 2030.0}, kLoadGroupTolerance, GroupTolerance::kRelative);
  EXPECT_EQ(f.index, (std::vector<int>{1, 0, 1, 0}));
  EXPECT_DOUBLE_EQ(f.mean[1], 4025.0);
  EXPECT_TRUE(GroupValues({}, 1.0, GroupTolerance::kAbsolute).mean.empty());
}

TEST(RigFitCommon, ZeroSlipSlopeOfALineIsItsSlope) {
  const std::vector<double> x = {-0.02, -0.01, 0.0, 0.01, 0.02, 0.03};
  std::vector<double> y;
  for (double v : x) y.push_back(-1500.0 * v);
  EXPECT_NEAR(ZeroSlipSlope(x, y), -1500.0, 1e-9);
  // One level: its slope through the origin (least squares over both signs).
  EXPECT_NEAR(ZeroSlipSlope(std::vector<double>{-0.01, 0.01}, std::vector<double>{-9.0, 11.0}),
              1000.0, 1e-9);
  EXPECT_TRUE(std::isnan(ZeroSlipSlope(std::vector<double>{0.0}, std::vector<double>{1.0})));
}

TEST(RigFitCommon, ZeroSlipSlopeExtrapolatesASaturatingCurve) {
  // y = tanh(10 x): secants 9.967 at 0.01 and 9.869 at 0.02 extrapolate to 10.065 (true 10).
  std::vector<double> x, y;
  for (double v : {0.01, 0.02, 0.05, 0.1}) {
    x.push_back(v);
    y.push_back(std::tanh(10.0 * v));
  }
  const double slope = ZeroSlipSlope(x, y);
  EXPECT_GT(slope, std::tanh(0.1) / 0.01);
  EXPECT_NEAR(slope, 10.0, 0.1);
  // Antisymmetric in y, to the last bit.
  std::vector<double> minus_y;
  for (double v : y) minus_y.push_back(-v);
  EXPECT_EQ(ZeroSlipSlope(x, minus_y), -slope);
}

}  // namespace
}  // namespace hotlap::ident::internal
