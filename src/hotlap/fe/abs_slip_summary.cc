#include "hotlap/fe/abs_slip_summary.h"

#include <algorithm>
#include <limits>

namespace hotlap::fe {

BrakeSlipSummary SummarizeBrakeSlip(const std::vector<HistoryRow>& history) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  BrakeSlipSummary out{.first_cycle_end_s = kNaN,
                       .max_slip_after_first_cycle = kNaN,
                       .fraction_time_below_0_135_after_first_cycle = kNaN};
  const size_t n = history.size();
  size_t after = n;
  bool exceeded = false;
  for (size_t k = 0; k < n; ++k) {
    const double s = history[k].slip;
    out.max_slip = std::max(out.max_slip, s);
    exceeded = exceeded || s > kPaperSlipTarget;
    if (exceeded && after == n && s < kPaperSlipTarget / 3.0) after = k;
  }
  if (after >= n) return out;
  out.first_cycle_end_s = history[after].time_s;
  double below = 0.0, span = 0.0, peak = 0.0;
  for (size_t k = after; k < n; ++k) {
    peak = std::max(peak, history[k].slip);
    if (k + 1 == n) break;
    const double dt = history[k + 1].time_s - history[k].time_s;
    span += dt;
    if (history[k].slip < kPaperSlipTarget) below += dt;
  }
  out.max_slip_after_first_cycle = peak;
  out.fraction_time_below_0_135_after_first_cycle = span > 0.0 ? below / span : 1.0;
  return out;
}

}  // namespace hotlap::fe
