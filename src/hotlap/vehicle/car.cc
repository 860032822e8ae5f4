#include "hotlap/vehicle/car.h"

#include <cmath>

#include <fmt/format.h>

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/vehicle/vehicle_fields.h"

namespace hotlap::vehicle {

namespace {

// The duct factor: hA = z' L L' z times `factor`, every Cholesky entry times its square root;
// the duct's air also runs through a bulk disc's vanes.
void ScaleConvection(brake::BrakeThermalParams<double>& p, double factor) {
  for (const brake::BrakeThermalField& f : brake::BrakeThermalFields()) {
    if (f.polynomial) f.Of(p) *= std::sqrt(factor);
  }
  p.bulk_convection *= factor;
}

// The gas-and-rim tyres take their cold pressure from the car's set-up; a bulk disc that heats
// the rim needs a tyre that has one.
void CoupleCorners(const YamlReader& y, Car& car) {
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    tyre::TyreThermalParams<double>& tyre = car.tyres[i].params;
    const brake::BrakeThermalParams<double>& brake = car.brakes[i].params;
    if (tyre.HasGasAndRim()) {
      const std::string file = car.tyres[i].path.string();
      if (car.vehicle && car.tyres[i].cold_pressure_in_file) {
        y.Fail("tyres", fmt::format("{}: gas.cold_pressure_kPa is set once, in the car's "
                                    "tyre_forces.{}.pressure_kPa; leave it out of the tyre file",
                                    file, CornerName(c)));
      }
      if (car.vehicle) {
        tyre.cold_pressure = car.vehicle->corners[i].pressure;
      } else if (!car.tyres[i].cold_pressure_in_file) {
        y.Fail("tyres", fmt::format("{}: thermal_model gas_rim needs the cold pressure: the car's "
                                    "tyre_forces.{}.pressure_kPa, or gas.cold_pressure_kPa in the "
                                    "tyre file of a car without tyre forces",
                                    file, CornerName(c)));
      }
    } else if (brake.HasBulk() && (brake.hub_conductance > 0.0 || brake.rim_view_fraction > 0.0)) {
      y.Fail("brakes",
             fmt::format("{}: the disc heats the rim (hub_conductance_W_per_K, "
                         "rim_view_fraction), but the {} tyre ({}) has no rim: give it "
                         "thermal_model gas_rim or set both to 0",
                         car.brakes[i].path.string(), CornerName(c), car.tyres[i].path.string()));
    }
  }
}

}  // namespace

Car LoadCar(const std::filesystem::path& path) { return LoadCar(path, {}); }

Car LoadCar(const std::filesystem::path& path, const std::vector<CarOverride>& overrides) {
  // Each file parsed once: the override plan, its optional-number probe and the readers below
  // all read the same trees.
  const YamlParseCache cache;
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
    for (const InitialStateField& f : InitialStateFields()) {
      const std::optional<double> celsius =
          f.default_from ? init.OptionalNumber(f.key, InitialTemperatureRange())
                         : init.Number(f.key, InitialTemperatureRange());
      // Left out (an optional one): the default's value, through degC as the file would give it.
      car.initial.*f.member =
          CelsiusToKelvin(celsius ? *celsius : KelvinToCelsius(car.initial.*f.default_from));
    }
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
  CoupleCorners(y, car);
  y.Finish();
  return car;
}

Car PaperModelsOf(const Car& car) {
  Car out = car;
  for (tyre::TyreFile& t : out.tyres) t.params.model = tyre::TyreThermalModel::kPaper;
  for (brake::BrakeFile& b : out.brakes) b.params.disc_model = brake::DiscModel::kLumped;
  return out;
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
