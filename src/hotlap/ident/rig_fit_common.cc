#include "hotlap/ident/rig_fit_common.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::ident::internal {

void CheckRigSamples(std::span<const RigSample> samples) {
  for (size_t i = 0; i < samples.size(); ++i) {
    const RigSample& s = samples[i];
    const bool finite = std::isfinite(s.slip_angle) && std::isfinite(s.slip_ratio) &&
                        std::isfinite(s.camber) && std::isfinite(s.speed) &&
                        std::isfinite(s.tread_temp) && std::isfinite(s.fy) && std::isfinite(s.mz) &&
                        (!s.fx || std::isfinite(*s.fx));
    if (!finite) throw InputError(fmt::format("rig sample {}: a value is not a finite number", i));
    if (!(s.fz > 0.0) || !std::isfinite(s.fz)) {
      throw InputError(fmt::format("rig sample {}: fz {:g} N must be > 0", i, s.fz));
    }
    if (!(s.tread_temp > 0.0)) {
      throw InputError(
          fmt::format("rig sample {}: tread_temp {:g} K must be > 0 (kelvin)", i, s.tread_temp));
    }
  }
}

std::pair<double, double> LineFit(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  const double c1 = sxx > 0.0 ? sxy / sxx : 0.0;
  return {my - c1 * mx, c1};
}

double ZeroSlipSlope(std::span<const double> x, std::span<const double> y) {
  std::vector<double> levels;
  for (double v : x) {
    if (std::abs(v) > 1e-9) levels.push_back(std::abs(v));
  }
  std::sort(levels.begin(), levels.end());
  std::vector<double> distinct;
  for (double l : levels) {
    if (distinct.empty() || l > distinct.back() * (1.0 + 1e-6)) distinct.push_back(l);
  }
  if (distinct.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto secant = [&](double level) {
    double sxy = 0.0, sxx = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
      if (std::abs(std::abs(x[i]) - level) <= 1e-6 * level) {
        sxy += x[i] * y[i];
        sxx += x[i] * x[i];
      }
    }
    return sxy / sxx;
  };
  const double k1 = secant(distinct[0]);
  if (distinct.size() < 2) return k1;
  const double k2 = secant(distinct[1]);
  const double w = distinct[0] / (distinct[1] - distinct[0]);
  return std::clamp(k1 - (k2 - k1) * w, std::min(k1, 1.5 * k1), std::max(k1, 1.5 * k1));
}

ValueGroups GroupValues(const std::vector<double>& values, double tolerance, GroupTolerance kind) {
  std::vector<size_t> order(values.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
  ValueGroups g;
  g.index.assign(values.size(), -1);
  std::vector<int> count;
  double last = 0.0;
  for (size_t k = 0; k < order.size(); ++k) {
    const double v = values[order[k]];
    const double tol = kind == GroupTolerance::kRelative ? tolerance * std::abs(v) : tolerance;
    if (k == 0 || v - last > tol) {
      g.mean.push_back(0.0);
      count.push_back(0);
    }
    g.index[order[k]] = static_cast<int>(g.mean.size()) - 1;
    g.mean.back() += v;
    ++count.back();
    last = v;
  }
  for (size_t i = 0; i < g.mean.size(); ++i) g.mean[i] /= count[i];
  return g;
}

}  // namespace hotlap::ident::internal
