#pragma once
/// @file
/// Parameter override files (`model: parameter_overrides`): per-corner values of the fitted tyre,
/// wear, contact-length and brake parameters that replace a car's, for `hotlap synth --params`
/// (the "true" parameters of a synthetic log) and `hotlap fit --truth` (docs/fitting.md).
///
/// Format: under `corners:`, any of fl, fr, rl, rr; under each, `tyre:` and/or `brake:` holding
/// any subset of the fitted keys of a tyre file (`heat_generation`, `wear`, `contact_length`
/// sections) or a brake file (`heat_partition`, `mass_participation`, and the two
/// `*_convection_cholesky_sqrtW_per_K` maps), with the same names, units and ranges:
///
///   name: truth-plus-50pct
///   model: parameter_overrides
///   corners:
///     fr:
///       tyre:
///         heat_generation: {p1: 0.426, p5_W_per_m2K: 226.05}   # 000 Table 4 x 1.5
///       brake:
///         heat_partition: 0.475                                 # assumed 0.95 x 0.5
///
/// Loading is strict: an unknown key (or a key with another unit) is an error.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/tyre/tyre_thermal_fields.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// One value to override: the field table's entry it sets and its value in the file's unit.
template <class Field>
struct Override {
  const Field* field = nullptr;
  double value = 0.0;
};

/// One corner's values to override, in file order; the parameters not listed keep the car's.
struct CornerOverrides {
  std::vector<Override<tyre::TyreThermalField>> tyre;     ///< fitted entries of the tyre table
  std::vector<Override<brake::BrakeThermalField>> brake;  ///< fitted entries of the brake table
};

/// An override file as loaded.
struct ParameterOverrides {
  std::string name;
  std::filesystem::path path;
  std::array<CornerOverrides, 4> corners;  ///< by CornerIndex
};

/// Loads an override file; InputError naming the file, key, value and range on any problem.
ParameterOverrides LoadParameterOverrides(const std::filesystem::path& path);

/// Applies the overrides to the car's tyre and brake parameters (corners sharing a file get their
/// own copies, as the car holds one per corner).
void ApplyParameterOverrides(const ParameterOverrides& overrides, vehicle::Car& car);

}  // namespace hotlap::sim
