#include "hotlap/ocp/mesh_error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace hotlap::ocp {

double TrapezoidDefect(const std::vector<double>& s, const std::vector<double>& f, int k) {
  const int nodes = static_cast<int>(s.size());
  const int i0 = std::clamp(k - 1, 0, nodes - 4);
  // The Lagrange cubic through the four nodes, at the interval's two Gauss-Legendre points
  // (exact for a cubic).
  const auto cubic = [&](double at) {
    double sum = 0.0;
    for (int i = i0; i < i0 + 4; ++i) {
      double basis = 1.0;
      for (int j = i0; j < i0 + 4; ++j) {
        if (j != i) basis *= (at - s[j]) / (s[i] - s[j]);
      }
      sum += basis * f[i];
    }
    return sum;
  };
  const double h = s[k + 1] - s[k], mid = 0.5 * (s[k] + s[k + 1]);
  const double offset = 0.5 * h / std::sqrt(3.0);
  const double rule = 0.5 * h * (cubic(mid - offset) + cubic(mid + offset));
  return rule - 0.5 * h * (f[k] + f[k + 1]);
}

MeshErrorEstimate EstimateMeshError(const CollocationRates& r) {
  MeshErrorEstimate e;
  if (r.empty()) return e;
  const int nodes = static_cast<int>(r.node_m.size()), intervals = nodes - 1;
  e.interval_s.assign(intervals, 0.0);
  std::vector<double> f(nodes);
  for (int j = 0; j < r.states; ++j) {
    bool any = false;
    for (int k = 0; k < intervals && !any; ++k) any = r.costates[k * r.states + j] != 0.0;
    if (!any) continue;  // a state without defects
    for (int k = 0; k < nodes; ++k) f[k] = r.rates[static_cast<size_t>(k) * r.states + j];
    for (int k = 0; k < intervals; ++k) {
      e.interval_s[k] +=
          r.costates[static_cast<size_t>(k) * r.states + j] * TrapezoidDefect(r.node_m, f, k);
    }
  }
  for (int k = 0; k < intervals; ++k) {
    e.interval_s[k] -= TrapezoidDefect(r.node_m, r.dt_ds, k);
    e.lap_time_error_s += e.interval_s[k];
    e.abs_error_s += std::abs(e.interval_s[k]);
  }
  return e;
}

}  // namespace hotlap::ocp
