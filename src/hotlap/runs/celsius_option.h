#pragma once
/// @file
/// A temperature option given in degC, or not given, in kelvin.

#include <optional>

#include "hotlap/common/units.h"

namespace hotlap::runs {

/// `celsius` in kelvin; nullopt where it was not given.
inline std::optional<double> KelvinOf(const std::optional<double>& celsius) {
  if (!celsius) return std::nullopt;
  return CelsiusToKelvin(*celsius);
}

}  // namespace hotlap::runs
