#pragma once
/// @file
/// The mesh check of an optimal lap: the same lap solved on a mesh of half the spacing, started
/// from the solution itself (its point and multipliers taken onto the finer mesh). The difference
/// of the two lap times is what the mesh leaves unresolved (`hotlap lap --method ocp
/// --mesh-check`, docs/optimal-control.md).

#include "hotlap/ocp/disc_limit_comparison.h"

namespace hotlap::ocp {

/// `solved` (a lap of `car` on `track` solved with `options`, e.g. by SolveLap) solved again on
/// half of options.step_m, with solved's front-disc limit, warm-started from solved's point and
/// multipliers (ResampleLapPoint, ResampleLapMultipliers) when solved converged, else from the
/// QSS guess. Labelled "half mesh". InputError as SolveLap.
SolvedLap SolveOnHalfMesh(const vehicle::Car& car, const track::Track& track,
                          OptimalLapOptions options, const SolvedLap& solved,
                          const LapProgress& progress = {}, const LapLog& log = {});

}  // namespace hotlap::ocp
