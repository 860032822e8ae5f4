#pragma once
/// @file
/// The files `hotlap fe` writes for each step of the finite-element tyre (docs/fe-tyre.md,
/// "Outputs"): the history CSV and the footprint pressure map (CSV and SVG).

#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/fe/tyre_steps.h"

namespace hotlap::fe {

/// The history CSV of one step (rim motion, spin, brake torque, road forces, slip, energies);
/// omega_R_mps uses `loaded_radius` (0 before rolling). Written atomically.
void WriteFeHistoryCsv(const std::filesystem::path& path, const std::string& step,
                       const FeConfig& config, const std::vector<HistoryRow>& history,
                       double loaded_radius);

/// footprint_pressure.csv and footprint_pressure.svg (one disc per contact node, coloured by
/// pressure) in the folder `out`.
void WriteFootprintPressure(const std::filesystem::path& out, const FeConfig& config,
                            const FootprintResult& footprint);

}  // namespace hotlap::fe
