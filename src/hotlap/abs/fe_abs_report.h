#pragma once
/// @file
/// The HTML report of `hotlap fe abs`: the braking event's histories in the layout of the FE/ABS
/// paper's Figures 8 to 11 (brake torque; forward and circumferential speeds; slip against the
/// 0.135 target; the road's longitudinal force with its slip), plus the energy balance.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_run.h"
#include "hotlap/fe/tyre_steps.h"

namespace hotlap::sim {

/// A lumped `hotlap abs` run of the same event (speed and duration), drawn beside the FE tyre's:
/// its history, its cycles, its R_l and its label in the legends and the text ("lumped, same ABS
/// file" for the FE file's controller and hydraulics; "lumped, own tuning" for the lumped quarter
/// car's own file, `abs.lumped_config_file`).
struct FeAbsLumpedRun {
  const AbsHistory* history = nullptr;
  CycleWindow cycles;
  double loaded_radius_m = 0.0;
  std::string label = "lumped";
};

/// Writes the report to `path` (atomically), with the control cycles `cycles` (CalcCycleWindow
/// of the same history) in words. `loaded_radius_m` turns the rim
/// spin into the circumferential speed omega R_l (as the history CSV's omega_R_mps); `metadata`
/// lines go under the title. Each chart draws the `lumped` runs too, dotted (their time from the
/// FE braking step's start; their torque with the FE history's sign), and the text compares the
/// cycles with each. Throws InputError if the file cannot be written, std::invalid_argument if the
/// history is empty.
void WriteFeAbsReport(const std::filesystem::path& path, const std::vector<fe::HistoryRow>& history,
                      const CycleWindow& cycles, double loaded_radius_m,
                      const std::vector<std::pair<std::string, std::string>>& metadata,
                      const std::vector<FeAbsLumpedRun>& lumped = {});

}  // namespace hotlap::sim
