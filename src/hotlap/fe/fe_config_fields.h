#pragma once
/// @file
/// The field tables of a finite-element tyre file (data/fe/*.yaml, fe_config.h): every number and
/// whole-number count with its section, key (with the file's unit), allowed range and conversion
/// to SI; the rubber regions and the cords with the numbers each holds; the cords' responses. The
/// reader (fe_config.cc) loops over them, so each key is written once, as the ABS file's
/// (brake/abs_params_fields.h) and the vehicle's tables list theirs.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/common/yaml_reader.h"
#include "hotlap/fe/fe_config.h"

namespace hotlap::fe {

/// One number (or count) of the file outside the rubber and cord lists.
struct FeConfigField {
  std::string_view section;  ///< the file's map ("tyre", "mesh", ...); empty for the top level
  std::string_view key;      ///< the key in it, with its unit, e.g. "section_width_mm"
  Range range;               ///< allowed file values, with the unit for messages
  double to_si = 1.0;        ///< file value times this is SI (mm to m: 1e-3)
  double& (*number)(FeConfig&) = nullptr;  ///< the member it sets, for a number
  int& (*count)(FeConfig&) = nullptr;      ///< the member it sets, for a whole-number count

  /// "section.key" (the key alone at the top level), as messages and overrides name it.
  std::string Path() const;
  bool IsCount() const { return count != nullptr; }
  /// The member's value in SI (a count as a number).
  double Of(const FeConfig& c) const;
};

/// Every number and count of the file but those of the rubber regions and cords, in file order:
/// sections tyre, profile, mesh, the top-level bulk_to_shear_ratio, solver, road, rim, inflate,
/// footprint, roll, abs, output.
std::span<const FeConfigField> FeConfigFields();

/// The entries of one section ("" for the top level), in file order.
std::vector<const FeConfigField*> FeConfigFieldsIn(std::string_view section);

/// The rubber regions under `rubber:`, in TyreRegion order (002 Table 1).
std::span<const std::string_view> FeRubberRegions();

/// One number of a rubber region (a Yeoh material).
struct FeRubberField {
  std::string_view key;  ///< e.g. "c10_Pa"
  double YeohMaterial::*member;
  Range range;
};

/// The numbers each rubber region holds, in file order (the bulk modulus is not among them: it
/// is bulk_to_shear_ratio times the initial shear modulus).
std::span<const FeRubberField> FeRubberFields();

/// The cords under `cords:`, in TyreCord order (002 Tables 2-3).
std::span<const std::string_view> FeCordNames();

/// One number of a cord's rebar.
struct FeCordField {
  std::string_view key;  ///< e.g. "youngs_modulus_Pa"
  double RebarMaterial::*member;
  Range range;
  /// False for the layout numbers (area, spacing, angle): 002 Table 3 has no bead row, the bead
  /// is circumferential wire.
  bool bead_has_it = true;
};

/// The numbers each cord holds, in file order.
std::span<const FeCordField> FeCordFields();

/// The cords' `response` choices, in FibreResponse order ("tension_only", "linear").
std::span<const std::string_view> FeCordResponses();

}  // namespace hotlap::fe
