#pragma once
/// @file
/// How the log fits treat a parameter they free, as a parameter set's field table records it
/// (tyre/tyre_thermal_fields.h, brake/brake_thermal_fields.h): its display name and unit, its
/// bounds and the floor of its scale. ident turns it into a FitParameter (channel_fit.h).

#include <string_view>

namespace hotlap {

/// The fit's view of one parameter, in the units of the parameter file.
struct FitHint {
  std::string_view label;  ///< short name for tables, e.g. "p2"
  std::string_view unit;   ///< for reports (may hold non-ASCII, e.g. "W/(m\u00b2 K)")
  double lower = 0.0;      ///< bounds of the fit
  double upper = 0.0;
  double scale_floor = 1.0;  ///< the fit's scale is max(|value|, scale_floor)
};

}  // namespace hotlap
