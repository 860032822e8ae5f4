#pragma once
/// @file
/// The minimum-lap-time optimal-control problem of the NASCAR paper (000 section 4): the vehicle
/// model of vehicle/vehicle_model.h driven round a track with its four tyres' tread and carcass
/// temperatures and wear, and its four brakes' disc and calliper temperatures, as states; tyre
/// forces scaled by g(T_tread) h(wear); track limits, the engine's power limit and, optionally, a
/// limit on the front disc temperatures.
///
/// Transcription (docs/optimal-control.md): distance s along the centre line is the independent
/// variable, N intervals of equal length, trapezoidal collocation. The programme is lifted: every
/// node carries, besides the states and controls, the quantities the equations share (tyre
/// forces, slip angles, wheel speeds, normal loads, total forces, dt/ds), each defined by an
/// equality constraint, so every equation is a small element differentiated exactly by
/// forward-mode AD (ocp/element.h). Ipopt solves it with exact first and second derivatives.
///
/// Node variables: states u, v, r (body speeds, yaw rate), n (lateral offset, left +), xi
/// (heading error), and per corner T_tread, T_carcass, wear, T_disc, T_calliper (and, on a car
/// with a gas-and-rim tyre or a surface-and-bulk disc, T_rim and T_bulk, each tyre's rolling
/// resistance its own function of carcass and gas: docs/optimal-control.md); controls steer
/// and the signed pedal p (drive when positive, brake when negative, never both), which sets the
/// drive power P (at the rear contact patches, 0..P_wheel) and the brake force B (>= 0, split by
/// the brake balance: front wheels beta B / 2 each, the rear axle (1 - beta) B); algebraic slip
/// ratios (front wheels, the rear axle's spool and each rear wheel), slip angles, wheel speeds,
/// normal loads, tyre forces, the body-axis totals X, Y, Mz, and w = dt/ds.

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/ocp/ipopt_solve.h"
#include "hotlap/ocp/mesh_error.h"
#include "hotlap/ocp/road_frame_channels.h"
#include "hotlap/sim/qss_lap.h"
#include "hotlap/track/track.h"
#include "hotlap/tyre/tyre_thermal.h"
#include "hotlap/vehicle/car.h"

