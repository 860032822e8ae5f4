#pragma once
/// @file
/// The optimal lap as users run it: a quasi-steady-state warm-up on the minimum-curvature line
/// (the initial guess, and the thermal state the lap starts from), the minimum-time solve
/// (lap_problem.h), and a replay of the solution's channels through the exact thermal models
/// (the optimiser uses a smooth |x|; the replay says how much that changed the temperatures).

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/ocp/lap_problem.h"
#include "hotlap/ocp/mesh_error.h"
#include "hotlap/ocp/mesh_refinement.h"
#include "hotlap/sim/replay.h"

namespace hotlap::ocp {

/// Where the thermal states start.
enum class ThermalStart {
  /// A car some laps into a run (default): QSS laps from the car's initial_state, lap after lap,
  /// until no carcass temperature rises more than OptimalLapOptions::racing_carcass_rise_K over a
  /// lap (at most racing_max_laps). The NASCAR paper starts its laps "at values representative of
  /// racing conditions", from which the carcasses rise 5-15 degC over a lap (000 section 4); the
  /// carcasses take several minutes to settle, so a run's lap starts on that slow rise, not at its
  /// end. Wear starts at zero.
  kRacing,
  kWarm,      ///< where one QSS out-lap from the car's initial_state leaves them
  kCar,       ///< the car file's initial_state (tyres and brakes as from the pits)
  kPeriodic,  ///< temperatures end the lap where they start (wear still starts at zero)
};

/// The start by its name in files and on command lines: "racing", "warm", "car" or "periodic".
/// InputError naming the choices otherwise.
ThermalStart ParseThermalStart(const std::string& name);

/// The thermal state and wear at node `k` of a solved lap; the rim and the disc bulk from
/// `fallback` where the solution has no such states (the paper's tyre, a lumped disc).
sim::ReplayInitialState StateAtNode(const LapSolution& solution, size_t k,
                                    const sim::ReplayInitialState& fallback = {});

/// Ipopt's settings for the lap: its defaults but for alpha_for_y = "min-dual-infeas".
inline IpoptOptions LapIpoptOptions() {
  IpoptOptions o;
  o.alpha_for_y = "min-dual-infeas";
  return o;
}

/// One solve of the adaptive mesh's refinement (OptimalLapOptions::tolerance_s).
struct MeshRound {
  int nodes = 0;
  int iterations = 0;
  double solve_seconds = 0.0;
  double lap_time_s = 0.0;
  double estimated_error_s = 0.0;  ///< MeshErrorEstimate::lap_time_error_s of this solve
  double abs_error_s = 0.0;        ///< MeshErrorEstimate::abs_error_s
  bool converged = false;          ///< the solve converged
};

/// A lap's solves done already (e.g. in a child process, ocp/child_solve.h): the coarse solve
/// (empty if none) and the fine one; with an adaptive mesh, the fine one's mesh, the rounds and
/// the fine one's start point (it froze the wear: the programme is posed again from it).
struct PresolvedLap {
  SolveResult coarse, fine;
  std::vector<double> mesh_m;
  std::vector<MeshRound> rounds;
  std::vector<double> start_point;
};

struct OptimalLapOptions {
  double step_m = 3.0;  ///< mesh spacing along the centre line
  /// The adaptive mesh: if > 0, the estimated lap-time error asked for, s (the sum of |e_k| of
  /// ocp/mesh_error.h), and step_m is not used. The lap is solved on the coarse mesh
  /// (coarse_step_m, from the QSS guess, or on step_m from start_point), then again and again on
  /// meshes refined from each solve's error estimate (RefineMesh), each solve from the last one's
  /// point and multipliers (StartFromSolutionOnMesh), until no interval is over its share of the
  /// tolerance, or after max_refinements solves. The trapezoid only (ignored with
  /// Hermite-Simpson). 0: the uniform mesh of step_m.
  double tolerance_s = 0.0;
  int max_refinements = 6;
  /// A fixed non-uniform mesh (LapProblemOptions::mesh_m) for the step_m solve instead of the
  /// uniform one (with tolerance_s, its first solve's); empty: uniform.
  std::vector<double> mesh_m;
  /// The refinement's limits (its tolerance_s is tolerance_s above).
  MeshRefinementOptions refinement;
  /// The adaptive mesh: start each refined solve from the last one's multipliers too (an Ipopt
  /// warm start), not only its point (adaptive_mesh.cc says why not by default).
  bool refinement_multipliers = false;
  /// The adaptive mesh: called with each refined mesh before its solve.
  std::function<void(const MeshRefinement&)> on_mesh;
  /// Run the programme (and its warm-up, guess and replay) on the paper's models
  /// (vehicle::PaperModelsOf: the two-mass tyre, the lumped disc) instead of the car's own
  /// gas-and-rim tyres and surface-and-bulk discs.
  bool paper_models = false;
  std::optional<double> front_disc_limit;  ///< K
  ThermalStart thermal_start = ThermalStart::kRacing;
  double racing_carcass_rise_K = 5.0;  ///< kRacing: the largest carcass rise over a lap, K
  int racing_max_laps = 40;            ///< kRacing: QSS laps at most
  double ambient_temp = 0.0;           ///< K
  double track_temp = 0.0;             ///< K
  double line_margin_m = 1.5;          ///< the QSS guess's racing line keeps this from the edges
  double car_half_width_m = 1.0;       ///< the optimal line keeps the car's centre this far in
  /// Coarse-to-fine: if above step_m, the lap is solved first on a mesh this coarse (from the QSS
  /// guess) and the fine solve starts from that solution, interpolated (ResampleLapPoint); 0: off.
  /// Ignored when start_point is given; a coarse solve that fails leaves the fine one to the guess.
  /// 15 m took the Gen-7 lap at 3 m from 274 iterations (140 s) to 196 + 31 (35 s in all;
  /// docs/validation/optimal-control.md, "Speed").
  double coarse_step_m = 15.0;
  /// Coarse to fine: the coarse solve starts from this solution of the same car and track on the
  /// coarse mesh (its point and multipliers, StartFromSolution; with or without the disc limit,
  /// the layout is the same) instead of the QSS guess. CompareDiscLimit starts the limited lap's
  /// coarse solve from the free lap's: 52 iterations against 324 from the guess on the Gen-7-like
  /// car's lap, to the same lap (docs/validation/optimal-control.md, "Speed").
  struct CoarseStart {
    LapLayout layout;
    SolveResult solve;
  };
  std::optional<CoarseStart> coarse_start;
  /// Robust starts on a fixed mesh: a solve that fails from its start (a coarse solution, or the
  /// QSS guess; at the iteration limit, a locally infeasible point, or in restoration or numerical
  /// trouble) is solved again from the other (from the guess, or from a coarse solve at twice
  /// step_m), both reported in OptimalLapRun::failed_starts. Not with coarse_start, presolved or
  /// the adaptive mesh, whose starts are the caller's; with start_point only if
  /// start_point_fallback.
  bool fallback_start = true;
  /// With fallback_start: a solve from start_point (a saved or neighbouring lap's) that fails is
  /// solved again from the default start (coarse to fine from the QSS guess) and, should that
  /// fail too, from the other, each failure reported. Off: the start point is the caller's alone
  /// (a stint's laps, a mesh check).
  bool start_point_fallback = false;
  /// With start_point_fallback: the solve from start_point stops after this many iterations (a
  /// slow start counts as failed, as SolveOptimalRuns' start_max_iterations) and the default
  /// start, with ipopt.max_iterations, is tried; 0: ipopt.max_iterations for both.
  int start_point_max_iterations = 0;
  /// Coarse to fine: called with the coarse solve (converged or not) before the fine solve starts.
  std::function<void(const LapSolution& coarse)> on_coarse_solve;
  /// The transcription of the step_m solve and of the coarse one (step_m and coarse_step_m are
  /// their intervals: Hermite-Simpson's nodes are half as far apart).
  Collocation collocation = Collocation::kTrapezoid;
  Collocation coarse_collocation = Collocation::kTrapezoid;
  /// Coarse to fine with the coarse solve's multipliers too (ResampleLapMultipliers): the fine
  /// solve is then an Ipopt warm start from mu = ipopt.warm_mu (docs/validation/optimal-control.md,
  /// "Speed").
  bool coarse_multipliers = true;
  /// CompareDiscLimit with coarse to fine: solve the limited lap in a child process beside the
  /// free one (two cores; Ipopt with MUMPS is not thread-safe, so not a thread). Off, or if the
  /// child cannot start or fails, the limited lap is solved after the free one. The child is a
  /// fork(): in a process with other threads running (an embedding interpreter, a thread pool)
  /// turn it off, since only the forking thread lives on in the child.
  bool second_process = true;
  /// RunOptimalLap takes these results instead of calling Ipopt (same problem, same options), and
  /// computes everything else as usual.
  std::optional<PresolvedLap> presolved;
  /// The pedal's smooth positive part (LapProblemOptions::pedal_smoothing).
  double pedal_smoothing = 5e-3;
  /// Weights of the control-smoothness penalty for the steer and the pedal
  /// (LapProblemOptions::steer_smoothing_weight, pedal_smoothing_weight; < 0: the problem's).
  double steer_smoothing_weight = -1.0;
  double pedal_smoothing_weight = -1.0;
  /// LapProblemOptions::convex_element_hessians.
  bool convex_element_hessians = false;
  /// LapProblemOptions::derivative_threads: threads evaluating the derivatives of each solve (the
  /// comparison's two solves side by side take half each).
  int derivative_threads = 1;
  /// LapProblemOptions::all_brake_states (false: the brakes that feed nothing back are
  /// integrated after the solve instead of solved for).
  bool all_brake_states = false;
  /// LapProblemOptions::wear_in_programme for every solve. False: a solve that starts from a
  /// solution (the fine solve of coarse to fine, a start_point) freezes the wear
  /// for the forces at the start's and integrates it after the solve; a solve from the QSS guess
  /// keeps it in the programme (left out there, it sent 3 of 6 meshes astray). A stint sets it.
  bool wear_in_programme = false;
  /// LapProblemOptions::independent_drive_and_brake: the old two controls (drive power and brake
  /// force, nothing stopping both at once) instead of the one pedal, for comparison.
  bool independent_drive_and_brake = false;
  /// Start the solve here instead of the QSS guess: another solution's SolveResult::x on the same
  /// track, car and mesh (LapProblemOptions::start_point).
  std::vector<double> start_point;
  /// A stint's chassis mass lap by lap (LapProblemOptions::lap_mass_kg; ocp/stint.h); empty: the
  /// car's.
  std::vector<double> lap_mass_kg;
  /// Ipopt's settings; the multipliers' step "min-dual-infeas" takes about a quarter fewer
  /// iterations on the lap than Ipopt's default (docs/validation/optimal-control.md, "Speed").
  IpoptOptions ipopt = LapIpoptOptions();
};

/// The programme of a run's last (fine) solve as it was posed: its problem options (the start
/// point that froze the wear, the thermal start) and the QSS guess (the hot pressures, the fixed
/// values of the states left out). EvaluateRunProgramme poses it again for another set-up.
struct PosedLap {
  LapProblemOptions problem;
  sim::QssLap guess;
};

struct OptimalLapRun {
  LapSolution solution;
  /// The fine solve's programme as posed (shared: runs are copied whole).
  std::shared_ptr<const PosedLap> posed;
  double qss_lap_time = 0.0;  ///< the QSS flying lap (the guess), s
  /// The coarse solve of coarse-to-fine (OptimalLapOptions::coarse_step_m; iterations 0 if none).
  SolveResult coarse;
  double coarse_lap_time = 0.0;  ///< its lap, s (0 if none)
  /// The QSS lap on the optimal lap's own line from its own thermal start (same car, path and
  /// start: the difference left is the dynamics the QSS leaves out), s; 0 if no solution.
  double qss_on_line_lap_time = 0.0;
  sim::ReplayInitialState start;  ///< the thermal state at the start line
  int start_laps = 0;  ///< QSS laps run before the start (kRacing: until settled; else 1 or 0)
  /// kRacing: the largest carcass rise over the last of those laps, K (0 otherwise).
  double start_carcass_rise_K = 0.0;
  /// The solution's channels replayed through the exact thermal models, at the mesh nodes.
  sim::ReplayResult exact;
  double max_tread_difference_K = 0.0;  ///< |exact - optimiser| over corners and nodes
  double max_disc_difference_K = 0.0;
  /// The solution's mesh error estimate (ocp/mesh_error.h; empty with Hermite-Simpson).
  MeshErrorEstimate mesh_error;
  /// The adaptive mesh's solves, the coarse one first (empty on a fixed mesh).
  std::vector<MeshRound> mesh_rounds;
  /// A start that failed before the solution's (OptimalLapOptions::fallback_start).
  struct FailedStart {
    std::string from;  ///< "a 15 m coarse solve" or "the QSS guess"
    int iterations = 0;
    std::string message;
  };
  std::vector<FailedStart> failed_starts;
  /// Where the reported solve started: "the given start point" (OptimalLapOptions::start_point),
  /// "a 15 m coarse solve" or "the QSS guess".
  std::string started_from;
};

/// The warm-up before a solve (RunOptimalLap's first step): the thermal state at the start line
/// (OptimalLapOptions::thermal_start) and the QSS flying lap on the minimum-curvature line that
/// seeds the solve.
struct LapWarmUp {
  sim::ReplayInitialState start;
  int start_laps = 0;                 ///< as OptimalLapRun::start_laps
  double start_carcass_rise_K = 0.0;  ///< as OptimalLapRun::start_carcass_rise_K
  sim::QssLap guess;
};

/// Runs the warm-up for `options` (its thermal start, temperatures and line margin).
LapWarmUp RunLapWarmUp(const vehicle::Car& car, const track::Track& track,
                       const OptimalLapOptions& options);

/// Runs the warm-up (or takes `warm_up`, one of RunLapWarmUp for the same car, track and
/// options), the solve and the exact replay. InputError for bad input (no vehicle
/// sections, a disc limit below the starting disc temperature); the solve's failures are reported
/// in solution.solve, never thrown.
OptimalLapRun RunOptimalLap(const vehicle::Car& car, const track::Track& track,
                            const OptimalLapOptions& options, const LapWarmUp* warm_up = nullptr);

/// The programme of `run`'s fine solve posed again for `car` (the run's car with other set-up
/// values: the same options, thermal start, guess, start point and frozen wear; the tyres at
/// `car`'s hot pressures over the guess lap, as RunOptimalLap sets them) and evaluated at the
/// run's solution, without solving (EvaluateLapProgramme). InputError if the run has no
/// solution or no posed programme.
LapProgrammeValues EvaluateRunProgramme(const vehicle::Car& car, const track::Track& track,
                                        const OptimalLapOptions& options, const OptimalLapRun& run);

/// A lift or brake point into a turn.
struct TurnApproach {
  std::string turn;               ///< "turn 1", ...
  double entry_m = 0.0;           ///< the turn's entry (centre-line distance)
  std::optional<double> lift_m;   ///< where drive power last falls below 95% of its peak before
                                  ///< the turn's slowest point
  std::optional<double> brake_m;  ///< where braking last starts before the slowest point
  double min_speed_mps = 0.0;     ///< slowest point of the turn
  double min_speed_at_m = 0.0;
};

/// Lift and brake points of the solution into each turn of the track (track_summary.h turns).
std::vector<TurnApproach> FindTurnApproaches(const LapSolution& solution, const track::Track& track,
                                             double wheel_power);

}  // namespace hotlap::ocp
