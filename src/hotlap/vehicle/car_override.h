#pragma once
/// @file
/// Car parameters overridden by their dotted keys (`--set KEY=VALUE`, hotlap.load_car's
/// overrides; docs/overrides.md): a set-up sweep's case is the car with some values changed.
///
/// A key is the car file's dotted path to a number (`chassis.mass_kg`,
/// `brake_system.front_share`, `tyre_forces.rr.pressure_kPa`, `initial_state.disc_temp_C`), or
/// a number of the brake or tyre thermal file a corner names, reached through that corner
/// (`brakes.fl.heat_partition`, `brakes.fl.disc_convection_cholesky_sqrtW_per_K.l33`,
/// `tyres.rr.construction.tread_mass_kg`), or a derived key (`brakes.<c>.duct_factor`). A value is
/// in the key's own unit and is checked as the file's own value is (LoadCar reads the files with
/// the overrides in place, YamlReader::Load). Corners that share a file get their own values.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/common/yaml_reader.h"

namespace hotlap::vehicle {

/// One car parameter and its new value, in the key's own unit.
struct CarOverride {
  std::string key;  ///< dotted key, e.g. "brakes.fl.duct_factor"
  double value = 0.0;
};

/// The derived key of each corner's brake: multiplies the disc's and the calliper's convective
/// conductance hA = z' P z by the factor (P = L L', every Cholesky entry of L times its square
/// root); > 0.
inline constexpr std::string_view kDuctFactorKey = "duct_factor";

/// "KEY=VALUE" as the command line gives it; InputError without '=', with an empty key, or with a
/// value that is not a finite number (read as the parameter files read numbers).
CarOverride ParseCarOverride(std::string_view text);
/// Each of `texts` as ParseCarOverride reads it, in order.
std::vector<CarOverride> ParseCarOverrides(const std::vector<std::string>& texts);

/// "key=value" (the value's shortest exact text), as messages and summaries name an override.
std::string OverrideText(const CarOverride& o);

/// Every key an override of the car at `path` (a car.yaml) may name, in file order: the car
/// file's numbers, then in place of each corner's tyre and brake file names the numbers of that
/// file (`tyres.<c>.`, `brakes.<c>.` before the file's own dotted path) and the derived keys;
/// then the optional numbers the files leave out, which an override adds (found by reading the
/// car with a YamlOptionalNumberProbe: e.g. `tyre_forces.<c>.rolling_radius_m` where a .tir file
/// gives the radius). InputError if the car file cannot be read; a tyre or brake file that cannot be read gives no
/// keys (LoadCar reports it).
std::vector<std::string> OverrideKeys(const std::filesystem::path& path);

/// The summaries' record of the overrides: {key: value}, {} when there are none.
nlohmann::json OverridesJson(const std::vector<CarOverride>& overrides);
/// "key=value, key=value" for reports.
std::string OverridesText(const std::vector<CarOverride>& overrides);

/// What LoadCar does with the overrides of the car at `path`: the numbers to replace in the car
/// file and in each corner's tyre and brake files (fields as those files name them), and each
/// corner's duct factor.
struct CarOverridePlan {
  std::vector<YamlOverride> car;
  std::array<std::vector<YamlOverride>, 4> tyres;   ///< by CornerIndex
  std::array<std::vector<YamlOverride>, 4> brakes;  ///< by CornerIndex
  std::array<std::optional<double>, 4> duct_factor;
};

/// Checks every override against the car's keys and sorts them by file. InputError naming the
/// override for a key given twice, a corner that is not fl, fr, rl or rr, a key that names text
/// (a file name, a model) or a section rather than a number, an unknown key (which part of it is
/// unknown, and the closest valid keys), or a derived key's value out of its range. Values of the
/// files' own keys are checked when the files are read.
CarOverridePlan PlanCarOverrides(const std::filesystem::path& path,
                                 const std::vector<CarOverride>& overrides);

}  // namespace hotlap::vehicle
