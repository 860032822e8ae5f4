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

TEST(FittedCarTest, SourceCommentsSayHowWellTheValueIsKnown) {
  ParameterEstimate e{.value = 0.5, .std_error = 0.0012345, .ci_low = 0.4976, .ci_high = 0.5024};
  e.well_determined = true;
  EXPECT_EQ(SourceComment("2030-01-02", "lap.csv", e),
            "fitted 2030-01-02 to lap.csv: std error 0.00123, 95% [0.4976, 0.5024]");
  e.well_determined = false;
  EXPECT_EQ(SourceComment("2030-01-02", "lap.csv", e),
            "fitted 2030-01-02 to lap.csv: std error 0.00123, 95% [0.4976, 0.5024]; not well "
            "determined");
  e.at_bound = true;
  EXPECT_EQ(SourceComment("d", "l", e),
            "fitted d to l: std error 0.00123, 95% [0.4976, 0.5024]; "
            "at its bound");
  e.undetermined = true;
  EXPECT_EQ(SourceComment("d", "l", e),
            "fitted d to l: undetermined by the data (kept where the fit left it)");
}

TEST(FittedCarTest, FileEditsOfAFitAreItsModelParametersPrefixed) {
  FitResult fit;
  fit.parameters = {{.key = "p1"},
                    {.key = "initial_tread_temp_C", .role = ParameterRole::kNuisance},
                    {.key = "p5_W_per_m2K"}};
  fit.estimates = {{.value = 0.4}, {.value = 350.0}, {.value = 641.0}};
  fit.estimates[2].undetermined = true;
  const std::vector<FileEdit> edits = FileEditsOf(fit, "heat_generation.", "D", "L");
  ASSERT_EQ(edits.size(), 2u);
  EXPECT_EQ(edits[0].key, "heat_generation.p1");
  EXPECT_EQ(edits[0].value, 0.4);
  EXPECT_EQ(edits[0].comment, SourceComment("D", "L", fit.estimates[0]));
  EXPECT_EQ(edits[1].key, "heat_generation.p5_W_per_m2K");
  EXPECT_EQ(edits[1].value, 641.0);
  EXPECT_TRUE(edits[1].comment.find("undetermined") != std::string::npos);
}

}  // namespace
}  // namespace hotlap::ident
