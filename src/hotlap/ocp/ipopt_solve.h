#pragma once
/// @file
/// Solving an ElementNlp with Ipopt (Debian's coinor-libipopt-dev, MUMPS linear solver), exact
/// first and second derivatives, and a result that says in plain words how it ended.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/ocp/element_nlp.h"

namespace hotlap::ocp {

struct SolveResult;

struct IpoptOptions {
  double tolerance = 1e-7;             ///< Ipopt `tol` (scaled NLP error)
  double constraint_tolerance = 1e-7;  ///< Ipopt `constr_viol_tol`
  int max_iterations = 1000;
  double max_cpu_seconds = 600.0;
  int print_level = 0;  ///< Ipopt's own output, 0 = none
  /// Ipopt `alpha_for_y`: the step size for the equality multipliers ("primal", Ipopt's default,
  /// or e.g. "min-dual-infeas", which cuts the lap problem's iterations by a quarter).
  std::string alpha_for_y = "primal";
  /// Further Ipopt options by name (e.g. {"mumps_pivot_order", "5"}), the value as the option's
  /// type takes it (integer, number or text); an unknown name or a value it refuses is an
  /// InputError.
  std::vector<std::pair<std::string, std::string>> extra;
  /// Warm start: the bound and constraint multipliers of an earlier solve of a programme with the
  /// same variables and rows (SolveResult's, as Ipopt saw them). When all three have the right
  /// sizes, Ipopt starts from them and nlp's initial point with a small barrier parameter
  /// (`warm_start_init_point`), instead of pushing the start into the interior and restarting
  /// the barrier.
  std::vector<double> warm_z_lower, warm_z_upper, warm_lambda;
  /// The barrier parameter a warm start begins with.
  double warm_mu = 1e-6;
  /// A start point that is close to the solution but has no multipliers (coarse to fine): if > 0
  /// and there is no warm start, Ipopt's barrier begins at this mu and the point is pushed off its
  /// bounds by 1e-6 instead of Ipopt's 1e-2 (`bound_push`, `bound_frac`), so the first steps do
  /// not undo the start. 0 (or < 0): Ipopt's defaults. On the lap problem it can help or hurt:
  /// docs/validation/optimal-control.md, "Speed".
  double primal_start_mu = 0.0;
  /// Called at every iteration with (iteration, objective, primal infeasibility, dual
  /// infeasibility); return false to stop.
  std::function<bool(int, double, double, double)> on_iteration;
  /// Checkpoints: every `checkpoint_every` iterations (0: never; not in Ipopt's restoration
  /// phase), the current iterate goes to on_checkpoint as a SolveResult (status kStopped, x, the
  /// multipliers as finalize_solution gives them, `iterations`, `barrier_mu`), which a later solve
  /// of the same programme can warm-start from (warm_* above, warm_mu = its barrier_mu): a run
  /// killed part way loses at most this many iterations (ocp/stint.h, docs/reliability.md).
  int checkpoint_every = 0;
  std::function<void(const SolveResult&)> on_checkpoint;
};

/// How the solve ended.
enum class SolveStatus {
  kConverged,   ///< to the tolerance
  kAcceptable,  ///< to Ipopt's acceptable level only
  kInfeasible,  ///< the constraints cannot all hold (e.g. a limit too tight)
  kIterationLimit,
  kTimeLimit,
  kRestorationFailed,  ///< Ipopt lost feasibility and could not regain it
  kStopped,            ///< on_iteration returned false
  kNumericalTrouble,   ///< the step computation failed (e.g. non-finite values)
  kOther,
};

struct SolveResult {
  SolveStatus status = SolveStatus::kOther;
  std::string message;    ///< the status in plain words
  std::vector<double> x;  ///< the last (best) point, physical units
  /// Multipliers at x, of the scaled programme (for IpoptOptions' warm start).
  std::vector<double> z_lower, z_upper, lambda;
  double objective = 0.0;
  int iterations = 0;
  /// Iterations whose step needed a Hessian perturbation (Ipopt's inertia correction): each
  /// factorised the KKT system at least twice.
  int regularized_iterations = 0;
  double primal_infeasibility = 0.0;  ///< max |constraint violation| at x, scaled
  double dual_infeasibility = 0.0;
  double solve_seconds = 0.0;
  /// The barrier parameter at x (a checkpoint's, for the warm start that resumes from it).
  double barrier_mu = 0.0;

  bool ok() const {
    return status == SolveStatus::kConverged || status == SolveStatus::kAcceptable;
  }
};

/// Solves from nlp's initial point. `nlp` must be finalized. Never throws for a failed solve:
/// the status says what happened and x holds Ipopt's last iterate (an unusable option in
/// `options.extra` is an InputError, before any solving). So that MUMPS' SCOTCH ordering gives
/// the same solve bit for bit on every run, the first call sets SCOTCH_PTHREAD_NUMBER=1 in the
/// process environment (unless it is set) and every call resets SCOTCH's random state.
SolveResult SolveWithIpopt(const ElementNlp& nlp, const IpoptOptions& options);

}  // namespace hotlap::ocp