namespace hotlap::ocp {

/// How the state equations are imposed between nodes (docs/optimal-control-model.md,
/// "Transcription").
enum class Collocation {
  /// x_{k+1} - x_k = ds/2 (f_k + f_{k+1}) on every interval of the mesh: second order.
  kTrapezoid,
  /// Hermite-Simpson in separated form: intervals of `step_m`, each with a node at its midpoint
  /// (an ordinary node: the same variables and node equations), and two defects an interval,
  /// Simpson's x_b - x_a = h/6 (f_a + 4 f_m + f_b) and Hermite's x_m = (x_a + x_b)/2 +
  /// h/8 (f_a - f_b): fourth order where the solution is smooth. The nodes are step_m / 2 apart.
  kHermiteSimpson,
};

/// "trapezoid" or "hermite-simpson"; InputError otherwise.
Collocation ParseCollocation(const std::string& name);

struct LapProblemOptions {
  double step_m = 2.0;  ///< mesh spacing along the centre line (an interval)
  /// A non-uniform mesh instead (the trapezoid only; ocp/mesh_refinement.h makes them): every
  /// node's distance along the centre line, m, increasing from 0 to the track's length (the last
  /// node closes the lap), at least 17 nodes; InputError otherwise. Empty: the uniform mesh of
  /// step_m. On such a mesh the pedal's smoothing weight (pedal_smoothing_weight < 0) follows
  /// each interval's own length.
  std::vector<double> mesh_m;
  Collocation collocation = Collocation::kTrapezoid;
  std::optional<double> front_disc_limit;  ///< K; front discs at most this at every node
  /// Temperatures end where they start (else they start fixed at `initial`); the wear starts at
  /// `initial` either way (it only grows).
  bool periodic_thermal = false;
  double ambient_temp = 0.0;        ///< K
  double track_temp = 0.0;          ///< K
  sim::ReplayInitialState initial;  ///< thermal states at the start line
  double car_half_width = 1.0;      ///< m kept between the centre of the car and an edge
  /// The driver's steering: road-wheel steer rate at most this, rad/s (0: no limit). Without it the
  /// optimiser finds "flicks" at huge slip angles that heat a cold tyre by sliding it.
  double max_steer_rate = 0.5;
  /// The old formulation, for comparison: drive power and brake force as two independent
  /// non-negative controls (nothing stops both being on; the pedal is then fixed at 0 and the
  /// smoothing penalty and rate limit act on nothing but the steer).
  bool independent_drive_and_brake = false;
  /// Keep every brake's temperatures in the programme. Otherwise a brake's disc and calliper
  /// temperatures, which feed nothing back into the lap, are left out of it (fixed variables that
  /// Ipopt removes, no defects) and integrated after the solve by the same trapezoid: the rear
  /// brakes always, the front ones unless they are limited (front_disc_limit), and none when the
  /// thermal states are periodic. The same solution, eight (or four) fewer states per node.
  bool all_brake_states = false;
  /// Keep the tyres' wear as states of the programme. Otherwise wear, which feeds back into the
  /// lap only through the grip factor h(wear) (the wear rate and the temperatures do not depend
  /// on it), is frozen for the tyre forces at the start point's values (start_point's, else the
  /// QSS guess's replay), left out of the programme (fixed variables, no defects) and integrated
  /// after the solve by the same collocation over the solved channels: a lap's wear changes h by
  /// about 0.01 at the right rear of the Gen-7-like car (its tuned wear, docs/race.md); frozen at
  /// the coarse solve's, h is within 1e-3 of the solution's in the main job
  /// (LapSolution::frozen_wear_grip_difference reports it). Four states fewer per node: a fine
  /// solve from a coarse one about 15% faster an iteration, in fewer iterations. RunOptimalLap
  /// leaves it out of solves that start from a solution only (from the QSS guess it made the solve
  /// less robust); a stint keeps it (its wear grows lap after lap).
  /// docs/validation/optimal-control.md, "Speed".
  bool wear_in_programme = true;
  /// Each element's Hessian with its negative curvature clipped (ElementNlp::
  /// SetConvexElementHessians) instead of the exact Lagrangian Hessian.
  bool convex_element_hessians = false;
  /// Threads that evaluate the derivatives (ElementNlp::SetThreads; 1: the calling thread).
  int derivative_threads = 1;
  /// The pedal (internal::PedalSplitFn): brake force at p = -1, N (0: twice the car's weight).
  double max_brake_force = 0.0;
  /// The pedal's smooth positive part: its eps (dimensionless; where both sides are on at once the
  /// weaker is at most max_brake_force eps^2 / (4 |p|)).
  double pedal_smoothing = 5e-3;
  /// The driver's feet: |dp/dt| at most this, 1/s (0: no limit). With 4/s a lift from full power
  /// takes 0.25 s and the braking force rises or falls at most 4 max_brake_force per second (8 g
  /// per second with the default: a 1 g brake application takes an eighth of a second).
  double max_pedal_rate = 4.0;
  /// Slip angles are kept within this, rad: the tyres' useful range (their peaks are near 0.1).
  double max_slip_angle = 0.25;
  /// Weight of the control-smoothness penalty: weight * sum over intervals of the squared change
  /// of each scaled control.
  double smoothing = 1e-4;
  /// The same penalty's weight for the pedal (< 0: `smoothing` (step_m / 3 m)^2: 1e-4 on the
  /// default 3 m mesh, 4e-4 on 6 m, 2.5e-3 on the 15 m coarse one). A coarse mesh resolves the
  /// pedal's rate-limited lifts and brake applications in fewer intervals and needs more damping
  /// to converge: on the Gen-7-like car's lap 1e-4 cycled for 1000 iterations on 20 m and 6 m,
  /// 2e-4 on 6 m; with the square law every mesh tried converges (15 m: 86 iterations, and the
  /// limited lap 91 against 608 at 5e-4; 6 m: 40; 3 m from the 15 m solution: 47). 1e-3 on the
  /// 3 m mesh gave the same laps in 2.5 times the iterations, and 1e-2 took the brake application
  /// into turn 1 away altogether (docs/optimal-control.md).
  double pedal_smoothing_weight = -1.0;
  /// The same penalty's weight for the steer (< 0: `smoothing`).
  double steer_smoothing_weight = -1.0;
  /// The tyre thermal model's |x| made smooth for the optimiser (tyre_thermal.h); the solution is
  /// replayed through the exact model to report the difference.
  tyre::TyreThermalSmoothing thermal_smoothing{10.0, 1e-3};
  /// A stint (ocp/stint.h) on a track made by track::Track::Repeated: the chassis mass of each
  /// lap in turn, kg (the fuel burnt lap by lap), constant within a lap; empty: the car's mass
  /// throughout. As many entries as the track has laps (InputError otherwise).
  std::vector<double> lap_mass_kg;
  /// A starting point for every variable (a SolveResult::x of the same problem size, e.g. the
  /// solution with a disc limit as the start of the lap without it); empty: from the guess.
  /// Values are clipped to this problem's bounds.
  std::vector<double> start_point;
};

/// One corner's channels along the solution, SI (K).
struct CornerTrace {
  std::vector<double> fz, fx, fy, slip_angle, slip_ratio, speed;
  std::vector<double> tread_temp, carcass_temp, wear, disc_temp, calliper_temp, brake_power;
  /// With a gas-and-rim tyre or a surface-and-bulk disc on the car (empty otherwise): the rim and
  /// disc bulk temperatures (K; held at the start's where the corner's model has none), and a
  /// gas-and-rim tyre's gas temperature (K), hot gauge pressure (Pa) and rolling-resistance
  /// coefficient (1) (the paper tyre's: empty).
  std::vector<double> rim_temp, disc_bulk_temp, gas_temp, pressure, rolling_resistance;
};

/// Where a lap problem's variables and rows lie. Variables: node by node, `vars_per_node` each.
/// Rows: the node equations, node by node (`rows_per_node` each); then the collocation defects,
/// from node to node (`defects_per_interval` each: with Hermite-Simpson an interval's Hermite
/// rows come from its first node to its midpoint, its Simpson rows from the midpoint to its
/// last node); then the lap's closure (`closure_rows`); then `rate_blocks` blocks of two rows
/// from node to node (the steer's and pedal's rate limits). `intervals()` counts the steps from
/// node to node (twice the Hermite-Simpson intervals).
struct LapLayout {
  int nodes = 0;  ///< intervals + 1
  int vars_per_node = 0;
  int rows_per_node = 0;
  int defects_per_interval = 0;
  int closure_rows = 0;
  int rate_blocks = 0;
  Collocation collocation = Collocation::kTrapezoid;
  /// A non-uniform mesh's node distances, m (LapProblemOptions::mesh_m); empty: uniform.
  std::vector<double> mesh_m;

