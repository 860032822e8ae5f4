#pragma once
/// @file
/// The field table of TyreThermalParams<double>: for each member, the section and key it has in a
/// tyre file (data/cars/gen7/tyres/), its unit, its allowed range and, for the parameters the log
/// fits free, how the fits bound and show it. Every place that names a tyre thermal parameter by
/// its file key (the reader, the synth overrides, the fits, the fitted car's edits) reads this
/// table, so each key is written once (issue 21, item 2; in the style of magic_formula_params.h's
/// table of the `.tir` coefficients).

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/common/fit_hint.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/tyre/tyre_thermal.h"

namespace hotlap::tyre {

/// One member of TyreThermalParams<double> as the tyre file holds it.
struct TyreThermalField {
  std::string_view section;  ///< the file's map, e.g. "heat_generation"
  std::string_view key;      ///< the key in it, with its unit, e.g. "p2_J_per_kgN"
  double TyreThermalParams<double>::*member;
  Range range;  ///< allowed file values, with the unit for messages ("J/(kg N)")
  /// File value to SI (degrees to radians); nullptr where the file is SI already.
  double (*to_si)(double) = nullptr;
  /// Set for the parameters a log fit frees (and a parameter override file may set).
  const FitHint* fit = nullptr;

  /// "section.key", as the fitted car's edits and error messages name it.
  std::string Path() const;
  /// The member of `p` this entry describes.
  double& Of(TyreThermalParams<double>& p) const { return p.*member; }
  double Of(const TyreThermalParams<double>& p) const { return p.*member; }
};

/// Every member of TyreThermalParams<double> (but `smoothing`, `model` and `cold_pressure`, which
/// the tyre file does not hold: the cold pressure is the car's tyre_forces.<c>.pressure_kPa), in
/// file order: sections heat_generation, wear, contact_length, construction, then the gas-and-rim
/// model's hysteresis, gas and rim.
std::span<const TyreThermalField> TyreThermalFields();

/// The sections of the table, in file order.
std::span<const std::string_view> TyreThermalSections();

/// True for the sections only the gas-and-rim model reads (hysteresis, gas, rim).
bool IsGasRimSection(std::string_view section);

/// The entries of one section, in file order.
std::vector<const TyreThermalField*> TyreThermalFieldsIn(std::string_view section);

/// The entries with a fit hint (p1..p5, wp1, wp2, p_cp1, p_cp2, and the gas path's carcass-gas,
/// gas-rim and rim-air conductances), in file order; with `section`
/// given, only those of that section.
std::vector<const TyreThermalField*> FittedTyreThermalFields(std::string_view section = {});

/// The entry at "section.key", or nullptr.
const TyreThermalField* FindTyreThermalField(std::string_view path);

}  // namespace hotlap::tyre
