#pragma once
/// @file
/// Loading brush-model and UniTire parameter files (YAML, units in the keys; see
/// data/tyres/brush_example.yaml, data/tyres/unitire_example.yaml and
/// docs/tyre-forces.md), and writing UniTire files (for fit results).
///
/// Files are read strictly: every key must be present and known, every value within its range;
/// any problem throws InputError naming the file, the field, the value and the allowed range.
/// Temperatures are degC in the files (`reference_temp_C`) and kelvin in the structs.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "hotlap/tyre/brush_model.h"
#include "hotlap/tyre/unitire.h"

namespace hotlap::tyre {

/// A brush-model file (`model: brush`) as loaded.
struct BrushParamsFile {
  std::string name;
  BrushParams<double> params;
};

/// A UniTire file (`model: unitire`) as loaded or to be written.
struct UniTireParamsFile {
  std::string name;
  UniTireParams<double> params;
};

/// Loads a brush-model file.
BrushParamsFile LoadBrushParams(const std::filesystem::path& path);

/// Loads a UniTire file.
UniTireParamsFile LoadUniTireParams(const std::filesystem::path& path);

/// Writes `file` as a UniTire file that LoadUniTireParams reads back to the same values (doubles
/// exactly; temperatures to rounding of the degC conversion), atomically (atomic_file.h).
/// `header_comment` (may span lines) opens the file as `#` comments; every value carries the
/// comment `# <source>`: `source_of(name)` with the field's name from kUniTireFieldNames (e.g.
/// "trail_temperature.decay") if given, else `value_source` (e.g. "fitted 2026-05-01 to rig run
/// 12"). Throws InputError if the file cannot be written, or if a value is outside the range the
/// loader accepts.
void WriteUniTireParams(const std::filesystem::path& path, const UniTireParamsFile& file,
                        std::string_view header_comment, std::string_view value_source = "fitted",
                        const std::function<std::string(std::string_view)>& source_of = {});

}  // namespace hotlap::tyre
