#pragma once
/// @file
/// Loading brake parameter files (YAML, units in the keys; see data/cars/gen7/brakes/ and
/// docs/file-formats.md). Any problem throws InputError naming the file, field, value and range.

#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::brake {

/// Dimensions of the part (000 Table 5), kept for reports; the lumped model does not use them.
struct BrakeGeometry {
  double disc_diameter = 0.0;           ///< m
  double mounting_hole_diameter = 0.0;  ///< m
  double disc_thickness = 0.0;          ///< m
};

struct BrakeFile {
  std::string name;
  std::filesystem::path path;
  BrakeThermalParams<double> params;
  BrakeGeometry geometry;
};

/// Loads a brake file (`model: two_mass_disc_calliper`).
BrakeFile LoadBrakeFile(const std::filesystem::path& path);
/// The same with numbers of the file replaced before it is read (YamlReader::Load), each checked
/// as the file's own.
BrakeFile LoadBrakeFile(const std::filesystem::path& path,
                        const std::vector<YamlOverride>& overrides);

}  // namespace hotlap::brake
