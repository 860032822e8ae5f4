#pragma once
/// @file
/// The field tables of the vehicle's numbers (vehicle_params.h): for each, the car file's section
/// and key, the allowed range with its unit and the conversion to SI. The reader
/// (ReadVehicleParams) and the set-up sensitivities' values (ocp/lap_sensitivities.h) read these
/// tables, so each key is written once, as the thermal models' tables (tyre/tyre_thermal_fields.h)
/// list theirs.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "hotlap/common/yaml_reader.h"
#include "hotlap/vehicle/car.h"
#include "hotlap/vehicle/vehicle_params.h"

namespace hotlap::vehicle {

/// One number of VehicleParams as a car file's `chassis`, `aero`, `powertrain` or
/// `brake_system` section holds it (in SI there).
struct VehicleField {
  std::string_view section;  ///< e.g. "chassis"
  std::string_view key;      ///< with its unit, e.g. "mass_kg"
  double& (*member)(VehicleParams&);
  Range range;  ///< allowed file values, with the unit for messages

  /// "section.key", as overrides and messages name it.
  std::string Path() const;
  double& Of(VehicleParams& p) const { return member(p); }
  double Of(const VehicleParams& p) const { return member(const_cast<VehicleParams&>(p)); }
};

/// Every number of the four sections, in file order.
std::span<const VehicleField> VehicleFields();

/// One number of a corner's tyre set-up (the car file's `tyre_forces.<c>`).
struct CornerSetupField {
  std::string_view key;  ///< e.g. "pressure_kPa"
  double CornerSetup::*member;
  Range range;
  /// File value to SI and back (kPa to Pa, degrees to radians); nullptr where the file is SI.
  double (*to_si)(double) = nullptr;
  double (*from_si)(double) = nullptr;
  bool optional = false;  ///< may be left out (the rolling radius of a .tir model)

  double ToSi(double file_value) const { return to_si ? to_si(file_value) : file_value; }
  double FromSi(double si) const { return from_si ? from_si(si) : si; }
};

/// The corner set-up's numbers, in file order.
std::span<const CornerSetupField> CornerSetupFields();

/// One temperature of a car file's `initial_state` (degC in the file, kelvin inside).
struct InitialStateField {
  std::string_view key;  ///< e.g. "tread_temp_C"
  double InitialTemperatures::*member;
  /// An optional one's default: this other member's value (listed before it); nullptr: required.
  double InitialTemperatures::*default_from = nullptr;
};

/// The initial state's temperatures, in file order, and their common range (degC).
std::span<const InitialStateField> InitialStateFields();
Range InitialTemperatureRange();

/// The value of the car-file key `path` ("chassis.mass_kg", "tyre_forces.rr.pressure_kPa") in
/// `p`, in the key's unit; nullopt for a key of no table.
std::optional<double> VehicleFileValue(const VehicleParams& p, std::string_view path);

}  // namespace hotlap::vehicle
