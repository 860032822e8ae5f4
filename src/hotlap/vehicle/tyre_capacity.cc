#include "hotlap/vehicle/tyre_capacity.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hotlap::vehicle {

namespace {

// The largest value of f over (0, x_max]: a coarse scan, then golden-section refinement around
// the best scan point.
template <class F>
double PeakOf(F f, double x_max) {
  constexpr int kScan = 24;
  double best_x = x_max / kScan, best = f(best_x);
  for (int i = 2; i <= kScan; ++i) {
    const double x = x_max * i / kScan;
    const double v = f(x);
    if (v > best) {
      best = v;
      best_x = x;
    }
  }
  double lo = std::max(best_x - x_max / kScan, 1e-6 * x_max);
  double hi = std::min(best_x + x_max / kScan, x_max);
  constexpr double kGolden = 0.6180339887498949;
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 14; ++i) {
    if (f1 > f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kGolden * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kGolden * (hi - lo);
      f2 = f(x2);
    }
  }
  return std::max({best, f1, f2});
}

}  // namespace

TyrePeaks FindTyrePeaks(const CornerSetup& corner, double fz, double speed) {
  TyrePeaks peaks;
  if (!(fz > 0.0)) return peaks;
  tyre::TyreOperatingPoint<double> op;
  op.fz = fz;
  op.camber = corner.camber;
  op.speed = speed;
  op.pressure = corner.pressure;
  const auto fx = [&](double kappa) {
    op.slip_ratio = kappa;
    op.slip_angle = 0.0;
    return tyre::CalcTyreForces(corner.forces, op).fx;
  };
  const auto fy = [&](double alpha) {
    op.slip_ratio = 0.0;
    op.slip_angle = alpha;
    return tyre::CalcTyreForces(corner.forces, op).fy;
  };
  peaks.drive = std::max(0.0, PeakOf([&](double k) { return fx(k); }, 0.6));
  peaks.brake = std::max(0.0, PeakOf([&](double k) { return -fx(-k); }, 0.6));
  // ISO-W: a negative slip angle pushes the tyre to the left.
  peaks.left = std::max(0.0, PeakOf([&](double a) { return fy(-a); }, 0.4));
  peaks.right = std::max(0.0, PeakOf([&](double a) { return -fy(a); }, 0.4));
  return peaks;
}

TyreCapacity::TyreCapacity(const CornerSetup& corner, double max_load_N, int points, double speed)
    : max_load_(max_load_N), step_(max_load_N / (points - 1)) {
  if (points < 2 || !(max_load_N > 0.0)) {
    throw std::invalid_argument("TyreCapacity: need >= 2 points and a positive load range");
  }
  table_.reserve(points);
  for (int i = 0; i < points; ++i) table_.push_back(FindTyrePeaks(corner, i * step_, speed));
}

TyrePeaks TyreCapacity::At(double fz) const {
  if (!(fz > 0.0)) return {};
  const double x = fz / step_;
  const int n = static_cast<int>(table_.size());
  const int i = std::clamp(static_cast<int>(x), 0, n - 2);
  const double w = x - i;
  const TyrePeaks& a = table_[i];
  const TyrePeaks& b = table_[i + 1];
  const auto lerp = [w](double p, double q) { return std::max(0.0, p + w * (q - p)); };
  return {lerp(a.drive, b.drive), lerp(a.brake, b.brake), lerp(a.left, b.left),
          lerp(a.right, b.right)};
}

}  // namespace hotlap::vehicle
