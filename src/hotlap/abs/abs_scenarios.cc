#include "hotlap/abs/abs_scenarios.h"

#include <algorithm>
#include <cmath>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/rk4.h"

namespace hotlap::sim {

namespace {

/// The event `base` braked to standstill on `surface` with `control`.
AbsEvent ToStandstill(const AbsConfig& config, const AbsEvent& base, const std::string& surface,
                      AbsControl control) {
  AbsEvent e = base;
  e.surface = surface;
  e.control = control;
  e.vehicle = AbsVehicleMode::kFree;
  e.duration_s = config.scenarios.max_duration_s;
  return e;
}

}  // namespace

std::vector<AbsComparisonRun> RunAbsComparison(const AbsConfig& config, const AbsEvent& base) {
  std::vector<AbsComparisonRun> out;
  for (const Surface& s : config.surfaces) {
    for (AbsControl control : {AbsControl::kAbs, AbsControl::kDriverOnly}) {
      AbsComparisonRun c;
      c.surface = s.name;
      c.control = control;
      c.run = RunAbs(config, ToStandstill(config, base, s.name, control));
      c.metrics = CalcAbsMetrics(config, c.run);
      out.push_back(std::move(c));
    }
  }
  return out;
}

AbsStopSeries RunAbsStopSeries(const AbsConfig& config, const AbsEvent& base) {
  const brake::BrakeThermalParams<double>& bp = config.brake.params;
  AbsStopSeries series;
  AbsEvent e = ToStandstill(config, base, config.scenarios.stop_series_surface, AbsControl::kAbs);
  double t0 = 0.0;
  // Records every `every` seconds of a history, and its last sample.
  const auto append = [&](const std::vector<double>& time, const std::vector<double>& disc,
                          const std::vector<double>& calliper, double every) {
    double next = -1.0;
    for (size_t i = 0; i < time.size(); ++i) {
      if (time[i] < next && i + 1 < time.size()) continue;
      if (!series.time.empty() && t0 + time[i] <= series.time.back()) continue;  // joins
      series.time.push_back(t0 + time[i]);
      series.disc_temp.push_back(disc[i]);
      series.calliper_temp.push_back(calliper[i]);
      next = time[i] + every;
    }
  };
  for (int k = 0; k < config.scenarios.stop_series_count; ++k) {
    series.stop_start_s.push_back(t0);
    const AbsRunResult run = RunAbs(config, e);
    series.stops.push_back(CalcAbsMetrics(config, run));
    const AbsHistory& h = run.history;
    append(h.time, h.disc_temp, h.calliper_temp, 0.01);
    t0 += run.end_time_s;

    // Cooling at the initial speed until the next stop, in RK4 steps of at most 0.5 s.
    const double interval = config.scenarios.stop_series_interval_s;
    brake::BrakeState<double> x = run.final_brake;
    if (interval > 0.0 && k + 1 < config.scenarios.stop_series_count) {
      const brake::BrakeInputTerms<double> terms =
          brake::CalcBrakeInputTerms(bp, {base.initial_speed_mps, 0.0, base.ambient_temp_K});
      const int n = std::max(1, static_cast<int>(std::ceil(interval / 0.5)));
      const double h_cool = interval / n;
      std::vector<double> time{0.0}, disc{x.disc_temp}, calliper{x.calliper_temp};
      for (int i = 1; i <= n; ++i) {
        x = Rk4Step(
            [&](double, const brake::BrakeState<double>& s) {
              return brake::CalcBrakeDerivatives(bp, s, terms);
            },
            0.0, x, h_cool);
        time.push_back(i * h_cool);
        disc.push_back(x.disc_temp);
        calliper.push_back(x.calliper_temp);
      }
      append(time, disc, calliper, 0.0);
      t0 += interval;
    }
    e.initial_disc_temp_K = x.disc_temp;
    e.initial_calliper_temp_K = x.calliper_temp;
  }
  return series;
}

}  // namespace hotlap::sim
