#pragma once
/// @file
/// What `hotlap fe` writes for each step (docs/fe-tyre.md, "Outputs"): the history CSV, the
/// footprint pressure map (CSV and SVG), and each step's part of the JSON summary.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/fe/tyre_steps.h"
#include "hotlap/sim/fe_abs_stop.h"

namespace hotlap::app {

/// The history CSV of one step; omega_R_mps uses `loaded_radius` (0 before rolling).
void WriteFeHistoryCsv(const std::filesystem::path& path, const std::string& step,
                       const fe::FeConfig& config, const std::vector<fe::HistoryRow>& history,
                       double loaded_radius);

/// footprint_pressure.csv and footprint_pressure.svg (one disc per contact node, coloured by
/// pressure) in `out`.
void WriteFootprintPressure(const std::filesystem::path& out, const fe::FeConfig& config,
                            const fe::FootprintResult& footprint);

/// The energies' JSON (J, and the hourglass over the internal energy).
nlohmann::json FeEnergiesJson(const fe::Energies& energies);

/// Each step's JSON, with the energies at its end. A cord strain above kCordStrainAllowance is
/// warned about on stderr, naming the step.
nlohmann::json InflateJson(const fe::InflateResult& r, const fe::Energies& energies);
nlohmann::json FootprintJson(const fe::FootprintResult& r, const fe::Energies& energies);
nlohmann::json RollJson(const fe::RollResult& r, const fe::Energies& energies);
nlohmann::json AbsStopJson(const sim::FeAbsStopResult& r, double duration_s,
                           const fe::Energies& energies);

}  // namespace hotlap::app
