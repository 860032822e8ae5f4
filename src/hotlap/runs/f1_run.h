#pragma once
/// @file
/// The optimal lap of the limebeer-2014-f1 car (docs/f1-peer.md) as `hotlap optimise` runs it:
/// what the planar model cannot take (overrides, a disc limit), the warning for a track that
/// banks or climbs, and Ipopt's options from the run's.

#include <string>

#include "hotlap/ocp/f1_lap_problem.h"
#include "hotlap/ocp/optimal_run.h"
#include "hotlap/track/track.h"

namespace hotlap::runs {

/// InputError if the run asks the F1 car for what it does not have: car overrides (no dotted
/// keys) or a disc limit (no brake temperatures). `car` names the car in the message.
void CheckF1Run(const std::string& car, bool overrides, const ocp::OptimalRunOptions& run);

/// A warning where the track banks or climbs (over 1 mrad anywhere, sampled every 5 m), which
/// the planar model ignores; "" on a flat track.
std::string PlanarTrackWarning(const track::Track& track);

/// The F1 solve's Ipopt options with the run's iteration limit, extra options and Ipopt output.
ocp::IpoptOptions F1RunIpoptOptions(const ocp::OptimalRunOptions& run);

}  // namespace hotlap::runs
