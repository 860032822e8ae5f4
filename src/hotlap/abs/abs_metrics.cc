#include "hotlap/abs/abs_metrics.h"

#include <algorithm>
#include <cmath>

namespace hotlap::sim {

double FractionOfTimeBelow(const std::vector<double>& times, const std::vector<double>& values,
                           double limit, double t_from, double t_to) {
  if (!(t_to > t_from) || times.size() < 2) return 1.0;
  double below = 0.0;
  for (size_t i = 0; i + 1 < times.size(); ++i) {
    const double ta = std::max(times[i], t_from), tb = std::min(times[i + 1], t_to);
    if (!(tb > ta)) continue;
    // The values at the clipped ends, linear in between.
    const double span = times[i + 1] - times[i];
    const auto at = [&](double t) {
      return values[i] + (values[i + 1] - values[i]) * (t - times[i]) / span;
    };
    const double va = at(ta), vb = at(tb);
    if (va < limit && vb < limit) {
      below += tb - ta;
    } else if (va < limit || vb < limit) {
      // One crossing: the part on the low side.
      const double tc = ta + (tb - ta) * (limit - va) / (vb - va);
      below += va < limit ? tc - ta : tb - tc;
    }
  }
  return std::clamp(below / (t_to - t_from), 0.0, 1.0);
}

CycleWindow CalcCycleWindow(const std::vector<double>& time, const std::vector<double>& lambda,
                            const std::vector<double>& cycle_starts_s,
                            std::optional<double> abs_exit_s, double end_time_s) {
  CycleWindow w;
  w.cycles = static_cast<int>(cycle_starts_s.size());
  const double active_end = abs_exit_s ? *abs_exit_s : end_time_s;
  if (w.cycles > 0) {
    w.first_cycle_start_s = cycle_starts_s.front();
    const double active = active_end - cycle_starts_s.front();
    w.cycles_per_s = active > 0.0 ? w.cycles / active : 0.0;
  }
  if (w.cycles > 1) {
    const double from = cycle_starts_s[1];
    w.second_cycle_start_s = from;
    for (size_t i = 0; i < time.size(); ++i) {
      if (time[i] >= from && time[i] < active_end) {
        w.max_lambda_after_first_cycle =
            std::max(w.max_lambda_after_first_cycle.value_or(lambda[i]), lambda[i]);
      }
    }
    if (active_end > from && time.size() >= 2) {
      w.fraction_time_lambda_below_0_135 =
          FractionOfTimeBelow(time, lambda, kPaperSlipLimit, from, active_end);
    }
  }
  return w;
}

AbsMetrics CalcAbsMetrics(const AbsConfig& config, const AbsRunResult& run) {
  const AbsHistory& h = run.history;
  const double exit_speed = config.controller.exit_speed_mps;
  AbsMetrics m;
  m.stopped = run.stopped;
  m.end_time_s = run.end_time_s;
  m.distance_m = run.final.distance;
  m.final_speed_mps = run.final.speed;
  if (run.stopped) {
    m.stop_time_s = run.end_time_s;
    m.stopping_distance_m = run.final.distance;
  }
  if (run.end_time_s > 0.0) {
    m.mean_deceleration_mps2 = (run.initial.speed - run.final.speed) / run.end_time_s;
  }

  // Control cycles and the window after the first one.
  static_cast<CycleWindow&>(m) =
      CalcCycleWindow(h.time, h.lambda, run.cycle_starts_s, run.abs_exit_s, run.end_time_s);
  m.abs_exit_s = run.abs_exit_s;

  // Slip and locking above the exit speed (below it the ABS lets the wheel lock on purpose).
  for (size_t i = 0; i < h.size(); ++i) {
    if (h.speed[i] < exit_speed) continue;
    m.max_lambda = std::max(m.max_lambda, h.lambda[i]);
    if (h.lambda[i] >= kLockedSlip || h.locked[i] != 0) m.wheel_locked = true;
  }

  // The brake.
  m.peak_disc_temp_K = *std::max_element(h.disc_temp.begin(), h.disc_temp.end());
  m.peak_calliper_temp_K = *std::max_element(h.calliper_temp.begin(), h.calliper_temp.end());
  m.final_disc_temp_K = run.final_brake.disc_temp;

  // Energy: kinetic energy lost plus the drum's work against the heat and losses.
  AbsEnergy& e = m.energy;
  e.kinetic_lost_J = CalcAbsKineticEnergy(config.plant.wheel, run.initial) -
                     CalcAbsKineticEnergy(config.plant.wheel, run.final);
  e.drum_work_J = run.final.drum_energy - run.initial.drum_energy;
  e.brake_J = run.final.brake_energy - run.initial.brake_energy;
  e.tyre_slip_J = run.final.slip_energy - run.initial.slip_energy;
  e.rolling_resistance_J = run.final.rolling_energy - run.initial.rolling_energy;
  const double supplied = e.kinetic_lost_J + e.drum_work_J;
  const double dissipated = e.brake_J + e.tyre_slip_J + e.rolling_resistance_J;
  e.closure_error = supplied != 0.0 ? (dissipated - supplied) / supplied : 0.0;
  return m;
}

}  // namespace hotlap::sim
