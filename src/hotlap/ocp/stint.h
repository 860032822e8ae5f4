#pragma once
/// @file
/// A stint as one optimal-control problem (issue 20; the NASCAR paper's "multi-lap studies ... as
/// a multi-phase optimal control problem, with each lap treated as a phase", 000 section 5): N
/// laps of the track as one lap problem on track::Track::Repeated(N), every state continuous from
/// lap to lap (temperatures, wear, and the mechanical states at the start line), forces scaled by
/// g(T_tread) h(wear) as in the single lap; and, against it, the greedy driver: the same N laps
/// driven as N single optimal laps in sequence, each from the previous lap's end state, with no
/// look-ahead.
///
/// How it is solved (docs/optimal-control.md, "Stints"): the greedy laps first (each coarse to
/// fine as a single lap is); their solutions and multipliers, lap after lap, are then the start of
/// the stint's solve, which is a feasible point of the stint problem but for the jumps of the
/// mechanical states at the lap lines, so that the stint is never a worse local optimum than
/// the greedy laps by much more than the solver's tolerance.
///
/// Fuel: the car's mass (with fuel) falls with the engine's work, at an assumed brake-specific
/// fuel consumption; a lap's mass is constant over the lap (LapProblemOptions::lap_mass_kg), the
/// fuel the lap before burnt taken off. The stint takes the greedy laps' fuel plan; its own burn
/// differs by a fraction of a kilogram (reported: fuel_plan_error_kg).
///
/// Accelerated wear: the wear rate times wear_scale (the compound's wp1), so that N laps stand for
/// about N * wear_scale laps of wear.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "hotlap/ocp/optimal_lap.h"

namespace hotlap::ocp {

struct StintOptions {
  int laps = 3;
  /// Wear rate times this (every tyre's wp1); 0: no wear.
  double wear_scale = 1.0;
  /// Fuel aboard at the start, kg, part of the car's mass; 0: no fuel burn (mass constant).
  double fuel_kg = 40.0;
  /// Brake-specific fuel consumption, kg per J of engine work (assumed: 300 g/kWh, a naturally
  /// aspirated racing V8 at full power).
  double bsfc_kg_per_J = 0.300 / 3.6e6;
  /// The single lap's options (mesh, disc limit, thermal start, temperatures, Ipopt): each lap of
  /// the stint is on the mesh of the single lap (its step rounded so that a lap is a whole number
  /// of intervals). The mesh is 6 m by default, not the single lap's 3 m: a stint is N laps'
  /// programme, and the Gen-7-like car's Darlington lap on 6 m is within 1 ms of 3 m's.
  OptimalLapOptions lap = [] {
    OptimalLapOptions o;
    o.step_m = kStintStepM;
    return o;
  }();
  static constexpr double kStintStepM = 6.0;
  /// Checkpoints (empty: none; ocp/stint_checkpoint.h, docs/reliability.md): this folder gets
  /// each greedy lap's solves as the lap ends and the stint solve's iterate every
  /// checkpoint_every Ipopt iterations (and at its end). A later run with the same folder, car,
  /// track and options resumes from them: the greedy laps saved are taken as they were solved
  /// (not solved again) and the stint's solve warm-starts from its last iterate, so a run killed
  /// part way loses at most one greedy lap's solve or checkpoint_every iterations. Files of
  /// another stint (another fingerprint) are not used, and are replaced as this one goes.
  std::filesystem::path checkpoint_dir;
  int checkpoint_every = 10;
  /// More that tells one stint from another in the checkpoints' fingerprint (the command line
  /// puts in its input files' bytes; the car's parameters count through the warm-up anyway).
  std::string checkpoint_key;
};

/// One lap of a stint.
struct StintLap {
  int lap = 0;          ///< 1-based
  double time_s = 0.0;  ///< lap time
  double top_speed_mps = 0.0;
  double mass_kg = 0.0;      ///< the car's mass over the lap
  double fuel_end_kg = 0.0;  ///< fuel aboard at the end of the lap
  double fuel_burnt_kg = 0.0;
  std::array<double, 4> peak_tread_temp_K{}, peak_carcass_temp_K{}, peak_disc_temp_K{};
  /// The lowest over the lap: with the peaks, the window each tyre and disc works in (a tread
  /// that cools on the straights below its grip window, a disc that never cools to its pads').
  std::array<double, 4> min_tread_temp_K{}, min_carcass_temp_K{}, min_disc_temp_K{};
  std::array<double, 4> wear_end_mm{};  ///< tread depth lost since the stint's start
  /// Gas-and-rim tyres (0 otherwise): the lap's mean gas temperature (K) and the hot gauge
  /// pressure at the lap's end (Pa), what a crew chief reads at a stop.
  std::array<double, 4> mean_gas_temp_K{}, end_pressure_Pa{};
  /// Each corner's energy audit over the lap, from the exact models' replay of the solution
  /// (OptimalLapRun::exact); has_audit false where there is none.
  std::array<sim::CornerEnergyAudit, 4> audit{};
  bool has_audit = false;
};

struct StintResult {
  /// The stint as one problem (its solution spans the repeated track: N laps).
  OptimalLapRun run;
  std::vector<StintLap> laps;
  double total_time_s = 0.0;
  /// The greedy driver's laps (each a single-lap solve) and their totals.
  std::vector<OptimalLapRun> greedy_runs;
  std::vector<StintLap> greedy_laps;
  double greedy_total_time_s = 0.0;
  /// The greatest difference between the fuel the stint's laps were given (the greedy plan) and
  /// the fuel they burn, kg.
  double fuel_plan_error_kg = 0.0;
  double solve_time_s = 0.0;  ///< the stint's own solve
  double greedy_solve_time_s = 0.0;
  int ipopt_iterations = 0;  ///< the stint's own solve (this run's, after any resumed ones)
  /// Resumed from checkpoints: greedy laps taken from their files, and the stint solve's
  /// iteration its saved iterate was taken at (0: started afresh).
  int greedy_laps_resumed = 0;
  int resumed_from_iteration = 0;
  bool ok() const { return run.solution.solve.ok(); }
};

/// Progress of a long solve, in words (e.g. "greedy lap 2 of 5: 29.71 s").
using StintLog = std::function<void(const std::string&)>;

/// The car a stint drives: `car` with every tyre's wear rate times wear_scale.
vehicle::Car StintCar(const vehicle::Car& car, double wear_scale);

/// Solves the stint and the greedy laps. InputError for bad options (laps < 1, negative wear
/// scale or fuel, fuel that runs out, a disc limit below where the discs start).
StintResult SolveStint(const vehicle::Car& car, const track::Track& track,
                       const StintOptions& options, const StintLog& log = {});

/// The per-lap figures of a solution on track.Repeated(laps) (or of one lap: laps 1), starting
/// with `fuel_start_kg` aboard at mass `mass_start_kg` (a lap's mass is `lap_mass_kg` if given).
std::vector<StintLap> StintLaps(const LapSolution& solution, const track::Track& single_track,
                                int laps, double fuel_start_kg,
                                const std::vector<double>& lap_mass_kg, double bsfc_kg_per_J,
                                double driveline_efficiency);

/// The point and multipliers of the stint problem made of single-lap solves, lap after lap (each
/// of `intervals_per_lap` intervals and layout `lap_layout`): the stint's node k is lap k / I's
/// node k mod I (the last node the last lap's last), its intervals likewise, its closure the last
/// lap's. SolveResult holds x and the multipliers; nothing else is set.
SolveResult ConcatenateLaps(const std::vector<const SolveResult*>& laps,
                            const LapLayout& lap_layout);

}  // namespace hotlap::ocp
