// The vehicle's field tables (vehicle/vehicle_fields.h): every number the reader fills, each
// read from its key in the file's unit, and the file value of each key read back.

#include "hotlap/vehicle/vehicle_fields.h"

#include <cmath>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

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
