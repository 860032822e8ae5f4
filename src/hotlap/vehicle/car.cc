#include "hotlap/vehicle/car.h"

#include <cmath>

#include <fmt/format.h>

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::vehicle {

namespace {

// The duct factor: hA = z' L L' z times `factor`, every Cholesky entry times its square root.
void ScaleConvection(brake::BrakeThermalParams<double>& p, double factor) {
  for (const brake::BrakeThermalField& f : brake::BrakeThermalFields()) {
    if (f.polynomial) f.Of(p) *= std::sqrt(factor);
  }
}

}  // namespace

Car LoadCar(const std::filesystem::path& path) { return LoadCar(path, {}); }

Car LoadCar(const std::filesystem::path& path, const std::vector<CarOverride>& overrides) {
  const CarOverridePlan plan = PlanCarOverrides(path, overrides);
  YamlReader y = YamlReader::Load(path, plan.car);
  Car car;
  car.path = path;
  car.overrides = overrides;
  car.name = y.String("name");
  y.Choice("model", {"stock_car"});
  {
    YamlReader tyres = y.Map("tyres");
    for (Corner c : kAllCorners) {
      const int i = CornerIndex(c);
      car.tyres[i] = tyre::LoadTyreFile(tyres.FilePath(CornerName(c)), plan.tyres[i]);
    }
    tyres.Finish();
  }
  {
    YamlReader brakes = y.Map("brakes");
    for (Corner c : kAllCorners) {
      const int i = CornerIndex(c);
      car.brakes[i] = brake::LoadBrakeFile(brakes.FilePath(CornerName(c)), plan.brakes[i]);
      if (plan.duct_factor[i]) ScaleConvection(car.brakes[i].params, *plan.duct_factor[i]);
    }
    brakes.Finish();
  }
  {
    YamlReader init = y.Map("initial_state");
    const Range temp = Range::Closed(-50.0, 1200.0, "degC");
    car.initial.tread_temp = CelsiusToKelvin(init.Number("tread_temp_C", temp));
    car.initial.carcass_temp = CelsiusToKelvin(init.Number("carcass_temp_C", temp));
    car.initial.disc_temp = CelsiusToKelvin(init.Number("disc_temp_C", temp));
    car.initial.calliper_temp = CelsiusToKelvin(init.Number("calliper_temp_C", temp));
    init.Finish();
  }
  constexpr std::array<std::string_view, 5> kVehicleSections = {"chassis", "aero", "powertrain",
                                                                "brake_system", "tyre_forces"};
  int present = 0;
  for (std::string_view section : kVehicleSections) present += y.Has(section) ? 1 : 0;
  if (present == static_cast<int>(kVehicleSections.size())) {
    car.vehicle = ReadVehicleParams(y);
  } else if (present > 0) {
    for (std::string_view section : kVehicleSections) {
      if (!y.Has(section)) {
        y.Fail(section,
               "is missing; a car with any of chassis, aero, powertrain, brake_system "
               "and tyre_forces needs all five (docs/vehicle.md)");
      }
    }
  }
  y.Finish();
  return car;
}

const VehicleParams& RequireVehicle(const Car& car, std::string_view purpose) {
  if (!car.vehicle) {
    throw InputError(fmt::format(
        "{}: the car has no chassis, aero, powertrain, brake_system and tyre_forces sections, "
        "which {} needs (docs/vehicle.md); it can only replay logs",
        car.path.string(), purpose));
  }
  return *car.vehicle;
}

}  // namespace hotlap::vehicle
