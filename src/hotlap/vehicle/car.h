#pragma once
/// @file
/// A car as its files describe it: per-corner tyres and brakes, and default starting
/// temperatures (the vehicle model adds chassis, aero and powertrain).

#include <array>
#include <filesystem>
#include <string>

#include "hotlap/brake/brake_params_io.h"
#include "hotlap/common/corner.h"
#include "hotlap/tyre/tyre_params_io.h"

namespace hotlap::vehicle {

/// Temperatures a simulation starts from when nothing better is known, K.
struct InitialTemperatures {
  double tread_temp = 0.0;
  double carcass_temp = 0.0;
  double disc_temp = 0.0;
  double calliper_temp = 0.0;
};

struct Car {
  std::string name;
  std::filesystem::path path;
  std::array<tyre::TyreFile, 4> tyres;     ///< indexed by CornerIndex
  std::array<brake::BrakeFile, 4> brakes;  ///< indexed by CornerIndex
  InitialTemperatures initial;

  const tyre::TyreFile& tyre(Corner c) const { return tyres[CornerIndex(c)]; }
  const brake::BrakeFile& brake(Corner c) const { return brakes[CornerIndex(c)]; }
};

/// Loads a car.yaml and every file it refers to (paths relative to the car file).
Car LoadCar(const std::filesystem::path& path);

}  // namespace hotlap::vehicle
