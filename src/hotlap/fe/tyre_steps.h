#pragma once
/// @file
/// The FE/ABS paper's steps on the generated tyre (002 §2.1): inflation, the static footprint,
/// free rolling and a braking event whose torque a callback sets (the ABS controller lives above
/// this layer, in abs/fe_abs_stop.h). One TyreRun carries the state from each step into the next.
///
///   fe::TyreRun run(config);
///   const fe::InflateResult inf = run.Inflate(hooks);
///   const fe::FootprintResult fp = run.Footprint(hooks);
///   const fe::RollResult roll = run.Roll(hooks);
///   const fe::BrakeResult br = run.Brake(duration, torque_callback, hooks);
///
/// Quasi-static steps (inflate, footprint) are dynamic relaxation: the load is ramped and held
/// with mass-proportional damping. Rolling and braking run with no mass damping (it would act on
/// the absolute velocity and brake the tyre); bulk viscosity remains.
///
/// Checkpoints (braking only): StepHooks::checkpoint is called every
/// StepHooks::checkpoint_interval_s of simulated time and at the end of the step; in it the caller
/// writes SaveState (and its own state: the torque callback's). A new TyreRun of the same
/// configuration that reads it with LoadState continues with ResumeBrake bit for bit.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "hotlap/fe/checkpoint.h"
#include "hotlap/fe/explicit_solver.h"
#include "hotlap/fe/fe_config.h"
#include "hotlap/fe/tyre_mesh.h"

namespace hotlap::fe {

/// One row of a step's history. SI units.
struct HistoryRow {
  double time_s = 0.0;
  double rim_x_m = 0.0, rim_z_m = 0.0;
  double rim_vx_mps = 0.0;
  double spin_rad_per_s = 0.0;
  double brake_torque_Nm = 0.0;  ///< applied about +y (negative brakes forward rolling)
  double road_fx_N = 0.0, road_fz_N = 0.0;
  double slip = 0.0;  ///< (Vx - R_l omega) / Vx (002:2), R_l = TyreRun::slip_radius_m()
  Energies energies;
};

/// Called with the step's name, simulated time and end time, now and then.
using ProgressFn = std::function<void(const std::string& step, double t, double t_end)>;
/// Called for each deformed-shape frame (0-based) of a step.
using FrameFn = std::function<void(const std::string& step, int frame)>;

struct StepHooks {
  ProgressFn progress;  ///< may be empty
  FrameFn frame;        ///< may be empty
  int frames = 1;       ///< frames per step, the last at the step's end
  double history_interval_s = 1e-4;
  /// Called between two time steps every checkpoint_interval_s of simulated time after the
  /// step's start, and at its end; may be empty.
  std::function<void()> checkpoint;
  double checkpoint_interval_s = 0.0;  ///< s (0: only at the end)
  /// Called with the simulated time, s, after each call of `checkpoint` has returned (the
  /// checkpoint is then whole on disk); may be empty.
  std::function<void(double t)> checkpoint_written;
};

struct InflateResult {
  double pressure_Pa = 0.0;
  double outer_radius_before_m = 0.0, outer_radius_after_m = 0.0;
  double section_width_before_m = 0.0, section_width_after_m = 0.0;
  double max_roundness_error_m = 0.0;  ///< spread of the crown radius round the circle
  /// The largest cord strain (Green-Lagrange) at the step's history rows
  /// (CalcMaxCordStrain; the stable step assumes at most kCordStrainAllowance).
  double max_cord_strain = 0.0;
  std::vector<HistoryRow> history;
};

/// One road-contact node at the end of the footprint step.
struct ContactPoint {
  double x_m = 0.0, y_m = 0.0;  ///< on the road, the rim centre above x = 0
  double force_N = 0.0;
  double pressure_Pa = 0.0;  ///< force over the node's share of the outer surface
};

struct FootprintResult {
  double vertical_load_N = 0.0;
  double road_force_z_N = 0.0;              ///< the road's reaction at the end
  double loaded_radius_m = 0.0;             ///< rim centre to road
  double deflection_m = 0.0;                ///< inflated outer radius less loaded radius
  double vertical_stiffness_N_per_m = 0.0;  ///< load over deflection (secant)
  double contact_area_m2 = 0.0;
  double contact_length_m = 0.0, contact_width_m = 0.0;
  double peak_pressure_Pa = 0.0, mean_pressure_Pa = 0.0;
  /// The largest cord strain (Green-Lagrange) at the step's history rows
  /// (CalcMaxCordStrain; the stable step assumes at most kCordStrainAllowance).
  double max_cord_strain = 0.0;
  std::vector<ContactPoint> contact;
  std::vector<HistoryRow> history;
};

struct RollResult {
  double speed_mps = 0.0;
  double spin_rad_per_s = 0.0;              ///< mean over the second half of the step
  double effective_radius_m = 0.0;          ///< speed / spin
  double loaded_radius_m = 0.0;             ///< mean rim height over the road, second half
  double road_fx_N = 0.0, road_fz_N = 0.0;  ///< means over the second half
  /// The largest cord strain (Green-Lagrange) at the step's history rows
  /// (CalcMaxCordStrain; the stable step assumes at most kCordStrainAllowance).
  double max_cord_strain = 0.0;
  std::vector<HistoryRow> history;
};

/// Brake torque magnitude (>= 0, N m) from the time, the rim's forward speed and its spin.
using BrakeTorqueFn = std::function<double(double t, double vx_mps, double spin_rad_per_s)>;

struct BrakeResult {
  double initial_speed_mps = 0.0, final_speed_mps = 0.0;
  double max_slip = 0.0;
  double max_brake_torque_Nm = 0.0;  ///< largest torque magnitude applied
  double distance_m = 0.0;
  /// The largest cord strain (Green-Lagrange) at the step's history rows
  /// (CalcMaxCordStrain; the stable step assumes at most kCordStrainAllowance).
  double max_cord_strain = 0.0;
  std::vector<HistoryRow> history;
};

/// Where TyreRun::RunUntil is within a step.
struct StepCursor {
  double t0 = 0.0;               ///< the step's start, s
  double next_history = 0.0;     ///< time of the last history row, s
  std::int64_t next_frame = 0;   ///< the next deformed-shape frame
  std::int64_t calls = 0;        ///< steps taken in this step (progress lines every 2000)
  double max_cord_strain = 0.0;  ///< the largest at the history rows so far
};

/// The braking step's own state.
struct BrakeStep {
  bool active = false;
  double t0 = 0.0;       ///< start time, s
  double x0 = 0.0;       ///< rim position at the start, m
  double applied = 0.0;  ///< torque of the last step, N m
  std::vector<HistoryRow> history;
};

/// A TyreRun's state besides the solver's: what its checkpoint saves with it, whole.
struct TyreRunState {
  double road_z_m = 0.0;  ///< the road's height (set by the footprint step)
  double inflated_radius_m = 0.0, loaded_radius_m = 0.0, rolling_radius_m = 0.0;
  StepCursor cursor;
  BrakeStep brake;
};

// The fields of each struct, in checkpoint order (visit_fields.h).

HOTLAP_VISIT_FIELDS(HistoryRow, time_s, rim_x_m, rim_z_m, rim_vx_mps, spin_rad_per_s,
                    brake_torque_Nm, road_fx_N, road_fz_N, slip, energies)

HOTLAP_VISIT_FIELDS(StepCursor, t0, next_history, next_frame, calls, max_cord_strain)

HOTLAP_VISIT_FIELDS(BrakeStep, active, t0, x0, applied, history)

HOTLAP_VISIT_FIELDS(TyreRunState, road_z_m, inflated_radius_m, loaded_radius_m, rolling_radius_m,
                    cursor, brake)

/// The tyre model and its state across the steps.
class TyreRun {
 public:
  explicit TyreRun(const FeConfig& config);

