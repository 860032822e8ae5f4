#pragma once
/// @file
/// The FE braking step's slip in the FE/ABS paper's terms (002 Fig. 10): held "less than 0.135
/// for the most part" after the first control cycle, with the cycles counted as the lumped
/// `hotlap abs` counts them (sim/abs_metrics.h): a cycle begins where the controller releases
/// pressure, and the first cycle ends where the second begins.

#include <span>
#include <vector>

#include "hotlap/fe/tyre_steps.h"

namespace hotlap::fe {

/// The paper's slip target (002 §3.3, Fig. 10).
inline constexpr double kPaperSlipTarget = 0.135;

struct BrakeSlipSummary {
  double max_slip = 0.0;  ///< over the whole history
  int cycles = 0;         ///< control cycles begun
  /// cycles / (end of the history - first cycle's start); 0 without cycles.
  double cycles_per_s = 0.0;
  /// The second cycle's start (the first cycle's end), s; NaN with fewer than two cycles.
  double first_cycle_end_s = 0.0;
  /// From the first cycle's end to the end of the history: the largest slip and the share of
  /// time (each history interval weighted by its length, at its first row's slip) below 0.135;
  /// NaN with fewer than two cycles.
  double max_slip_after_first_cycle = 0.0;
  double fraction_time_below_0_135_after_first_cycle = 0.0;
};

/// The figures above from a braking step's history and the times (the history's clock, s,
/// increasing) at which the controller began each cycle.
BrakeSlipSummary SummarizeBrakeSlip(const std::vector<HistoryRow>& history,
                                    std::span<const double> cycle_starts_s);

}  // namespace hotlap::fe
