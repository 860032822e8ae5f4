#include "hotlap/vehicle/car.h"

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::vehicle {

Car LoadCar(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  Car car;
  car.path = path;
  car.name = y.String("name");
  y.Choice("model", {"stock_car"});
  {
    YamlReader tyres = y.Map("tyres");
    for (Corner c : kAllCorners) {
      car.tyres[CornerIndex(c)] = tyre::LoadTyreFile(tyres.FilePath(CornerName(c)));
    }
    tyres.Finish();
  }
  {
    YamlReader brakes = y.Map("brakes");
    for (Corner c : kAllCorners) {
      car.brakes[CornerIndex(c)] = brake::LoadBrakeFile(brakes.FilePath(CornerName(c)));
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
