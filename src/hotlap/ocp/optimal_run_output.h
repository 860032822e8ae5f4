#pragma once
/// @file
/// The files of an optimal-lap run (docs/optimal-control.md): each lap's channels as CSV in the
/// shared format, and the HTML page that overlays the laps.

#include <filesystem>
#include <vector>

#include "hotlap/ocp/disc_limit_comparison.h"
#include "hotlap/track/track.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ocp {

/// One lap's channels (OptimalLapColumns) as CSV, with the source, track, car, disc limit and
/// solver status as metadata; written atomically.
void WriteSolvedLapCsv(const std::filesystem::path& path, const SolvedLap& lap,
                       const track::Track& track, const vehicle::Car& car);

/// Creates the folder `out` and writes optimal.csv (one lap) or unconstrained.csv and
/// constrained.csv (the comparison), then optimal.html or compare.html: the runs' table and
/// AddOptimalLapCharts (`step_m`, the mesh spacing, is named). Returns the paths in that order.
std::vector<std::filesystem::path> WriteOptimalRunFiles(const std::filesystem::path& out,
                                                        const std::vector<SolvedLap>& laps,
                                                        const vehicle::Car& car,
                                                        const track::Track& track, double step_m);

}  // namespace hotlap::ocp
