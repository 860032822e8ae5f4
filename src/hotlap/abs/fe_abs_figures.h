#pragma once
/// @file
/// The figures of one FE ABS stop that an ensemble judges (docs/fe-tyre.md, "ABS stop"): how
/// well the slip was held after the first control cycle, how often the controller cycled, when
/// it first released, and how the wheel stopped. An ensemble (fe_abs_ensemble.h) takes each
/// figure's mean, standard error and spread over its members.

#include <optional>
#include <string>
#include <vector>

#include "hotlap/abs/fe_abs_stop.h"

namespace hotlap::sim {

/// One stop's figures; times from the braking step's start. The window after the first cycle is
/// CycleWindow's: from the second cycle's start to the ABS exit or the end.
struct FeAbsFigures {
  /// Share of the window with slip < kPaperSlipLimit (none with fewer than two cycles).
  std::optional<double> fraction_below_0_135;
  std::optional<double> slip_p99;   ///< 99th percentile of the slip rows in the window
  std::optional<double> slip_mean;  ///< mean of the slip rows in the window
  std::optional<double> slip_max;   ///< largest slip row in the window
  double cycles_per_s = 0.0;        ///< CycleWindow::cycles_per_s
  int cycles = 0;
  std::optional<double> first_release_s;  ///< the first cycle's start
  double distance_m = 0.0;                ///< travelled over the stop
  double mean_deceleration_mps2 = 0.0;    ///< (Vx at the start - at the end) / duration
};

/// The figures of `r`, a stop of `duration_s` (FeAbsStop::Run).
FeAbsFigures CalcFeAbsFigures(const FeAbsStopResult& r, double duration_s);

/// The figures by name, in the order the JSON and the report list them: a name, a unit ("" for
/// none) and the value (none where the stop had none).
struct FeAbsFigureValue {
  std::string key;
  std::string unit;
  std::optional<double> value;
};
std::vector<FeAbsFigureValue> ListFeAbsFigures(const FeAbsFigures& f);

}  // namespace hotlap::sim
