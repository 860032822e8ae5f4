#pragma once
/// @file
/// Perturbations far below any physical uncertainty that make the members of an FE ABS stop
/// ensemble differ (docs/fe-tyre.md, "ABS stop"): the stop is a threshold-controlled stick-slip
/// event whose single history depends on round-off after a few control cycles, so it is judged
/// by the statistics of many runs that differ by such perturbations.
///
///   sim::ApplyFePerturbation(sim::FePerturbation::kSpin, member, members, run);  // after Roll

#include <string>

#include "hotlap/fe/tyre_steps.h"

namespace hotlap::sim {

/// What differs between the members of an ensemble.
enum class FePerturbation {
  /// The rim's spin at the braking step's start times 1 + d, d spread evenly over
  /// [-1e-9, 1e-9] across the members (0 for a single member).
  kSpin,
  /// The order in which the rim's force and torque are summed over its nodes (member k starts
  /// at node k: fe::StepOptions::rim_sum_rotation); member 0 is the plain order.
  kSumOrder,
  /// Every node's velocity at the braking step's start moved by one rounding (a relative
  /// 2^-52, its sign drawn per member, node and axis): what another rounding in the element
  /// kernel does.
  kRoundOff,
};

/// The relative spin perturbation of kSpin.
inline constexpr double kSpinPerturbation = 1e-9;

/// "spin", "sum-order", "round-off".
const char* FePerturbationName(FePerturbation kind);
/// The kind a name gives; InputError naming `what` and the allowed names otherwise.
FePerturbation ParseFePerturbation(const std::string& name, const std::string& what);

/// Applies member `member`'s perturbation (0 <= member < members) to `run`, which has rolled
/// (TyreRun::Roll) and not yet braked.
void ApplyFePerturbation(FePerturbation kind, int member, int members, fe::TyreRun& run);

}  // namespace hotlap::sim