  int intervals() const { return nodes - 1; }
  int variables() const { return nodes * vars_per_node; }
  int rows() const {
    return nodes * rows_per_node + intervals() * (defects_per_interval + 2 * rate_blocks) +
           closure_rows;
  }
  /// The same problem on a mesh of `n` nodes.
  LapLayout WithNodes(int n) const {
    LapLayout l = *this;
    l.nodes = n;
    l.mesh_m.clear();
    return l;
  }
  /// The same problem on the non-uniform mesh `mesh_m`.
  LapLayout WithMesh(std::vector<double> mesh_m) const {
    LapLayout l = WithNodes(static_cast<int>(mesh_m.size()));
    l.mesh_m = std::move(mesh_m);
    return l;
  }
};

/// The optimal lap at the mesh nodes (N + 1: the last closes the lap).
/// The road-frame channels (distance, time, u, v, r, n) come from RoadFrameChannels.
struct LapSolution : RoadFrameChannels {
  SolveResult solve;
  std::vector<double> xi;  ///< heading error, rad
  std::vector<double> steer, pedal, drive_power, brake_force;
  double max_brake_force = 0.0;  ///< N, the pedal's brake force at p = -1
  std::array<CornerTrace, 4> corners;
  double lap_time = 0.0;  ///< s
  /// With the wear left out of the programme (LapProblemOptions::wear_in_programme false): the
  /// largest |h(wear) - h(frozen wear)| over nodes and tyres, the grip factor's error from
  /// freezing the wear (dimensionless); 0 otherwise.
  double frozen_wear_grip_difference = 0.0;
  int variables = 0;
  int constraints = 0;
  LapLayout layout;
  /// The trapezoid's state rates and costates at the solution, for the mesh error estimate
  /// (EstimateMeshError, ocp/mesh_error.h); empty with Hermite-Simpson.
  CollocationRates rates;
};

/// InputError naming the disc if a front disc of `start` is above `front_disc_limit` (K): a lap
/// that starts there cannot hold the limit.
void RequireFrontDiscsWithinLimit(const sim::ReplayInitialState& start, double front_disc_limit);

/// The mesh nodes of the lap problem on `track` with intervals of about `step_m` (the intervals
/// plus the closing node; with Hermite-Simpson, their midpoints too).
int LapNodeCount(const track::Track& track, double step_m,
                 Collocation collocation = Collocation::kTrapezoid);

/// A point of the lap problem (a SolveResult::x) on a mesh of `from_nodes` nodes, taken onto a
/// mesh of `to_nodes` nodes of the same track, car and options: every node variable linearly
/// interpolated in centre-line distance (both meshes are uniform and close the lap). The start of
/// a fine solve from a coarse one. InputError if x is not from_nodes whole nodes.
std::vector<double> ResampleLapPoint(const std::vector<double>& x, int from_nodes, int to_nodes);

/// Multipliers of a lap problem (as SolveResult holds them: of the scaled programme).
struct LapMultipliers {
  std::vector<double> z_lower, z_upper, lambda;
};

/// A solve's multipliers on the mesh of `from`, taken onto the mesh of `to` (the same problem on
/// another node count): the warm start of a fine solve from a coarse one. The transcription's
/// multipliers approximate continuous ones in two ways. A defect's multiplier is the costate of
/// its state (time per unit of state, whatever the spacing), and a rate limit's is likewise a
/// density-free function of distance: both are interpolated at the interval midpoints. A node
/// equation's or a bound's multiplier carries its node's share of the lap, ds (ds / 2 at the two
/// ends, as in the trapezoid): they are interpolated as densities per metre and multiplied by the
/// new share. The closure's rows are copied. InputError if the sizes do not match `from`.
LapMultipliers ResampleLapMultipliers(const SolveResult& solve, const LapLayout& from,
                                      const LapLayout& to);

/// The start of a solve from a solved lap (`solve`, of the layout `from`) on a mesh of `to_nodes`
/// nodes of the same problem transcribed by `to_collocation`: its point (ResampleLapPoint) as
/// `start_point` and, if `with_multipliers`, its multipliers (ResampleLapMultipliers) as `ipopt`'s
/// warm start. Coarse to fine, the mesh check and a saved lap (ocp/lap_start_file.h) all start
/// this way.
void StartFromSolution(const SolveResult& solve, const LapLayout& from, int to_nodes,
                       Collocation to_collocation, bool with_multipliers,
                       std::vector<double>& start_point, IpoptOptions& ipopt);

/// A lap problem's programme evaluated at a point, in physical units, row by row in the layout's
/// rows (LapLayout: a row left out of the programme, a brake's or the frozen wear's defect, has
/// value, bounds 0 and scale 1): what a parametric sensitivity (ocp/lap_sensitivities.h) needs of
/// the programme posed for a perturbed car at a fixed solution.
struct LapProgrammeValues {
  double objective = 0.0;        ///< f(x): the lap time and the smoothness penalty, s
  double objective_scale = 1.0;  ///< the solver sees f / objective_scale
  std::vector<double> rows, row_lower, row_upper, row_scale;  ///< g(x), its bounds and scales
  std::vector<double> lower, upper, scale;                    ///< the variables' bounds and scales
};

/// The programme SolveMinimumTimeLap poses for `car`, `options` and `guess` (options.start_point
/// and wear_in_programme as the solve had them: they fix the frozen wear), evaluated at `x` (a
/// SolveResult::x of it) with every fixed variable at its fixed value, as the solver saw it: no
/// solve. InputError as SolveMinimumTimeLap, or if x is not the programme's size.
LapProgrammeValues EvaluateLapProgramme(const vehicle::Car& car, const track::Track& track,
                                        const LapProblemOptions& options, const sim::QssLap& guess,
                                        const std::vector<double>& x);

/// Builds and solves the lap. `guess` (a QSS lap of the same car and track, e.g. from
/// sim::RunQssLap) gives the starting point. InputError if the car has no vehicle sections;
/// failures of the solve are reported in the result's `solve` (never thrown).
/// `solved`, if not null, is this problem's solve done already (by another process: ocp/
/// child_solve.h): it is taken as the result instead of calling Ipopt (InputError if its x is not
/// this problem's size).
LapSolution SolveMinimumTimeLap(const vehicle::Car& car, const track::Track& track,
                                const LapProblemOptions& options, const sim::QssLap& guess,
                                const IpoptOptions& ipopt, const SolveResult* solved = nullptr);

}  // namespace hotlap::ocp
