#include "hotlap/vehicle/car.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/corner.h"
#include "hotlap/common/error.h"
#include "test_util.h"

namespace hotlap::vehicle {
namespace {

namespace fs = std::filesystem;
using test::Contains;

TEST(CarTest, ShippedCarLoadsEveryCorner) {
  const Car car = LoadCar(test::Gen7Dir() / "car.yaml");
  EXPECT_EQ(car.name, "gen7");
  for (Corner c : kAllCorners) {
    SCOPED_TRACE(std::string(CornerName(c)));
    EXPECT_EQ(car.tyre(c).name, "gen7-" + std::string(CornerName(c)));
    EXPECT_EQ(car.tyre(c).path.filename(), std::string(CornerName(c)) + ".yaml");
    ASSERT_NE(car.tyre(c).compound, nullptr);
    EXPECT_EQ(car.tyre(c).compound->name, "gen7-speedway-compound");
    EXPECT_EQ(car.brake(c).name, c == Corner::kFrontLeft ? "gen7-front-left-brake"
                                 : IsFront(c)            ? "gen7-front-brake"
                                                         : "gen7-rear-brake");
    EXPECT_EQ(car.brake(c).params.disc_mass, IsFront(c) ? 8.8 : 4.9);  // 000 Table 5
    EXPECT_EQ(&car.tyre(c), &car.tyres[CornerIndex(c)]);
  }
}

// 000 Table 4, p1 and p5 per corner, reached through the car (the full table is checked in
// tests/tyre/tyre_params_io_test.cc).
TEST(CarTest, CornersGetTheirOwnTyreParameters) {
  const Car car = LoadCar(test::Gen7Dir() / "car.yaml");
  EXPECT_EQ(car.tyre(Corner::kFrontRight).params.p1, 0.284);
  EXPECT_EQ(car.tyre(Corner::kFrontLeft).params.p1, 0.243);
  EXPECT_EQ(car.tyre(Corner::kRearRight).params.p1, 0.328);
  EXPECT_EQ(car.tyre(Corner::kRearLeft).params.p1, 0.173);
  EXPECT_EQ(car.tyre(Corner::kFrontRight).params.p5, 150.7);
  EXPECT_EQ(car.tyre(Corner::kFrontLeft).params.p5, 111.8);
  EXPECT_EQ(car.tyre(Corner::kRearRight).params.p5, 427.5);
  EXPECT_EQ(car.tyre(Corner::kRearLeft).params.p5, 166.5);
  EXPECT_EQ(car.tyre(Corner::kRearRight).params.wear_exponent, 1.785);
  EXPECT_EQ(car.tyre(Corner::kFrontLeft).params.contact_length_coeff, 0.0099999);
}

// degC in the file, kelvin inside (exact to rounding).
TEST(CarTest, InitialTemperaturesAreConvertedToKelvin) {
  const Car car = LoadCar(test::Gen7Dir() / "car.yaml");
  EXPECT_NEAR(car.initial.tread_temp, 333.15, 1e-12);
  EXPECT_NEAR(car.initial.carcass_temp, 333.15, 1e-12);
  EXPECT_NEAR(car.initial.disc_temp, 423.15, 1e-12);
  EXPECT_NEAR(car.initial.calliper_temp, 353.15, 1e-12);
}

// A copy of the whole shipped car folder, so that relative paths resolve inside the copy.
class BadCarFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::copy(test::Gen7Dir(), dir_.path() / "gen7", fs::copy_options::recursive);
    car_path_ = dir_.path() / "gen7" / "car.yaml";
  }
  // Replaces `from` with `to` in `relative` (inside the copy), loads the car and returns the
  // InputError's message.
  std::string LoadError(const std::string& relative, const std::string& from,
                        const std::string& to) {
    edited_ = dir_.path() / "gen7" / relative;
    test::WriteTextFile(edited_, test::ReplaceOnce(test::ReadTextFile(edited_), from, to));
    try {
      LoadCar(car_path_);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for '" << from << "' -> '" << to << "' in " << relative;
    return "";
  }
  test::TempDir dir_;
  fs::path car_path_, edited_;
};

TEST_F(BadCarFileTest, UneditedCopyLoads) {
  EXPECT_EQ(LoadCar(car_path_).tyre(Corner::kRearRight).params.p5, 427.5);
}

TEST_F(BadCarFileTest, MissingReferencedFile) {
  const std::string m = LoadError("car.yaml", "fl: tyres/fl.yaml", "fl: tyres/fl_soft.yaml");
  EXPECT_TRUE(Contains(m, car_path_.string()));
  EXPECT_TRUE(Contains(m, "field 'tyres.fl'"));
  EXPECT_TRUE(Contains(m, "tyres/fl_soft.yaml"));
  EXPECT_TRUE(Contains(m, "does not exist"));
}

TEST_F(BadCarFileTest, MissingCorner) {
  const std::string m = LoadError("car.yaml", "  rr: brakes/rear.yaml", "");
  EXPECT_TRUE(Contains(m, car_path_.string()));
  EXPECT_TRUE(Contains(m, "missing field 'brakes.rr'"));
}

TEST_F(BadCarFileTest, UnknownExtraKey) {
  const std::string m =
      LoadError("car.yaml", "  rr: tyres/rr.yaml", "  rr: tyres/rr.yaml\n  spare: tyres/rr.yaml");
  EXPECT_TRUE(Contains(m, car_path_.string()));
  EXPECT_TRUE(Contains(m, "unknown field 'tyres.spare'"));
}

TEST_F(BadCarFileTest, InitialTemperatureOutOfRange) {
  const std::string m = LoadError("car.yaml", "disc_temp_C: 150", "disc_temp_C: 1500");
  EXPECT_TRUE(Contains(m, "field 'initial_state.disc_temp_C'"));
  EXPECT_TRUE(Contains(m, "1500"));
  EXPECT_TRUE(Contains(m, "in [-50, 1200] degC"));
}

TEST_F(BadCarFileTest, WrongUnitSuffixInInitialState) {
  const std::string m = LoadError("car.yaml", "tread_temp_C: 60", "tread_temp_K: 333.15");
  EXPECT_TRUE(Contains(m, "missing field 'initial_state.tread_temp_C'"));
  EXPECT_TRUE(Contains(m, "'tread_temp_K'"));
}

// An error deep in the tree names the file it is in, not the car file.
TEST_F(BadCarFileTest, ErrorInATyreFileNamesThatFile) {
  const std::string m = LoadError("tyres/fl.yaml", "carcass_mass_kg: 11.0", "carcass_mass_kg: -1");
  EXPECT_TRUE(Contains(m, edited_.string()));
  EXPECT_TRUE(Contains(m, "field 'construction.carcass_mass_kg'"));
}

TEST_F(BadCarFileTest, ErrorInABrakeFileNamesThatFile) {
  const std::string m =
      LoadError("brakes/rear.yaml", "calliper_emissivity: 0.25", "calliper_emissivity: 2.5");
  EXPECT_TRUE(Contains(m, edited_.string()));
  EXPECT_TRUE(Contains(m, "field 'calliper_emissivity'"));
}

TEST_F(BadCarFileTest, ErrorInTheCompoundNamesThatFile) {
  const std::string m =
      LoadError("tyres/compound.yaml", "{wear_mm: 1, factor: 0.88}", "{wear_mm: 0, factor: 0.88}");
  EXPECT_TRUE(Contains(m, edited_.string()));
  EXPECT_TRUE(Contains(m, "field 'grip_vs_wear'"));
}

TEST_F(BadCarFileTest, WrongModel) {
  const std::string m = LoadError("car.yaml", "model: stock_car", "model: open_wheel");
  EXPECT_TRUE(Contains(m, "field 'model'"));
  EXPECT_TRUE(Contains(m, "'stock_car'"));  // the allowed choice is listed
}

TEST(CarTest, MissingCarFile) {
  try {
    LoadCar(test::Gen7Dir() / "no_such_car.yaml");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "no_such_car.yaml"));
    EXPECT_TRUE(Contains(e.what(), "no such file"));
  }
}

}  // namespace
}  // namespace hotlap::vehicle
