#include "hotlap/fe/abs_slip_summary.h"

#include <algorithm>
#include <limits>

namespace hotlap::fe {

BrakeSlipSummary SummarizeBrakeSlip(const std::vector<HistoryRow>& history,
                                    std::span<const double> cycle_starts_s) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  BrakeSlipSummary out{.first_cycle_end_s = kNaN,
                       .max_slip_after_first_cycle = kNaN,
                       .fraction_time_below_0_135_after_first_cycle = kNaN};
  for (const HistoryRow& r : history) out.max_slip = std::max(out.max_slip, r.slip);
  out.cycles = static_cast<int>(cycle_starts_s.size());
  if (history.empty() || cycle_starts_s.empty()) return out;
  const double end = history.back().time_s;
  const double active = end - cycle_starts_s.front();
  out.cycles_per_s = active > 0.0 ? out.cycles / active : 0.0;
  if (cycle_starts_s.size() < 2) return out;
  const double from = cycle_starts_s[1];
  out.first_cycle_end_s = from;
  double below = 0.0, span = 0.0, peak = 0.0;
  for (size_t k = 0; k < history.size(); ++k) {
    if (history[k].time_s < from) continue;
    peak = std::max(peak, history[k].slip);
    if (k + 1 == history.size()) break;
    const double dt = history[k + 1].time_s - history[k].time_s;
    span += dt;
    if (history[k].slip < kPaperSlipTarget) below += dt;
  }
  out.max_slip_after_first_cycle = peak;
  out.fraction_time_below_0_135_after_first_cycle = span > 0.0 ? below / span : 1.0;
  return out;
}

}  // namespace hotlap::fe
