#pragma once
/// @file
/// Scenario comparisons of `hotlap abs --scenarios` (docs/abs.md): every surface of a
/// configuration braked to standstill with and without ABS, and a series of ABS stops heating
/// the brake disc.

#include <string>
#include <vector>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_run.h"

namespace hotlap::sim {

/// One stop of the comparison.
struct AbsComparisonRun {
  std::string surface;
  AbsControl control = AbsControl::kAbs;
  AbsRunResult run;
  AbsMetrics metrics;
};

/// Every surface of `config` (friction laws and surfaces, in file order), with ABS and with the
/// driver's pressure alone, from `base.initial_speed_mps` to standstill (free vehicle, at most
/// config.scenarios.max_duration_s). Pairs in order: surface 1 with ABS, surface 1 without, ...
std::vector<AbsComparisonRun> RunAbsComparison(const AbsConfig& config, const AbsEvent& base);

/// A series of ABS stops on config.scenarios.stop_series_surface, each from
/// `base.initial_speed_mps` to standstill, with config.scenarios.stop_series_interval_s of
/// driving at that speed between them (no braking: the brake cools by convection and radiation).
/// The disc and calliper temperatures carry over from stop to stop.
struct AbsStopSeries {
  std::vector<double> time;           ///< s, stops and cooling back to back
  std::vector<double> disc_temp;      ///< K
  std::vector<double> calliper_temp;  ///< K
  std::vector<double> stop_start_s;   ///< when each stop began
  std::vector<AbsMetrics> stops;      ///< the figures of each stop
};

/// Runs the series (config.scenarios.stop_series_count stops).
AbsStopSeries RunAbsStopSeries(const AbsConfig& config, const AbsEvent& base);

}  // namespace hotlap::sim
