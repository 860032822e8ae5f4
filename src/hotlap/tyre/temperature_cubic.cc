#include "hotlap/tyre/temperature_cubic.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"

namespace hotlap::tyre {

namespace {
std::string Celsius(double kelvin) { return fmt::format("{:g} degC", KelvinToCelsius(kelvin)); }
}  // namespace

TemperatureCubic TemperatureCubic::Create(const TemperatureCubicSpec& s, const std::string& what) {
  const auto fail = [&](const std::string& message) { throw InputError(what + ": " + message); };
  if (!(s.valid_min_temp < s.valid_max_temp)) {
    fail(fmt::format("valid range [{}, {}] is empty", Celsius(s.valid_min_temp),
                     Celsius(s.valid_max_temp)));
  }
  if (!(s.low_temp < s.optimal_temp && s.optimal_temp < s.high_temp)) {
    fail(
        fmt::format("temperatures must be distinct and ordered low < optimal < high; got low {}, "
                    "optimal {}, high {}",
                    Celsius(s.low_temp), Celsius(s.optimal_temp), Celsius(s.high_temp)));
  }
  if (s.low_temp < s.valid_min_temp || s.high_temp > s.valid_max_temp) {
    fail(fmt::format("low and high temperatures ({}, {}) must lie inside the valid range [{}, {}]",
                     Celsius(s.low_temp), Celsius(s.high_temp), Celsius(s.valid_min_temp),
                     Celsius(s.valid_max_temp)));
  }

  // (000:6) in the shifted variable x = T - T_opt: rows are g(0) = 1, g'(0) = 0, g(x_low),
  // g(x_high); unknowns are a, b, c, d.
  const double xl = s.low_temp - s.optimal_temp;
  const double xh = s.high_temp - s.optimal_temp;
  Eigen::Matrix4d m;
  m << 0, 0, 0, 1,                   //
      0, 0, 1, 0,                    //
      xl * xl * xl, xl * xl, xl, 1,  //
      xh * xh * xh, xh * xh, xh, 1;
  const Eigen::Vector4d rhs(1.0, 0.0, s.low_value, s.high_value);
  const Eigen::Vector4d coeff = m.fullPivLu().solve(rhs);
  const TemperatureCubic cubic(s, coeff[0], coeff[1], coeff[2], coeff[3]);

  // Candidate extrema on the valid range: the ends and the stationary points x = 0 and
  // x = -2b/(3a) (roots of 3a x^2 + 2b x).
  std::vector<double> candidates = {s.valid_min_temp, s.valid_max_temp, s.optimal_temp};
  if (std::abs(cubic.a_) > 0.0) {
    const double x2 = -2.0 * cubic.b_ / (3.0 * cubic.a_);
    const double t2 = s.optimal_temp + x2;
    if (t2 > s.valid_min_temp && t2 < s.valid_max_temp) candidates.push_back(t2);
  }
  double min_value = HUGE_VAL, max_value = -HUGE_VAL, min_at = 0.0, max_at = 0.0;
  for (double t : candidates) {
    const double v = cubic.Evaluate(t);
    if (v < min_value) min_value = v, min_at = t;
    if (v > max_value) max_value = v, max_at = t;
  }
  if (min_value <= 0.0) {
    fail(fmt::format(
        "the cubic is not positive on its valid range [{}, {}]: it reaches {:.4g} at "
        "{}; move the low/high values closer to 1 or narrow the valid range",
        Celsius(s.valid_min_temp), Celsius(s.valid_max_temp), min_value, Celsius(min_at)));
  }
  constexpr double kTol = 1e-12;
  if (s.kind == CubicKind::kGripMaximum && (cubic.b_ >= 0.0 || max_value > 1.0 + kTol)) {
    fail(
        fmt::format("the optimal temperature {} is not the grip maximum on the valid range (the "
                    "cubic reaches {:.4g} at {}); low and high values must be below 1",
                    Celsius(s.optimal_temp), max_value, Celsius(max_at)));
  }
  if (s.kind == CubicKind::kWearMinimum && (cubic.b_ <= 0.0 || min_value < 1.0 - kTol)) {
    fail(
        fmt::format("the optimal temperature {} is not the wear-rate minimum on the valid range "
                    "(the cubic reaches {:.4g} at {}); low and high values must be above 1",
                    Celsius(s.optimal_temp), min_value, Celsius(min_at)));
  }
  return cubic;
}

double TemperatureCubic::Slope(double temp) const {
  if (temp <= spec_.valid_min_temp || temp >= spec_.valid_max_temp) return 0.0;
  const double x = temp - spec_.optimal_temp;
  return (3.0 * a_ * x + 2.0 * b_) * x + c_;
}

}  // namespace hotlap::tyre
