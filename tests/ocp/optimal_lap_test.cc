// The optimal lap's options by name (ocp/optimal_lap.h).

#include "hotlap/ocp/optimal_lap.h"

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::ocp {
namespace {

TEST(ParseThermalStartTest, EveryNameAndNothingElse) {
  EXPECT_EQ(ParseThermalStart("racing"), ThermalStart::kRacing);
  EXPECT_EQ(ParseThermalStart("warm"), ThermalStart::kWarm);
  EXPECT_EQ(ParseThermalStart("car"), ThermalStart::kCar);
  EXPECT_EQ(ParseThermalStart("periodic"), ThermalStart::kPeriodic);
  EXPECT_PRED2(test::Contains, test::InputErrorOf([] { ParseThermalStart("Racing"); }),
               "'Racing': expected racing, warm, car or periodic");
  EXPECT_THROW(ParseThermalStart(""), InputError);
}

}  // namespace
}  // namespace hotlap::ocp
