#pragma once
/// @file
/// The field table of BrakeThermalParams<double>: for each member (each entry of the two
/// convection polynomials counted as one), the section and key it has in a brake file
/// (data/cars/gen7/brakes/), its unit, its allowed range, its conversion to SI and, for the
/// parameters the log fit frees, how the fit bounds and shows it. Every place that names a brake
/// thermal parameter by its file key (the reader, the synth overrides, the fit, the fitted car's
/// edits) reads this table, so each key is written once (issue 21, item 2).

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/fit_hint.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::brake {

/// One member of BrakeThermalParams<double> as the brake file holds it: a top-level number
/// (`member` set) or an entry of a convection polynomial (`polynomial` and `entry` set).
struct BrakeThermalField {
  std::string_view section;  ///< the file's map, e.g. "disc_convection_cholesky_sqrtW_per_K"; ""
                             ///< for a key at the top level of the file
  std::string_view key;      ///< the key in it, with its unit, e.g. "pad_area_mm2"
  double BrakeThermalParams<double>::*member = nullptr;
  ConvectionPolynomial<double> BrakeThermalParams<double>::*polynomial = nullptr;
  double ConvectionPolynomial<double>::*entry = nullptr;
  Range range;  ///< allowed file values, with the unit for messages ("mm^2")
  /// File value to SI (mm^2 to m^2, ...); nullptr where the file is SI already.
  double (*to_si)(double) = nullptr;
  /// Set for the parameters the log fit frees (and a parameter override file may set).
  const FitHint* fit = nullptr;

  /// "section.key", or "key" at the top level: as the fit's keys and the error messages name it.
  std::string Path() const;
  /// The member of `p` this entry describes.
  double& Of(BrakeThermalParams<double>& p) const {
    return member ? p.*member : (p.*polynomial).*entry;
  }
  double Of(const BrakeThermalParams<double>& p) const {
    return member ? p.*member : (p.*polynomial).*entry;
  }
};

/// Every member of BrakeThermalParams<double>, in file order: the top-level keys, then the disc's
/// and the calliper's convection polynomials (l11, l21, l22, l31, l32, l33 each), then the
/// `disc_bulk` section (read only with `disc_model: surface_bulk`). The file's `geometry` map
/// documents the part and is not part of the parameters (brake_params_io.cc).
std::span<const BrakeThermalField> BrakeThermalFields();

/// The sections of the table in file order, "" (the top level) first, `disc_bulk` last.
std::span<const std::string_view> BrakeThermalSections();

/// The section only a surface-and-bulk disc has.
inline constexpr std::string_view kDiscBulkSection = "disc_bulk";

/// The entries of one section, in file order.
std::vector<const BrakeThermalField*> BrakeThermalFieldsIn(std::string_view section);

/// The entries with a fit hint (gamma, xi, the twelve Cholesky entries), in file order, which is
/// the fit's order.
std::vector<const BrakeThermalField*> FittedBrakeThermalFields();

/// The entry at Path() `path`, or nullptr.
const BrakeThermalField* FindBrakeThermalField(std::string_view path);

}  // namespace hotlap::brake