  InflateResult Inflate(const StepHooks& hooks);
  /// Needs Inflate first. The road is placed under the inflated tyre, the rim pressed down.
  FootprintResult Footprint(const StepHooks& hooks);
  /// Needs Footprint first. The rim is driven forward at the configured speed with its spin free.
  RollResult Roll(const StepHooks& hooks);
  /// Needs Roll first. The rim carries a quarter-car mass (load / g) free along x and the brake
  /// torque opposes its spin (regularised near zero spin). Runs for `duration_s`.
  BrakeResult Brake(double duration_s, const BrakeTorqueFn& torque, const StepHooks& hooks);
  /// Continues a braking step restored by LoadState until `duration_s` after its start; the
  /// result covers the whole step (its history from the start).
  BrakeResult ResumeBrake(double duration_s, const BrakeTorqueFn& torque, const StepHooks& hooks);

  /// Writes the state of a braking step in progress (or just ended): the run's (TyreRunState:
  /// the radii of the earlier steps, the step's position and history) and the solver's, each
  /// whole (field_io.h). Throws if no braking step ran.
  void SaveState(BinaryWriter& out) const;
  /// Reads what SaveState wrote (InputError via the reader if it does not fit).
  void LoadState(BinaryReader& in);
  /// The braking step's start time, s (once Brake ran or LoadState read one).
  double brake_start_s() const { return state_.brake.t0; }

  const FeConfig& config() const { return config_; }
  const TyreMesh& tyre() const { return tyre_; }
  const ExplicitSolver& solver() const { return solver_; }
  /// For benchmarks and tools that step the solver themselves.
  ExplicitSolver& mutable_solver() { return solver_; }
  double loaded_radius_m() const { return state_.loaded_radius_m; }
  /// The R_l of the slip (002:2): the free-rolling radius V / omega once Roll has run (the paper's
  /// "loaded radius from step four" is that ratio: 11.165 / 28.268 = 395 mm), else the loaded
  /// radius from the footprint.
  double slip_radius_m() const {
    return state_.rolling_radius_m > 0.0 ? state_.rolling_radius_m : state_.loaded_radius_m;
  }
  /// The run's own state (the solver's is solver().state()).
  const TyreRunState& state() const { return state_; }

 private:
  HistoryRow Row(double torque) const;
  /// Steps until `t_end`, calling `each` before every step, recording history and hooks. With
  /// `resume`, continues from state_.cursor (no new first history row).
  void RunUntil(const std::string& step, double t_end, const StepHooks& hooks,
                const std::function<void()>& each, std::vector<HistoryRow>& history,
                const double* torque, bool resume = false);
  BrakeResult RunBrake(double duration_s, const BrakeTorqueFn& torque, const StepHooks& hooks,
                       bool resume);
  double OuterRadiusMean() const;

  FeConfig config_;
  TyreMesh tyre_;
  ExplicitSolver solver_;
  TyreRunState state_;
};

}  // namespace hotlap::fe
