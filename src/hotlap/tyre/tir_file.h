#pragma once
/// @file
/// Reading and writing Magic Formula tyre property files (`.tir`, the TNO / MSC ADAMS format).
///
/// The format: `[SECTION]` headers; `KEY = value` lines, where a value is a number or a string in
/// single quotes; comments start with `$` or `!` (a whole line, or the rest of a line outside
/// quotes). Keys and section names are case-insensitive. Some sections ([SHAPE],
/// [DEFLECTION_LOAD_CURVE], ...) hold tables: a `{column names}` line and rows of numbers; they are
/// skipped, as mfeval skips them.
///
/// How to use: `ReadTirFile(path).params` are the coefficients, in SI units, ready for
/// CalcMagicFormula (or use LoadMagicFormula in magic_formula.h). WriteTirFile writes
/// coefficients back, for example after a fit.
///
/// Version (FITTYP in [MODEL]): 61 is MF 6.1, 62 is MF 6.2, and 6 and 21 are MF 5.2, as mfeval
/// reads them. Two additions: FITTYP 5 (MF-Tyre 5.0/5.1, e.g. Chrono's 335/65R22.5 file) is read
/// as MF 5.2, whose equations those files were written for (mfeval would apply the 6.1 equations
/// to it); and a file with no FITTYP whose PROPERTY_FILE_FORMAT is 'PAC2002' (MSC ADAMS's
/// implementation of MF 5.2, e.g. Chrono's HMMWV and sedan files) is MF 5.2. Any other FITTYP, or
/// no FITTYP in another kind of file, is an error.
///
/// Units ([UNITS]): LENGTH, FORCE, ANGLE, MASS, TIME and the optional PRESSURE (default
/// FORCE/LENGTH^2) are read and every dimensional value converted to SI (see TirQuantity); for
/// example 'mm', 'kN' and 'deg' work. Magic Formula coefficients are dimensionless and are never
/// converted.
///
/// As real tools write them: a key with an empty value (`ROAD_INCREMENT =`, `WIDTH =  $ note`)
/// is absent, as MF-Tyre and mfeval take it (the default is used; TirFile::warnings lists all
/// such keys in one warning); sections may come in any order; a key that is neither a
/// coefficient nor a known key of the format is kept and listed in one warning, not refused.
///
/// Pitfalls: PAC2002 files give the pressures as IP and IP_NOM in [TIRE_CONDITIONS]; they are read
/// as INFLPRES and NOMPRES when those are absent (mfeval ignores them; the forces are the same
/// because PAC2002 has no pressure terms). Keys this reader does not use (inertia, structural,
/// turn slip, ...) are kept in TirFile::entries but not in the coefficients, so WriteTirFile does
/// not write them.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/tyre/magic_formula_params.h"

namespace hotlap::tyre {

/// One `KEY = value` line as written.
struct TirEntry {
  std::string section;  ///< upper case, without brackets; "" before the first section
  std::string key;      ///< upper case
  std::string value;    ///< as written, without quotes and comment; in the file's units
  bool quoted = false;  ///< the value was a quoted string
  int line = 0;         ///< 1-based line number
};

/// The file's units as factors to SI: SI value = file value * factor.
struct TirUnits {
  double length = 1.0;    ///< m per LENGTH unit
  double force = 1.0;     ///< N per FORCE unit
  double angle = 1.0;     ///< rad per ANGLE unit
  double mass = 1.0;      ///< kg per MASS unit
  double time = 1.0;      ///< s per TIME unit
  double pressure = 1.0;  ///< Pa per PRESSURE unit (FORCE/LENGTH^2 when the file has none)

  /// The factor for one quantity.
  double ToSi(TirQuantity quantity) const;
};

/// A parsed `.tir` file.
struct TirFile {
  std::filesystem::path path;
  int fittyp = 0;                    ///< FITTYP as written; 0 when absent
  std::string property_file_format;  ///< PROPERTY_FILE_FORMAT as written (may be empty)
  TirUnits units;
  std::vector<TirEntry> entries;       ///< every `KEY = value` line, in file order
  MagicFormulaParams<double> params;   ///< coefficients in SI; defaults where the file has none
  std::vector<std::string> defaulted;  ///< coefficients the file did not give
  /// At most two: the keys written without a value (`WIDTH =`), which are taken as absent, and
  /// the keys neither a coefficient nor a known key of the format (e.g. a misspelt coefficient).
  std::vector<std::string> warnings;

  /// The last entry with this key (case-insensitive), or nullptr.
  const TirEntry* Find(std::string_view key) const;
};

/// Reads and parses `path`. InputError "FILE:LINE: ..." for a line that is not a section, a
/// comment, a table row or `KEY = value`, for a coefficient that is not a number or is given
/// twice, for an unknown unit, and for a missing or unsupported FITTYP; "cannot read 'FILE': ..."
/// when the file cannot be read.
TirFile ReadTirFile(const std::filesystem::path& path);

/// Parses `text` as the contents of a `.tir` file; `path` names it in messages.
TirFile ParseTirFile(std::string_view text, const std::filesystem::path& path);

/// The `.tir` text for `params`: SI units, FITTYP 6 (MF 5.2), 61 or 62, every coefficient of
/// MagicFormulaParams with its description, numbers written so that they read back exactly.
/// `comment` (several lines allowed) is written near the top as `!` comment lines, e.g. where the
/// coefficients came from.
std::string FormatTirFile(const MagicFormulaParams<double>& params, std::string_view comment = {});

/// Writes FormatTirFile(params, comment) to `path` atomically (see WriteFileAtomically).
/// InputError when the file cannot be written.
void WriteTirFile(const std::filesystem::path& path, const MagicFormulaParams<double>& params,
                  std::string_view comment = {});

}  // namespace hotlap::tyre
