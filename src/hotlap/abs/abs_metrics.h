#pragma once
/// @file
/// What an ABS run achieved: stopping, the control cycles, how well the slip was held, whether
/// the wheel locked, the brake's temperatures, and the energy balance (docs/abs.md, where each
/// is defined precisely; the JSON keys of `hotlap abs` are these).

#include <optional>

#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_run.h"

namespace hotlap::sim {

/// Slip held "below about 0.135" in the paper (002 §3.3, Figure 10).
inline constexpr double kPaperSlipLimit = 0.135;
/// A wheel counts as locked at lambda >= 0.95 (omega R_l <= 0.05 Vx) or when held stopped.
inline constexpr double kLockedSlip = 0.95;

/// The energy balance of a run, J. Balance: kinetic_lost + drum_work = brake + tyre_slip +
/// rolling_resistance; `closure_error` is (right - left) / left.
struct AbsEnergy {
  double kinetic_lost_J = 0.0;        ///< (m Vx^2 + J omega^2)/2 at the start minus at the end
  double drum_work_J = 0.0;           ///< work the drum did holding Vx (drum mode), else 0
  double brake_J = 0.0;               ///< brake heat, integral of T_b omega
  double tyre_slip_J = 0.0;           ///< integral of -Fx (Vx - R_l omega)
  double rolling_resistance_J = 0.0;  ///< integral of -My omega
  double closure_error = 0.0;         ///< relative, see above
};

/// The control cycles of a braking event and how well the slip was held after the first one.
struct CycleWindow {
  int cycles = 0;  ///< control cycles (pressure releases that begin one)
  /// cycles / ABS-active time, from the first cycle's start to the ABS exit (or the end); 0
  /// without cycles.
  double cycles_per_s = 0.0;
  std::optional<double> first_cycle_start_s;
  std::optional<double> second_cycle_start_s;  ///< the first cycle ends here
  /// Largest lambda sampled from the second cycle's start until the ABS exit (or the end); none
  /// with fewer than two cycles or no sample there.
  std::optional<double> max_lambda_after_first_cycle;
  /// Share of that same window with lambda < kPaperSlipLimit (time-weighted, linear between
  /// samples); none with fewer than two cycles or an empty window.
  std::optional<double> fraction_time_lambda_below_0_135;
};

/// The figures of one run: its control cycles and the window after the first (CycleWindow),
/// and the rest below.
struct AbsMetrics : CycleWindow {
  bool stopped = false;
  std::optional<double> stop_time_s;          ///< when Vx reached the stop speed
  std::optional<double> stopping_distance_m;  ///< distance travelled by then
  double distance_m = 0.0;                    ///< distance travelled in the run
  double end_time_s = 0.0;
  double final_speed_mps = 0.0;
  double mean_deceleration_mps2 = 0.0;  ///< (Vx(0) - Vx(end)) / end time

  std::optional<double> abs_exit_s;  ///< first tick in kExit after braking began
  double max_lambda = 0.0;           ///< largest lambda while Vx >= the exit speed
  /// lambda >= kLockedSlip, or the wheel held stopped, while Vx >= the exit speed.
  bool wheel_locked = false;

  double peak_disc_temp_K = 0.0;
  double peak_calliper_temp_K = 0.0;
  double final_disc_temp_K = 0.0;
  AbsEnergy energy;
};

/// The window of CycleWindow from a history (`time` increasing, `lambda` the braking slip at
/// each), the times at which the controller began each cycle, its exit (if it came) and the end
/// of the event, all on the history's clock. Used by CalcAbsMetrics and by the FE tyre's ABS stop.
CycleWindow CalcCycleWindow(const std::vector<double>& time, const std::vector<double>& lambda,
                            const std::vector<double>& cycle_starts_s,
                            std::optional<double> abs_exit_s, double end_time_s);

/// The figures of `run`, made with `config` (its wheel for the energies, its controller's exit
/// speed for the windows).
AbsMetrics CalcAbsMetrics(const AbsConfig& config, const AbsRunResult& run);

/// Time-weighted share of [t_from, t_to] in which `values` (sampled at `times`, linear between
/// samples) is below `limit`, in [0, 1]; 1 for an empty window.
double FractionOfTimeBelow(const std::vector<double>& times, const std::vector<double>& values,
                           double limit, double t_from, double t_to);

}  // namespace hotlap::sim
