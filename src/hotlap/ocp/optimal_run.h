#pragma once
/// @file
/// The optimal lap as `hotlap optimise` and `hotlap lap --method ocp` run it, as a library call:
/// plain options in the commands' units (degC, names), and one solve (with a front-disc limit or
/// from a saved lap, if asked) or the disc-limit comparison. What is written and printed of the
/// runs: optimal_run_output.h (CSV and HTML), optimal_run_json.h, optimal_run_text.h.
///
/// How to use:
///
///   ocp::OptimalRunOptions o;               // as the command line: step_m, disc limits, ...
///   o.compare_disc_limit_C = 500;
///   const ocp::OptimalRuns runs = ocp::SolveOptimalRuns(car, track, o);
///   ocp::WriteOptimalRunFiles("out", runs.laps, car, track, o.step_m);

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/ocp/disc_limit_comparison.h"
#include "hotlap/ocp/lap_cache.h"
#include "hotlap/ocp/lap_start_file.h"

namespace hotlap::ocp {

/// The options of an optimal-lap run, as the commands take them (docs/optimal-control.md).
struct OptimalRunOptions {
  double step_m = 3.0;  ///< mesh spacing along the centre line, m
  /// The adaptive mesh (OptimalLapOptions::tolerance_s): the estimated lap-time error asked
  /// for, s; 0: the fixed mesh of step_m.
  double tolerance_s = 0.0;
  double coarse_step_m = 15.0;            ///< solve first on this mesh and start from it (0: off)
  std::string collocation = "trapezoid";  ///< of the --step-m solve (ParseCollocation)
  std::string coarse_collocation = "trapezoid";  ///< of the coarse solve
  double steer_smoothing = -1.0;         ///< the steer's smoothness weight (< 0: the library's)
  double pedal_smoothing = -1.0;         ///< the pedal's
  bool convex_element_hessians = false;  ///< each element's negative curvature clipped
  /// The tyres' wear as states of the programme (OptimalLapOptions::wear_in_programme) instead
  /// of frozen for the forces and integrated after the solve.
  bool wear_in_programme = false;
  /// The paper's models in place of the car's own (OptimalLapOptions::paper_models).
  bool paper_models = false;
  /// The old two controls (drive power and brake force) instead of the one pedal.
  bool independent_drive_and_brake = false;
  std::optional<double> disc_limit_C;          ///< one solve with this front-disc limit, degC
  std::optional<double> compare_disc_limit_C;  ///< two solves: without, and with this limit
  std::string thermal_start = "racing";        ///< a name of ParseThermalStart
  double ambient_C = 25.0;
  double track_C = 40.0;
  int max_iterations = 1000;
  bool ipopt_output = false;   ///< Ipopt's own iteration log
  bool second_process = true;  ///< the comparison's limited lap beside the free one
  /// Threads evaluating each solve's derivatives (OptimalLapOptions::derivative_threads); 0: one
  /// per core of the machine, at most 8 (the command line's default).
  int threads = 1;
  /// After the solves, each converged lap's set-up sensitivities (ComputeLapSensitivities, every
  /// parameter of CrewChiefParameters the car takes) into SolvedLap::sensitivities.
  bool sensitivities = false;
  /// A solve from a saved lap (SolveOptimalRuns' warm starts) stops after this many iterations
  /// and the next start is tried (a slow start counts as failed); 0: max_iterations (150 for the
  /// laps of a lap cache).
  int start_max_iterations = 0;
  /// A lap cache (ocp/lap_cache.h): one solve starts from the two laps of this folder nearest it
  /// (LapCacheKeyOf: the same build, car files, track and programme; the distance over the car's
  /// overrides, the disc limit and the temperatures), and its converged lap is kept there under
  /// `lap_cache_name` (default: the car's name and overrides). Not for the comparison.
  std::string lap_cache_dir;
  std::string lap_cache_name;
  /// The coordinates' scales for the distance (default: each crew-chief key's typical step, 50
  /// degC of disc limit, 10 degC of air or track; else the value's size).
  std::map<std::string, double> lap_cache_scales;
  std::vector<std::pair<std::string, std::string>> ipopt_options;  ///< passed to Ipopt as they are
};

/// InputError for a disc limit and a comparison's limit both given, or a limit outside (0, 1500)
/// degC (SolveOptimalRuns checks them; callers may check before any work).
void CheckDiscLimits(const OptimalRunOptions& options);

/// What a lap of `car` on `track` with `options` is cached under: the family (the build, every
/// file of the car's folder, the track's name and length, the mesh, collocation, thermal start and
/// the programme's other choices) and the coordinates (every crew-chief value of
/// CrewChiefParameters, the car's or its override, any other override, the disc limit if any, the
/// air and track temperatures). InputError for a car made in code (no files).
CachedLapKey LapCacheKeyOf(const vehicle::Car& car, const track::Track& track,
                           const OptimalRunOptions& options);

/// The solver's options for `options` (mesh options.step_m; the disc limits are not set).
OptimalLapOptions MakeOptimalLapOptions(const OptimalRunOptions& options);

/// The solved laps of a run.
struct OptimalRuns {
  std::vector<SolvedLap> laps;             ///< one, or the comparison's free and limited laps
  bool limited_in_second_process = false;  ///< DiscLimitComparison's
};

/// With options.compare_disc_limit_C the comparison (CompareDiscLimit); else one solve labelled
/// "optimal lap" or, with options.disc_limit_C, "discs <= X degC", started from `warm_start` if
/// not null (a saved lap, UseLapStart); with options.sensitivities, each converged lap's set-up
/// sensitivities. InputError as those.
OptimalRuns SolveOptimalRuns(const vehicle::Car& car, const track::Track& track,
                             const OptimalRunOptions& options, const LapStart* warm_start = nullptr,
                             const LapProgress& progress = {}, const LapLog& log = {});

/// As above, from each of `warm_starts` in turn (the nearest first; each solve within
/// options.start_max_iterations) until one converges, else from the default start; the starts
/// that failed are in the solution's failed_starts, the one it converged from its started_from
/// ("saved lap 1", ...; "the saved lap" if there is one).
OptimalRuns SolveOptimalRuns(const vehicle::Car& car, const track::Track& track,
                             const OptimalRunOptions& options,
                             const std::vector<LapStart>& warm_starts,
                             const LapProgress& progress = {}, const LapLog& log = {});

}  // namespace hotlap::ocp
