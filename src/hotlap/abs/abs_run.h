#pragma once
/// @file
/// One ABS braking event: the controller (brake/abs_controller.h) ticking at its fixed period,
/// the hydraulic delay, and the plant (abs_plant.h) integrated between ticks, with the brake's
/// disc and calliper heated by the brake power (brake/brake_thermal.h). docs/abs.md.
///
/// How to use:
///
///   const sim::AbsConfig config = sim::LoadAbsConfig(sim::DefaultAbsConfigPath());
///   const sim::AbsRunResult run = sim::RunAbs(config, config.event);
///   const sim::AbsMetrics m = sim::CalcAbsMetrics(config, run);   // abs_metrics.h
///
/// Time stepping: at each controller tick t_k = k T the sensors are read (Vx, omega, the driver's
/// pressure), the controller commands a pressure target, the target enters the delay line, and
/// the plant is integrated to t_{k+1} in `steps_per_period` classical RK4 steps with the delayed
/// target held. Inside a step the run locates, by the Illinois method on the step fraction, the
/// moments where the wheel stops (omega = 0: the brake then holds it), where the holding torque
/// exceeds the brake's capacity (it spins again), where the vehicle reaches the stop speed, and
/// where the road changes segment, and restarts the step there; so each step's right-hand side is
/// smooth except for the tyre's own kinks and the hydraulics' rate limits.
///
/// The disc/calliper model is stepped once per tick (one RK4 step; its time constants are tens
/// of seconds) with the tick's mean brake power, the energy the plant's quadrature gave, and the
/// tick's mean speed for convection; so every joule of brake heat reaches the disc. Temperatures
/// between ticks are interpolated linearly for the records.

#include <optional>
#include <vector>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_plant.h"
#include "hotlap/brake/brake_thermal.h"

namespace hotlap::sim {

/// The records of one run: one entry at t = 0, at the start of every integration step and at
/// the end. SI units; temperatures in K.
struct AbsHistory {
  std::vector<double> time;             ///< s
  std::vector<double> distance;         ///< m
  std::vector<double> speed;            ///< Vx, m/s
  std::vector<double> wheel_speed;      ///< omega, rad/s
  std::vector<double> lambda;           ///< braking slip (Vx - R_l omega) / Vx (002:2), 1
  std::vector<double> transient_slip;   ///< kappa', 1 (< 0 braking)
  std::vector<double> driver_pressure;  ///< Pa
  std::vector<double> pressure_target;  ///< the delayed target the hydraulics follow, Pa
  std::vector<double> pressure;         ///< wheel-cylinder pressure, Pa
  std::vector<double> brake_torque;     ///< torque the brake applies, N m
  std::vector<double> fx;               ///< N (< 0 braking)
  std::vector<double> friction;         ///< road friction mu(v_s), 1
  std::vector<double> disc_temp;        ///< K
  std::vector<double> calliper_temp;    ///< K
  std::vector<int> state;               ///< brake::AbsState as int; -1 without ABS
  std::vector<int> locked;              ///< 1 while the brake holds the wheel stopped

  size_t size() const { return time.size(); }
};

/// What one run gives.
struct AbsRunResult {
  AbsHistory history;
  std::vector<double> cycle_starts_s;     ///< ticks at which the controller began a control cycle
  std::optional<double> abs_exit_s;       ///< first tick in kExit after braking began
  bool stopped = false;                   ///< the vehicle reached the stop speed
  double end_time_s = 0.0;                ///< time of the last record, s
  AbsPlantState<double> initial;          ///< plant state at t = 0
  AbsPlantState<double> final;            ///< plant state at the end
  brake::BrakeState<double> final_brake;  ///< disc and calliper at the end, K
  double ambient_temp_K = 0.0;            ///< the cooling air of the run
  int steps = 0;                          ///< integration steps taken (events included)
};

/// Runs one braking event of `config` as `event` says (its surface, speeds, control and so on;
/// pass `config.event` for the file's own). InputError for an unknown surface; NumericalError if
/// the state stops being finite.
AbsRunResult RunAbs(const AbsConfig& config, const AbsEvent& event);

}  // namespace hotlap::sim
