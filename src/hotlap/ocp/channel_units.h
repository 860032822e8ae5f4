#pragma once
/// @file
/// Channels converted for output (CSV columns, report charts): kelvin to degC, or times a factor
/// (rad to deg, W to kW).

#include <vector>

#include "hotlap/common/units.h"

namespace hotlap::ocp::internal {

inline std::vector<double> Celsius(std::vector<double> kelvin) {
  for (double& x : kelvin) x = KelvinToCelsius(x);
  return kelvin;
}

inline std::vector<double> Scaled(std::vector<double> v, double factor) {
  for (double& x : v) x *= factor;
  return v;
}

}  // namespace hotlap::ocp::internal
