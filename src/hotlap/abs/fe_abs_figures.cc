#include "hotlap/abs/fe_abs_figures.h"

#include <algorithm>

#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/ensemble_stats.h"

namespace hotlap::sim {

FeAbsFigures CalcFeAbsFigures(const FeAbsStopResult& r, double duration_s) {
  FeAbsFigures f;
  const fe::BrakeResult& br = r.brake;
  const double t0 = br.history.empty() ? 0.0 : br.history.front().time_s;
  f.cycles = r.cycles.cycles;
  f.cycles_per_s = r.cycles.cycles_per_s;
  f.fraction_below_0_135 = r.cycles.fraction_time_lambda_below_0_135;
  if (r.cycles.first_cycle_start_s) f.first_release_s = *r.cycles.first_cycle_start_s - t0;
  f.distance_m = br.distance_m;
  if (duration_s > 0.0) {
    f.mean_deceleration_mps2 = (br.initial_speed_mps - br.final_speed_mps) / duration_s;
  }
  if (r.cycles.second_cycle_start_s) {
    const double from = *r.cycles.second_cycle_start_s;
    // The window as CalcCycleWindow takes it (the last row is its end, not in it).
    const double to = r.abs_exit_s ? *r.abs_exit_s : br.history.back().time_s;
    std::vector<double> window;
    for (const fe::HistoryRow& row : br.history) {
      if (row.time_s >= from && row.time_s < to) window.push_back(row.slip);
    }
    if (!window.empty()) {
      double sum = 0.0;
      for (double s : window) sum += s;
      f.slip_mean = sum / static_cast<double>(window.size());
      f.slip_max = *std::max_element(window.begin(), window.end());
      f.slip_p99 = Quantile(std::move(window), 0.99);
    }
  }
  return f;
}

std::vector<FeAbsFigureValue> ListFeAbsFigures(const FeAbsFigures& f) {
  return {{"fraction_below_0_135", "", f.fraction_below_0_135},
          {"slip_p99", "", f.slip_p99},
          {"slip_mean", "", f.slip_mean},
          {"slip_max", "", f.slip_max},
          {"cycles_per_s", "1/s", f.cycles_per_s},
          {"first_release_s", "s", f.first_release_s},
          {"distance_m", "m", f.distance_m},
          {"mean_deceleration_mps2", "m/s^2", f.mean_deceleration_mps2}};
}

}  // namespace hotlap::sim
