#include "hotlap/track/track_summary.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hotlap::track {

namespace {

// Distance from sample b back to where the curvature reaches zero between samples a and b
// (a before b when `direction` = -1, after it when +1), in [0, step]: from the curvature rate
// when the zero is a kink (a clothoid starting off a straight), else by linear interpolation.
double ZeroOffset(const TrackPoint& a, const TrackPoint& b, double step) {
  if (std::abs(a.curvature_per_m) < 1e-12 && b.curvature_rate_per_m2 != 0.0) {
    const double d = std::abs(b.curvature_per_m / b.curvature_rate_per_m2);
    if (d <= step) return d;
  }
  const double ka = std::abs(a.curvature_per_m), kb = std::abs(b.curvature_per_m);
  return ka + kb > 0.0 ? step * kb / (ka + kb) : 0.0;
}

}  // namespace

TrackSummary Summarize(const Track& track, const SummaryOptions& options) {
  const double L = track.length_m();
  const int n = std::max(16, static_cast<int>(std::ceil(L / options.step_m)));
  const double step = L / n;
  std::vector<TrackPoint> p(n);
  for (int i = 0; i < n; ++i) p[i] = track.At(step * i);
  const auto at = [&](int i) -> const TrackPoint& { return p[((i % n) + n) % n]; };

  TrackSummary out;
  out.length_m = L;
  out.winding = track.winding();
  out.closure = track.closure_error();
  double max_kappa = 0.0;
  out.bank_min_rad = out.width_min_m = std::numeric_limits<double>::infinity();
  out.bank_max_rad = out.width_max_m = -std::numeric_limits<double>::infinity();
  for (const TrackPoint& q : p) {
    if (std::abs(q.curvature_per_m) > max_kappa) {
      max_kappa = std::abs(q.curvature_per_m);
      out.min_radius_at_m = q.s_m;
    }
    if (q.bank_rad < out.bank_min_rad) out.bank_min_rad = q.bank_rad, out.bank_min_at_m = q.s_m;
    if (q.bank_rad > out.bank_max_rad) out.bank_max_rad = q.bank_rad, out.bank_max_at_m = q.s_m;
    out.width_min_m = std::min(out.width_min_m, q.width_left_m + q.width_right_m);
    out.width_max_m = std::max(out.width_max_m, q.width_left_m + q.width_right_m);
  }
  out.min_radius_m = max_kappa > 0.0 ? 1.0 / max_kappa : std::numeric_limits<double>::infinity();

  // Turns: runs of samples tighter than the threshold, one direction each.
  const double k_on = 1.0 / options.turn_radius_m;
  const auto sign = [](double k) { return k > 0.0 ? 1 : -1; };
  const auto marked = [&](int i) { return std::abs(at(i).curvature_per_m) >= k_on; };
  // Start scanning where no run is under way, so that no run is cut by the scan's start.
  int first = -1;
  for (int i = 0; i < n && first < 0; ++i) {
    if (!marked(i) || sign(at(i).curvature_per_m) != sign(at(i - 1).curvature_per_m)) first = i;
  }
  if (first < 0) {  // one turn all the way round (a circle)
    if (marked(0)) {
      out.turns.push_back({sign(p[0].curvature_per_m), 0.0, out.min_radius_at_m, 0.0,
                           out.min_radius_m, out.bank_max_rad});
    }
    return out;
  }
  for (int k = 0; k < n;) {
    const int a = first + k;
    if (!marked(a)) {
      ++k;
      continue;
    }
    const int dir = sign(at(a).curvature_per_m);
    int b = a;
    while (b + 1 < first + n && marked(b + 1) && sign(at(b + 1).curvature_per_m) == dir) ++b;
    k = b - first + 1;
    // Extend back while the curvature keeps falling in this direction, and forward likewise.
    int e = a;
    while (e > a - n + 1 && dir * at(e - 1).curvature_per_m > 0.0 &&
           dir * at(e - 1).curvature_per_m < dir * at(e).curvature_per_m) {
      --e;
    }
    int x = b;
    while (x < b + n - 1 && dir * at(x + 1).curvature_per_m > 0.0 &&
           dir * at(x + 1).curvature_per_m < dir * at(x).curvature_per_m) {
      ++x;
    }
    TrackTurn turn;
    turn.direction = dir;
    double entry = step * e, exit = step * x;
    if (dir * at(e - 1).curvature_per_m <= 0.0) entry -= ZeroOffset(at(e - 1), at(e), step);
    if (dir * at(x + 1).curvature_per_m <= 0.0) exit += ZeroOffset(at(x + 1), at(x), step);
    turn.entry_m = track.Wrap(entry);
    turn.exit_m = track.Wrap(exit);
    double best = 0.0;
    turn.max_bank_rad = -std::numeric_limits<double>::infinity();
    for (int i = e; i <= x; ++i) {
      if (dir * at(i).curvature_per_m > best) {
        best = dir * at(i).curvature_per_m;
        turn.apex_m = at(i).s_m;
      }
      turn.max_bank_rad = std::max(turn.max_bank_rad, at(i).bank_rad);
    }
    turn.min_radius_m = 1.0 / best;
    out.turns.push_back(turn);
  }
  std::sort(out.turns.begin(), out.turns.end(),
            [](const TrackTurn& l, const TrackTurn& r) { return l.entry_m < r.entry_m; });
  return out;
}

}  // namespace hotlap::track
