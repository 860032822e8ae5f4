#include "hotlap/tyre/air_properties.h"

#include <cmath>

#include <gtest/gtest.h>

#include "test_util.h"

namespace hotlap::tyre {
namespace {

// The series form of k nu^-0.805 equals the direct power of the interpolated properties.
TEST(AirPropertiesTest, ConvectionFactorMatchesDirectPowerAcrossTheTable) {
  double worst = 0.0;
  for (double temp = 250.0; temp <= 600.0; temp += 0.137) {
    const double direct = AirConductivity(temp) * std::pow(AirKinematicViscosity(temp), -0.805);
    worst = std::max(worst, std::abs(AirConvectionFactor(temp) / direct - 1.0));
  }
  EXPECT_LT(worst, 1e-10);
}

TEST(AirPropertiesTest, ConvectionFactorIsExactAtKnotsAndClampedOutside) {
  for (size_t i = 0; i < internal::kAirTableTempK.size(); ++i) {
    const double direct =
        internal::kAirConductivity[i] * std::pow(internal::kAirKinematicViscosity[i], -0.805);
    EXPECT_NEAR(AirConvectionFactor(internal::kAirTableTempK[i]), direct, 1e-10 * direct);
  }
  EXPECT_EQ(AirConvectionFactor(200.0), AirConvectionFactor(273.15));
  EXPECT_EQ(AirConvectionFactor(900.0), AirConvectionFactor(573.15));
}

TEST(AirPropertiesTest, ConvectionFactorDerivativeMatchesDifferences) {
  for (double temp : {280.0, 321.7, 400.0, 500.0}) {
    const Jet2 x(temp, 0);
    const double h = 1e-4;  // well inside one table interval
    const double numeric =
        (AirConvectionFactor(temp + h) - AirConvectionFactor(temp - h)) / (2 * h);
    test::ExpectNearDerivative(AirConvectionFactor(x).v[0], numeric, AirConvectionFactor(temp),
                               "dF/dT at " + std::to_string(temp));
  }
}

// Air conducts better and is more viscous when hot; the factor k nu^-0.805 falls with T.
TEST(AirPropertiesTest, PropertiesRiseAndFactorFallsWithTemperature) {
  EXPECT_GT(AirConductivity(350.0), AirConductivity(300.0));
  EXPECT_GT(AirKinematicViscosity(350.0), AirKinematicViscosity(300.0));
  EXPECT_LT(AirConvectionFactor(350.0), AirConvectionFactor(300.0));
}

}  // namespace
}  // namespace hotlap::tyre
