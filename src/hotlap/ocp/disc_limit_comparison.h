#pragma once
/// @file
/// The NASCAR paper's comparison (000 section 4) as a library call: the minimum-time lap without
/// and with a limit on the front disc temperatures, each with its figures and its lift and brake
/// points. `hotlap lap --method ocp --compare-disc-limit-C X` and `hotlap optimise` print and
/// write what these return.
///
/// How to use:
///
///   ocp::OptimalLapOptions o;               // mesh, thermal start, temperatures, Ipopt
///   const ocp::DiscLimitComparison c = ocp::CompareDiscLimit(car, track, o, CelsiusToKelvin(500));
///   c.delta_s();                            // what the limit costs
///
/// Ipopt with MUMPS is not thread-safe: run one comparison (one solve) per process at a time.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/ocp/lap_sensitivities.h"
#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/ocp/optimal_output.h"

namespace hotlap::ocp {

/// One solved lap and what is reported of it.
struct SolvedLap {
  std::string label;                       ///< e.g. "no limit", "discs <= 500 degC"
  std::optional<double> front_disc_limit;  ///< K
  OptimalLapRun run;
  OptimalLapFigures figures;
  std::vector<TurnApproach> approaches;  ///< lift and brake points into each turn
  /// Set-up sensitivities of the lap (OptimalRunOptions::sensitivities; empty if not asked or
  /// the lap did not converge).
  std::vector<LapSensitivity> sensitivities;
  /// The cached lap it converged from (OptimalRunOptions::lap_cache_dir), its name and distance;
  /// "" if none.
  std::string warm_start_from;
  double warm_start_distance = 0.0;
};

/// Called at every Ipopt iteration of a solve with the lap's label, the iteration, the objective
/// (lap time and penalties, s), the constraint violation and the dual infeasibility; return false
/// to stop the solve (it then reports the last point, not converged).
using LapProgress = std::function<bool(const std::string& label, int iteration, double objective,
                                       double infeasibility, double optimality)>;

/// What a solve or the comparison wants to tell the user besides the iterations (a line each,
/// no newline), e.g. "no limit: solving (3.0 m mesh)...".
using LapLog = std::function<void(const std::string& line)>;

/// Solves one lap (RunOptimalLap) and computes its figures and turn approaches. `from`, if not
/// null, is another solve of the same problem size (same track, car and mesh) whose point and
/// multipliers start this one; `warm_up`, if not null, the warm-up to use (RunLapWarmUp of the
/// same car, track and options). InputError as RunOptimalLap.
SolvedLap SolveLap(const vehicle::Car& car, const track::Track& track, OptimalLapOptions options,
                   const std::string& label, const SolveResult* from = nullptr,
                   const LapProgress& progress = {}, const LapLog& log = {},
                   const LapWarmUp* warm_up = nullptr);

/// The free lap and the limited one.
struct DiscLimitComparison {
  SolvedLap free, limited;
  /// The limited lap came out faster than the free one, so the free lap was solved again from it
  /// (a local optimum; the better free lap is kept, its iterations and time are both solves').
  bool free_solved_again = false;
  /// The limited lap was solved in a child process beside the free one
  /// (OptimalLapOptions::second_process); its solve seconds are the child's.
  bool limited_in_second_process = false;
  /// What the limit costs: the limited lap's time minus the free lap's, s.
  double delta_s() const { return limited.figures.lap_time_s - free.figures.lap_time_s; }
  bool converged() const { return free.run.solution.solve.ok() && limited.run.solution.solve.ok(); }
};

/// Solves the lap without a disc limit, then with the front discs at most `front_disc_limit` (K)
/// at every node: coarse to fine like the free lap where `options.coarse_step_m` turns that on
/// (its coarse solve from the free lap's coarse solution, then its fine solve beside the free
/// lap's in a child process where `options.second_process`), else warm-started from the free
/// solution (a continuation: the same neighbourhood, fewer
/// iterations where the limit changes the lap little); if coarse to fine does not converge, the
/// continuation is tried too (iterations and seconds of both counted). The problem is not convex,
/// and the limited lap is a feasible point of the free problem: if it is faster, the free solve
/// stopped at a worse local optimum, and the free lap is solved again from the limited one, keeping
/// the better of the two. `options`' front_disc_limit and start_point are ignored. The warm-up runs
/// once, for all the solves. InputError for bad input, before any solve for a limit below a front
/// disc's temperature at the start line (except with a periodic thermal start, where the start is
/// free).
DiscLimitComparison CompareDiscLimit(const vehicle::Car& car, const track::Track& track,
                                     const OptimalLapOptions& options, double front_disc_limit,
                                     const LapProgress& progress = {}, const LapLog& log = {});

}  // namespace hotlap::ocp
