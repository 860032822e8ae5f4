#pragma once
// `hotlap optimise` for a car of model limebeer-2014-f1 (the 3-DOF F1 car of the fastest-lap
// peer benchmark, docs/f1-peer.md): one minimum-time solve, a channels CSV and a JSON summary.

#include <filesystem>

#include "optimal_runs.h"

namespace hotlap::app {

/// Solves the lap of the F1 car in `car_file` on args.track; writes <out>/optimal.csv and, with
/// --json, the summary. Returns 0, or 3 when the solve did not converge (its last point is still
/// written).
int RunF1Optimal(const OptimalArgs& args, const std::filesystem::path& car_file);

}  // namespace hotlap::app
