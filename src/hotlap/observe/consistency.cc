#include "hotlap/observe/consistency.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hotlap::observe {

std::string_view SensorQuantity(Sensor s) {
  switch (s) {
    case Sensor::kTread:
      return "tread_temp";
    case Sensor::kDisc:
      return "disc_temp";
    case Sensor::kCalliper:
      return "calliper_temp";
    case Sensor::kPressure:
      return "pressure";
    case Sensor::kGasTemp:
      return "gas_temp";
  }
  return "";
}

std::pair<double, double> MeanNisBounds95(long n) {
  if (n <= 0) return {0.0, std::numeric_limits<double>::infinity()};
  // chi2_p(n) ~ n (1 - 2/(9n) + z_p sqrt(2/(9n)))^3, z = 1.959964 for 2.5% and 97.5%.
  constexpr double kZ = 1.959963984540054;
  const double a = 2.0 / (9.0 * static_cast<double>(n));
  const double lo = std::max(0.0, 1.0 - a - kZ * std::sqrt(a));
  const double hi = 1.0 - a + kZ * std::sqrt(a);
  return {lo * lo * lo, hi * hi * hi};
}

double SensorMonitor::MeanNis() const {
  return used > 0 ? nis_sum / static_cast<double>(used) : std::numeric_limits<double>::quiet_NaN();
}

bool SensorMonitor::GateRejectsTooMany() const {
  return rejected > kMaxRejectedFraction * static_cast<double>(used + rejected);
}

bool SensorMonitor::Consistent() const {
  if (GateRejectsTooMany()) return false;
  if (used == 0) return true;
  const auto [lo, hi] = Bounds95();
  const double m = MeanNis();
  return m >= lo && m <= hi;
}

std::optional<double> SensorMonitor::Record(double time_s, double nis, bool was_used,
                                            double window_s, double threshold, double after_s) {
  if (was_used) {
    ++used;
    nis_sum += nis;
  } else {
    ++rejected;
  }
  // Running mean with time constant window_s; a rejected reading counts too (capped, so one wild
  // value cannot hold the mean up for long), since a sensor that is rejected on and on is the
  // disagreement this watches for.
  const double dt = last_time_ ? time_s - *last_time_ : 0.0;
  const double weight = last_time_ ? 1.0 - std::exp(-dt / window_s) : 0.0;
  if (above_since_) disagree_time_s += dt;
  last_time_ = time_s;
  average_ += weight * (std::min(nis, 100.0) - average_);
  if (!(average_ > threshold)) {
    above_since_.reset();
    warned_ = false;
    return std::nullopt;
  }
  if (!above_since_) above_since_ = time_s;
  if (!warned_ && time_s - *above_since_ > after_s) {
    warned_ = true;
    ++disagreements;
    return *above_since_;
  }
  return std::nullopt;
}

}  // namespace hotlap::observe
