#pragma once
/// @file
/// Loading tyre compound and tyre thermal parameter files (YAML, units in the keys; see
/// data/cars/gen7/tyres/ and docs/file-formats.md). Every value is checked against its allowed
/// range; any problem throws InputError naming the file, field, value and range.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "hotlap/common/yaml_reader.h"
#include "hotlap/tyre/compound.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::tyre {

/// A tyre as loaded from its file.
struct TyreFile {
  std::string name;
  std::filesystem::path path;
  std::filesystem::path compound_path;
  TyreThermalParams<double> params;
  std::shared_ptr<const TyreCompound> compound;
  /// The gas-and-rim model's cold pressure came from the file's gas.cold_pressure_kPa (for a car
  /// without tyre forces; a car with them sets it from tyre_forces.<c>.pressure_kPa).
  bool cold_pressure_in_file = false;
};

/// Loads a compound file (`model: cubic_grip_wear`).
TyreCompound LoadTyreCompound(const std::filesystem::path& path);

/// Loads a tyre file (`model: two_mass_thermal`) and the compound file it names.
TyreFile LoadTyreFile(const std::filesystem::path& path);
/// The same with numbers of the tyre file (not of its compound file) replaced before it is read
/// (YamlReader::Load), each checked as the file's own.
TyreFile LoadTyreFile(const std::filesystem::path& path,
                      const std::vector<YamlOverride>& overrides);

}  // namespace hotlap::tyre
