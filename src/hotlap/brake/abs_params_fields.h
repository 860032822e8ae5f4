#pragma once
/// @file
/// The field tables of an ABS file's `controller:` and `hydraulics:` sections (docs/abs.md,
/// data/abs/paper.yaml): for each number its key (with the file's unit), the member it sets, the
/// allowed range and the conversion from the file's unit to SI. The readers (abs_params_io.h) loop
/// over them, so each key is written once, as the vehicle's and the thermal models' tables
/// (vehicle/vehicle_fields.h, tyre/tyre_thermal_fields.h) list theirs.

#include <span>
#include <string_view>

#include "hotlap/brake/abs_controller.h"
#include "hotlap/brake/brake_hydraulics.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::brake {

/// One number of the `controller:` section.
struct AbsControllerField {
  std::string_view key;  ///< with its unit, e.g. "decel_threshold_g"
  double AbsControllerParams::*member;
  Range range;  ///< allowed file values, with the unit for messages
  /// File value to SI (g to m/s^2, MPa to Pa); nullptr where the file is SI.
  double (*to_si)(double) = nullptr;
  /// A step or timer acting at controller ticks: the range's lower end is the period (read first).
  bool at_least_a_period = false;

  /// The range a file's value must lie in, given the period already read.
  Range RangeGiven(double period_s) const;
  double ToSi(double file_value) const { return to_si ? to_si(file_value) : file_value; }
};

/// Every number of the `controller:` section, in file order (`period_s` first). The wheel's
/// radius is not among them: it is the wheel's loaded radius, read once with the wheel.
std::span<const AbsControllerField> AbsControllerFields();

/// One number of the `hydraulics:` section.
struct BrakeHydraulicsField {
  std::string_view key;  ///< with its unit, e.g. "max_rise_rate_MPa_per_s"
  double BrakeHydraulicsParams<double>::*member;
  Range range;
  double (*to_si)(double) = nullptr;  ///< file value to SI (MPa to Pa); nullptr where SI

  double ToSi(double file_value) const { return to_si ? to_si(file_value) : file_value; }
};

/// Every number of the `hydraulics:` section, in file order.
std::span<const BrakeHydraulicsField> BrakeHydraulicsFields();

}  // namespace hotlap::brake
