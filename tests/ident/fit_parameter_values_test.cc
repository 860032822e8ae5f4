// FitParameterValues: a car's parameters under the keys the fits report them by, the brake's
// convection as the entries of P = L L'; every key a fit reports has a value.

#include "hotlap/ident/fit_parameter_values.h"

#include <gtest/gtest.h>

#include "hotlap/ident/brake_thermal_fit.h"
#include "hotlap/ident/tyre_thermal_fit.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

TEST(FitParameterValues, NamesTheTyreAndBrakeValuesOfTheCorner) {
  vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  car.tyres[CornerIndex(Corner::kRearLeft)].params.p3 = 1.25e-5;
  brake::BrakeThermalParams<double>& b = car.brakes[CornerIndex(Corner::kRearLeft)].params;
  b.heat_partition = 0.71;
  b.calliper_convection = {2.0, 0.5, 3.0, -1.0, 0.25, 4.0};  // l11 l21 l22 l31 l32 l33

  const std::map<std::string, double> v = FitParameterValues(car, Corner::kRearLeft);
  EXPECT_EQ(v.size(), 7u + 2u + 3u + 2u + 12u);  // tyre, contact length, gas path, brake
  EXPECT_EQ(v.at("rim_air_W_per_K"), car.tyre(Corner::kRearLeft).params.rim_air_conductance);
  EXPECT_EQ(v.at("p3_J_per_kgN"), 1.25e-5);
  EXPECT_EQ(v.at("wp2"), car.tyre(Corner::kRearLeft).params.wear_exponent);
  EXPECT_EQ(v.at("p_cp1"), car.tyre(Corner::kRearLeft).params.contact_length_coeff);
  EXPECT_EQ(v.at("heat_partition"), 0.71);
  EXPECT_EQ(v.at("calliper_convection_P11_W_per_K"), 4.0);
  EXPECT_EQ(v.at("calliper_convection_P21_W_per_K"), 1.0);
  EXPECT_EQ(v.at("calliper_convection_P22_W_per_K"), 0.25 + 9.0);
  EXPECT_EQ(v.at("calliper_convection_P31_W_per_K"), -2.0);
  EXPECT_EQ(v.at("calliper_convection_P32_W_per_K"), -0.5 + 0.75);
  EXPECT_EQ(v.at("calliper_convection_P33_W_per_K"), 1.0 + 0.0625 + 16.0);
  // Another corner keeps the file's values.
  EXPECT_NE(FitParameterValues(car, Corner::kFrontLeft).at("heat_partition"), 0.71);
  for (const std::string& key : TyreParameterKeys()) EXPECT_EQ(v.count(key), 1u) << key;
  for (const char* key : {"mass_participation", "disc_convection_P33_W_per_K"}) {
    EXPECT_EQ(v.count(key), 1u) << key;
  }
}

TEST(ConvectionMatrixEntries, AreTheEntriesOfLTimesItsTranspose) {
  const brake::ConvectionPolynomial<double> l{1.5, -0.5, 2.0, 0.25, 1.0, 3.0};
  const std::array<double, 6> p = ConvectionMatrixEntries(l);
  EXPECT_EQ(p[0], 2.25);                // P11 = l11^2
  EXPECT_EQ(p[1], -0.75);               // P21 = l21 l11
  EXPECT_EQ(p[2], 0.25 + 4.0);          // P22 = l21^2 + l22^2
  EXPECT_EQ(p[3], 0.375);               // P31 = l31 l11
  EXPECT_EQ(p[4], -0.125 + 2.0);        // P32 = l31 l21 + l32 l22
  EXPECT_EQ(p[5], 0.0625 + 1.0 + 9.0);  // P33 = l31^2 + l32^2 + l33^2
}

}  // namespace
}  // namespace hotlap::ident
