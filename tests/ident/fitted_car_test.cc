// Writing a fitted car: it loads as it is (vehicle sections included), carries the fitted values
// with their source comments and every other line unchanged, and is self-contained.

#include "hotlap/ident/fitted_car.h"

#include <filesystem>
#include <regex>

#include <gtest/gtest.h>

#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::ident {
namespace {

namespace fs = std::filesystem;

TEST(FittedCarTest, WritesASelfContainedCarThatLoadsWithTheFittedValues) {
  const test::TempDir dir;
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  FittedCarEdits edits;
  edits.header = {"Fitted by a test."};
  edits.tyres[3] = {{"heat_generation.p1", 0.4321, "fitted today to log.csv, std error 0.001"},
                    {"wear.wp2", 1.6, "fitted today"}};
  edits.brakes[1] = {{"heat_partition", 0.9, "fitted"},
                     {"disc_convection_cholesky_sqrtW_per_K.l22", 2.5, "fitted"}};
  const auto written = WriteFittedCar(car, dir.path() / "out" / "fit.yaml", edits);
  EXPECT_EQ(written.back(), dir.path() / "out" / "fit.yaml");  // the car file last

  // Move the whole result elsewhere: it still loads (nothing points back at data/).
  fs::rename(dir.path() / "out", dir.path() / "moved");
  const vehicle::Car fitted = vehicle::LoadCar(dir.path() / "moved" / "fit.yaml");
  EXPECT_DOUBLE_EQ(fitted.tyre(Corner::kRearRight).params.p1, 0.4321);
  EXPECT_DOUBLE_EQ(fitted.tyre(Corner::kRearRight).params.wear_exponent, 1.6);
  EXPECT_DOUBLE_EQ(fitted.tyre(Corner::kFrontRight).params.p1,
                   car.tyre(Corner::kFrontRight).params.p1);
  EXPECT_DOUBLE_EQ(fitted.brake(Corner::kFrontRight).params.heat_partition, 0.9);
  EXPECT_DOUBLE_EQ(fitted.brake(Corner::kFrontLeft).params.heat_partition,
                   car.brake(Corner::kFrontLeft).params.heat_partition);  // its own file now
  EXPECT_DOUBLE_EQ(fitted.brake(Corner::kFrontRight).params.disc_convection.l22, 2.5);
  ASSERT_TRUE(fitted.vehicle.has_value());
  EXPECT_DOUBLE_EQ(fitted.vehicle->chassis.mass, car.vehicle->chassis.mass);

  const std::string rr = test::ReadTextFile(dir.path() / "moved/fit/tyres/rr.yaml");
  EXPECT_TRUE(test::Contains(rr, "# Fitted by a test.\n"));
  EXPECT_TRUE(std::regex_search(rr, std::regex("\n  p1: 0.4321 +# fitted today to log.csv, "
                                               "std error 0.001\n")));
  // Every other line as in the original.
  const std::string original = test::ReadTextFile(test::Gen7Dir() / "tyres/rr.yaml");
  EXPECT_TRUE(test::Contains(rr, "  p5_W_per_m2K: 427.5"));
  EXPECT_TRUE(test::Contains(original, "contact_width_m: 0.2286                 # c_w"));
  EXPECT_TRUE(test::Contains(rr, "contact_width_m: 0.2286                 # c_w"));
  const std::string car_text = test::ReadTextFile(dir.path() / "moved/fit.yaml");
  EXPECT_TRUE(test::Contains(car_text, "  rr: fit/tyres/rr.yaml"));
  EXPECT_TRUE(test::Contains(car_text, "{file: fit/tyres/left.tir, pressure_kPa: 137.9"));
  EXPECT_TRUE(test::Contains(car_text, "mass_kg: 1542                       # public"));
}

TEST(FittedCarTest, UnknownKeyIsAnErrorBeforeTheCarFileIsWritten) {
  const test::TempDir dir;
  const vehicle::Car car = vehicle::LoadCar(test::Gen7Dir() / "car.yaml");
  FittedCarEdits edits;
  edits.tyres[0] = {{"heat_generation.p9", 1.0, "x"}};
  EXPECT_THROW(WriteFittedCar(car, dir.path() / "fit.yaml", edits), InputError);
  EXPECT_FALSE(fs::exists(dir.path() / "fit.yaml"));
}

TEST(FittedCarTest, Formats) {
  EXPECT_EQ(FormatFileNumber(0.123456789123), "0.12345679");
  EXPECT_TRUE(std::regex_match(TodayIsoDate(), std::regex("20[0-9]{2}-[01][0-9]-[0-3][0-9]")));
}

}  // namespace
}  // namespace hotlap::ident
