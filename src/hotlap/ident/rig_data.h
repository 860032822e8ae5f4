#pragma once
/// @file
/// Tyre-rig measurements in the shared CSV format: one steady-state point per row, units in the
/// column names, converted to SI on read.
///
/// Columns (docs/tyre-forces.md): required `slip_angle_deg`, `fz_N`, `fy_N`, `mz_Nm`,
/// `tread_temp_C`; optional `slip_ratio`, `fx_N`, `camber_deg`, `speed_mps`. Other units are
/// accepted where they are unambiguous: `_rad` for angles, `_kN` for forces, `_kNm` for moments,
/// `_K` for the temperature, `_kph` for the speed. Unknown columns are an error (a misspelt
/// optional column would otherwise be silently ignored).

#include <filesystem>
#include <vector>

#include "hotlap/ident/unitire_fit.h"

namespace hotlap::ident {

/// Reads rig samples. InputError naming the file (and line and column where it applies) for a
/// missing required column, an unknown column or unit, an empty cell in a required column, a load
/// that is not positive, or any CSV error of ReadCsv. Missing optional columns default to zero
/// slip ratio, zero camber and kRigSpeed; an empty `fx` cell means Fx was not measured there.
std::vector<RigSample> ReadRigCsv(const std::filesystem::path& path);

/// Writes rig samples in the canonical units (degrees, N, N m, degC, m/s), atomically, with the
/// given `# key: value` metadata. Writes `fx_N` only if some sample has fx.
void WriteRigCsv(const std::filesystem::path& path,
                 const std::vector<std::pair<std::string, std::string>>& metadata,
                 const std::vector<RigSample>& samples);

}  // namespace hotlap::ident
