// The vehicle's field tables (vehicle/vehicle_fields.h): every number the reader fills, each
// read from its key in the file's unit, and the file value of each key read back.

#include "hotlap/vehicle/vehicle_fields.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "hotlap/common/read_file.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/vehicle/car.h"
#include "test_util.h"

namespace hotlap::vehicle {
namespace {

TEST(VehicleFieldsTest, EachKeyIsTheFilesNumberInSiAndReadsBack) {
  const Car car = LoadCar(test::Gen7Dir() / "car.yaml");
  const VehicleParams& p = RequireVehicle(car, "test");
  // Hand-checked against data/cars/gen7/car.yaml.
  EXPECT_DOUBLE_EQ(p.chassis.mass, 1542.0);
  EXPECT_DOUBLE_EQ(p.brakes.front_share, 0.60);
  EXPECT_DOUBLE_EQ(p.corners[3].pressure, 303.4e3);
  EXPECT_NEAR(p.corners[1].camber, -3.0 * M_PI / 180.0, 1e-15);
  // Each key: its file value is the member's (the sections are in SI).
  std::map<std::string, double> file_values;
  for (const YamlScalarField& f : ListYamlScalars(test::Gen7Dir() / "car.yaml")) {
    if (f.number) file_values[f.field] = std::stod(f.text);
  }
  const auto file_value = [&](const std::string& path) {
    EXPECT_TRUE(file_values.count(path)) << path;
    return file_values[path];
  };
  std::set<std::string> paths;
  for (const VehicleField& f : VehicleFields()) {
    EXPECT_TRUE(paths.insert(f.Path()).second) << f.Path() << " listed twice";
    const double file = file_value(f.Path());
    EXPECT_EQ(f.Of(p), file) << f.Path();
    EXPECT_DOUBLE_EQ(*VehicleFileValue(p, f.Path()), file) << f.Path();
    EXPECT_TRUE(f.range.Contains(file)) << f.Path();
  }
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    for (const CornerSetupField& f : CornerSetupFields()) {
      const std::string path = std::string("tyre_forces.") + c + "." + std::string(f.key);
      EXPECT_EQ(*VehicleFileValue(p, path), file_value(path)) << path;
    }
  }
  EXPECT_FALSE(VehicleFileValue(p, "chassis.cross_weight"));
  EXPECT_FALSE(VehicleFileValue(p, "tyre_forces.xx.pressure_kPa"));
  EXPECT_FALSE(VehicleFileValue(p, "tyre_forces.fl.file"));
}

// The initial state: each temperature from its key, kelvin inside; an optional one left out takes
// its default's value.
TEST(VehicleFieldsTest, TheInitialStateIsReadFromItsTable) {
  const Car car = LoadCar(test::Gen7Dir() / "car.yaml");
  // data/cars/gen7/car.yaml: 60, 60, 150, 80, 45, 120 degC.
  EXPECT_DOUBLE_EQ(car.initial.tread_temp, 333.15);
  EXPECT_DOUBLE_EQ(car.initial.calliper_temp, 353.15);
  EXPECT_DOUBLE_EQ(car.initial.rim_temp, 318.15);
  EXPECT_DOUBLE_EQ(car.initial.disc_bulk_temp, 393.15);
  EXPECT_EQ(InitialStateFields().size() * sizeof(double), sizeof(InitialTemperatures));
  // A copy of the car without the two optional ones.
  test::TempDir dir;
  std::filesystem::copy(test::Gen7Dir(), dir.path() / "gen7",
                        std::filesystem::copy_options::recursive);
  std::string text = ReadWholeFile(dir.path() / "gen7/car.yaml"), kept;
  for (size_t at = 0; at < text.size();) {
    const size_t end = std::min(text.find('\n', at), text.size() - 1) + 1;
    const std::string line = text.substr(at, end - at);
    if (!test::Contains(line, "rim_temp_C:") && !test::Contains(line, "disc_bulk_temp_C:")) {
      kept += line;
    }
    at = end;
  }
  ASSERT_LT(kept.size(), text.size());
  test::WriteTextFile(dir.path() / "gen7/car.yaml", kept);
  const Car without = LoadCar(dir.path() / "gen7/car.yaml");
  EXPECT_DOUBLE_EQ(without.initial.rim_temp, without.initial.carcass_temp);
  EXPECT_DOUBLE_EQ(without.initial.disc_bulk_temp, without.initial.disc_temp);
}

// The tables cover every double of the four sections: a member added to a struct and not to the
// table would be left at zero by the reader.
TEST(VehicleFieldsTest, TheTablesCoverEveryNumberOfTheirStructs) {
  size_t chassis = 0, aero = 0, powertrain = 0, brakes = 0;
  for (const VehicleField& f : VehicleFields()) {
    chassis += f.section == "chassis";
    aero += f.section == "aero";
    powertrain += f.section == "powertrain";
    brakes += f.section == "brake_system";
  }
  EXPECT_EQ(chassis * sizeof(double), sizeof(ChassisParams));
  EXPECT_EQ(aero * sizeof(double), sizeof(AeroParams));
  EXPECT_EQ(powertrain * sizeof(double), sizeof(PowertrainParams));
  EXPECT_EQ(brakes * sizeof(double), sizeof(BrakeSystemParams));
  EXPECT_EQ(VehicleFields().size(), chassis + aero + powertrain + brakes);
  // The corner set-up: its three numbers and the force model.
  EXPECT_EQ(CornerSetupFields().size(), 3u);
}

}  // namespace
}  // namespace hotlap::vehicle
