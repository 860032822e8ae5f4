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
#include <optional>
#include <string>

#include "hotlap/vehicle/car.h"

namespace hotlap::sim {

/// Tyre values to override; unset ones keep the car's.
struct TyreOverrides {
  std::optional<double> p1, p2, p3, p4, p5;         ///< heat_generation
  std::optional<double> wear_coeff, wear_exponent;  ///< wear: wp1 (mm/s), wp2
  std::optional<double> contact_length_coeff;       ///< contact_length: p_cp1
  std::optional<double> contact_length_exponent;    ///< contact_length: p_cp2
};

/// Cholesky entries l11, l21, l22, l31, l32, l33, sqrt(W/K).
using CholeskyOverrides = std::array<std::optional<double>, 6>;

/// Brake values to override; unset ones keep the car's.
struct BrakeOverrides {
  std::optional<double> heat_partition, mass_participation;
  CholeskyOverrides disc_convection, calliper_convection;
};

struct ParameterOverrides {
  std::string name;
  std::filesystem::path path;
  std::array<TyreOverrides, 4> tyres;    ///< by CornerIndex
  std::array<BrakeOverrides, 4> brakes;  ///< by CornerIndex
};

/// Loads an override file; InputError naming the file, key, value and range on any problem.
ParameterOverrides LoadParameterOverrides(const std::filesystem::path& path);

/// Applies the overrides to the car's tyre and brake parameters (corners sharing a file get their
/// own copies, as the car holds one per corner).
void ApplyParameterOverrides(const ParameterOverrides& overrides, vehicle::Car& car);

}  // namespace hotlap::sim
