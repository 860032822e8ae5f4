#pragma once
/// @file
/// The HTML report of `hotlap fe abs`: the braking event's histories in the layout of the FE/ABS
/// paper's Figures 8 to 11 (brake torque; forward and circumferential speeds; slip against the
/// 0.135 target; the road's longitudinal force with its slip), plus the energy balance.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/fe/tyre_steps.h"
#include "hotlap/sim/abs_metrics.h"

namespace hotlap::sim {

/// Writes the report to `path` (atomically), with the control cycles `cycles` (CalcCycleWindow
/// of the same history) in words. `loaded_radius_m` turns the rim
/// spin into the circumferential speed omega R_l (as the history CSV's omega_R_mps); `metadata`
/// lines go under the title. Throws InputError if the file cannot be written, std::invalid_argument
/// if the history is empty.
void WriteFeAbsReport(const std::filesystem::path& path, const std::vector<fe::HistoryRow>& history,
                      const CycleWindow& cycles, double loaded_radius_m,
                      const std::vector<std::pair<std::string, std::string>>& metadata);

}  // namespace hotlap::sim
