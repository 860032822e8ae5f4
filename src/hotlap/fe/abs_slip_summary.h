#pragma once
/// @file
/// The FE braking step's slip in the FE/ABS paper's terms (002 Fig. 10): held "less than 0.135
/// for the most part" after the first control cycle.

#include <vector>

#include "hotlap/fe/tyre_steps.h"

namespace hotlap::fe {

/// The paper's slip target (002 §3.3, Fig. 10).
inline constexpr double kPaperSlipTarget = 0.135;

/// How well the braking step held the slip, in the paper's terms ("less than 0.135 for the most
/// part", 002 Fig. 10). The first control cycle ends when the slip, having exceeded 0.135, first
/// falls below a third of it (0.045): the wheel has spun back up. (The lumped `hotlap abs` ends it
/// at the controller's second pressure release, which the FE history does not carry.)
struct BrakeSlipSummary {
  double max_slip = 0.0;
  /// Time of the first cycle's end; NaN if the slip never exceeded 0.135 and fell back.
  double first_cycle_end_s = 0.0;
  /// From then to the end of the history: the largest slip and the share of time below 0.135;
  /// NaN without a first cycle end.
  double max_slip_after_first_cycle = 0.0;
  double fraction_time_below_0_135_after_first_cycle = 0.0;
};

/// The figures above from a braking step's history.
BrakeSlipSummary SummarizeBrakeSlip(const std::vector<HistoryRow>& history);

}  // namespace hotlap::fe
