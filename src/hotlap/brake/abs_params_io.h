#pragma once
/// @file
/// Reading the `controller:` and `hydraulics:` sections of an ABS configuration file
/// (docs/abs.md, data/abs/paper.yaml). Strict, units in the keys; any problem throws InputError
/// naming the file, the field, the value and the allowed range.

#include "hotlap/brake/abs_controller.h"
#include "hotlap/brake/brake_hydraulics.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::brake {

/// Reads the `controller:` mapping (calls its Finish()). `wheel_radius_m` is not in this section
/// (it is the wheel's loaded radius, read once with the wheel) and is left at 0 for the caller.
AbsControllerParams ReadAbsControllerParams(YamlReader& section);

/// Reads the `hydraulics:` mapping (calls its Finish()). Pressures are in MPa in the file.
BrakeHydraulicsParams<double> ReadBrakeHydraulicsParams(YamlReader& section);

}  // namespace hotlap::brake
