#pragma once
/// @file
/// The FE tyre's ABS stop as an ensemble (docs/fe-tyre.md, "ABS stop"): after the third control
/// cycle round-off alone moves the cycles as much as halving the step does, so one history of
/// this threshold-controlled stick-slip event says little; the statistics of N stops that differ
/// by perturbations far below any physical uncertainty (fe_perturbation.h) do converge.
///
///   fe::TyreRun run(config);  run.Inflate(h); run.Footprint(h); run.Roll(h);
///   sim::FeAbsEnsembleOptions o;  o.members = 16;  o.duration_s = 0.6;  o.threads = 2;
///   const sim::FeAbsEnsembleResult e = sim::RunFeAbsEnsemble(run, abs_config, o);
///   e.stats[k]   // the k-th figure of ListFeAbsFigures over the members
///
/// The steps before the braking are run once; each member copies the rolled run, is perturbed
/// and brakes on one thread; `threads` members run at once. The result does not depend on the
/// thread count (each member's run is the same bits on any).

#include <functional>
#include <string>
#include <vector>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/ensemble_stats.h"
#include "hotlap/abs/fe_abs_figures.h"
#include "hotlap/abs/fe_perturbation.h"
#include "hotlap/fe/tyre_steps.h"

namespace hotlap::sim {

struct FeAbsEnsembleOptions {
  int members = 16;
  FePerturbation perturbation = FePerturbation::kSpin;
  /// The members run are first_member .. first_member + members - 1 of the perturbation's
  /// sequence: a shard of a larger ensemble, whose members are the same bits as the larger
  /// ensemble's (its statistics are then those of the shards' members together). kSumOrder and
  /// kRoundOff only: a kSpin member's perturbation depends on the ensemble's size.
  int first_member = 0;
  int threads = 1;          ///< members run at once (each on one solver thread)
  double duration_s = 0.0;  ///< braking time of each member, s
  double history_interval_s = 1e-4;
  /// Called (from the thread that ran it, one call at a time) as each member ends, with its index
  /// in the sequence (from first_member); may be empty.
  std::function<void(int member, const FeAbsFigures& figures)> member_done;
};

/// A channel of the members' histories on the common clock: the members' mean and the smallest
/// and largest value at each row (the band the report draws).
struct EnsembleBand {
  std::vector<double> mean, min, max;
};

/// What the ensemble gave.
struct FeAbsEnsembleResult {
  FePerturbation perturbation = FePerturbation::kSpin;
  int first_member = 0;                  ///< the first member's index in the sequence
  std::vector<FeAbsFigures> members;     ///< each member's figures, in member order
  std::vector<std::string> keys, units;  ///< ListFeAbsFigures' names and units
  std::vector<EnsembleStat> stats;       ///< per key, over the members that have the figure
  std::vector<double> time_s;            ///< the band's clock (the histories' rows)
  EnsembleBand slip, vx_mps, omega_r_mps, torque_Nm;
  double slip_radius_m = 0.0;  ///< R_l of omega R_l
};

/// Refuses (InputError, naming --first-member) a shard the perturbation cannot make: a negative
/// first member, or one past 0 of kSpin (whose members depend on the ensemble's size).
void CheckFeEnsembleShard(FePerturbation perturbation, int first_member);

/// Runs the ensemble from `rolled` (a TyreRun after Roll; copied, not changed) with the ABS
/// controller of `abs`. Throws InputError for fewer than 1 member or threads, NumericalError if a
/// member's step fails (the first failure, after the running members end).
FeAbsEnsembleResult RunFeAbsEnsemble(const fe::TyreRun& rolled, const AbsConfig& abs,
                                     const FeAbsEnsembleOptions& options);

/// The statistic of figure `key` in `e` (InputError if there is none of that name).
const EnsembleStat& FindEnsembleStat(const FeAbsEnsembleResult& e, const std::string& key);

}  // namespace hotlap::sim
