#include "hotlap/abs/ensemble_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hotlap::sim {

EnsembleStat CalcEnsembleStat(const std::vector<double>& values) {
  EnsembleStat s;
  s.n = static_cast<int>(values.size());
  if (values.empty()) return s;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / s.n;
  double ss = 0.0;
  for (double v : values) ss += (v - s.mean) * (v - s.mean);
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  s.min = *lo;
  s.max = *hi;
  // Equal values have no spread (their mean's rounding would otherwise leave one of 1e-16).
  s.sd = s.n > 1 && s.min < s.max ? std::sqrt(ss / (s.n - 1)) : 0.0;
  s.standard_error = s.sd / std::sqrt(static_cast<double>(s.n));
  return s;
}

double EquivalenceBound(const EnsembleStat& a, const EnsembleStat& b, double se_floor) {
  if (a.n == 0 || b.n == 0) return std::numeric_limits<double>::infinity();
  const double sa = std::max(a.standard_error, se_floor);
  const double sb = std::max(b.standard_error, se_floor);
  return std::abs(a.mean - b.mean) + 2.0 * std::sqrt(sa * sa + sb * sb);
}

double Quantile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double r = std::clamp(p, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const size_t i = static_cast<size_t>(std::floor(r));
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (r - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

}  // namespace hotlap::sim
