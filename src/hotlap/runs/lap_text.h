#pragma once
/// @file
/// What `hotlap lap --method qss` prints of a run: its header line, then the laps, the last
/// lap's braking zones, each corner's peaks and wear, the last lap's means and energy audit per
/// corner (docs/lap-simulation.md, "Heat over a run") and a note where a tyre fell short.

#include <string>

#include "hotlap/runs/lap_run.h"

namespace hotlap::runs {

/// "hotlap lap: car '...' on ... (..., N points), N laps, quasi-steady-state\n".
std::string LapRunHeader(const vehicle::Car& car, const track::Track& track,
                         const LapRunOptions& options, const LapPlan& plan);

/// The tables of a finished run (every line ends in a newline).
std::string LapRunText(const LapRun& run, const vehicle::Car& car, int laps);

}  // namespace hotlap::runs
