#pragma once
/// @file
/// A car as its files describe it: per-corner tyres and brakes, default starting temperatures,
/// and (optionally) the chassis, aero, powertrain, brake balance and tyre force models that the
/// lap simulation and optimal control need (vehicle_params.h). A car with only the thermal parts
/// can be replayed over a log but not driven round a track.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/brake/brake_params_io.h"
#include "hotlap/common/corner.h"
#include "hotlap/tyre/tyre_params_io.h"
#include "hotlap/vehicle/car_override.h"
#include "hotlap/vehicle/vehicle_params.h"

namespace hotlap::vehicle {

/// Temperatures a simulation starts from when nothing better is known, K.
struct InitialTemperatures {
  double tread_temp = 0.0;
  double carcass_temp = 0.0;
  double disc_temp = 0.0;
  double calliper_temp = 0.0;
  double rim_temp = 0.0;        ///< the gas-and-rim tyres' rims
  double disc_bulk_temp = 0.0;  ///< the surface-and-bulk discs' bulk
};

struct Car {
  std::string name;
  std::filesystem::path path;
  std::array<tyre::TyreFile, 4> tyres;     ///< indexed by CornerIndex
  std::array<brake::BrakeFile, 4> brakes;  ///< indexed by CornerIndex
  InitialTemperatures initial;
  std::optional<VehicleParams> vehicle;  ///< absent for a thermal-only car file
  /// The overrides the car was loaded with, as given (empty: the files' values); the summaries
  /// record them (OverridesJson).
  std::vector<CarOverride> overrides;

  const tyre::TyreFile& tyre(Corner c) const { return tyres[CornerIndex(c)]; }
  const brake::BrakeFile& brake(Corner c) const { return brakes[CornerIndex(c)]; }
};

/// Loads a car.yaml and every file it refers to (paths relative to the car file). The vehicle
/// sections (chassis, aero, powertrain, brake_system, tyre_forces) are all present or all absent.
Car LoadCar(const std::filesystem::path& path);
/// The same with parameters overridden by their dotted keys (car_override.h, docs/overrides.md):
/// each value replaces the file's before the file is read, so it is checked as the file's own
/// (messages start with "override 'KEY=VALUE'"); a corner's brake and tyre files are read for that
/// corner alone, so corners sharing a file get their own values. InputError for any override
/// PlanCarOverrides refuses.
Car LoadCar(const std::filesystem::path& path, const std::vector<CarOverride>& overrides);

/// The same car with the paper's models at every corner: the two-mass tyre without gas and rim
/// (thermal_model paper) and the lumped disc (disc_model lumped); their other parameters as they
/// are. For the solvers whose states are the paper's (the optimal lap).
Car PaperModelsOf(const Car& car);

/// The car's vehicle parameters; InputError naming the car file and what `purpose` needs if the
/// file has none.
const VehicleParams& RequireVehicle(const Car& car, std::string_view purpose);

}  // namespace hotlap::vehicle
