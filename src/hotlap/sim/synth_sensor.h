#pragma once
/// @file
/// What a sensor does to the quantity it measures, for synthetic logs (synth.h) and for fits
/// that model it (ident/): a first-order lag and seeded Gaussian noise.
///
/// The lag is tau dy/dt = x(t) - y with x linear between samples, solved exactly over each
/// interval: y1 = a y0 + (1 - a) x0 + (1 - tau (1 - a) / dt) (x1 - x0), a = exp(-dt / tau). A
/// ramp of slope s is read s tau late, and a step reaches 63% after tau. The sensor starts
/// settled (y = x at the first sample). Templated so a fit can differentiate through it.

#include <cmath>
#include <cstdint>
#include <random>

#include "hotlap/common/scalar.h"

namespace hotlap::sim {

/// A first-order sensor of time constant tau (s); tau <= 0 reads the true value.
template <Scalar T>
class FirstOrderLag {
 public:
  explicit FirstOrderLag(double tau_s) : tau_(tau_s) {}

  /// The reading at time `t_s` (after the previous call's time) of the true value `x`.
  T Next(double t_s, const T& x) {
    if (!started_ || !(tau_ > 0.0)) {
      started_ = true;
      t_ = t_s;
      x_ = x;
      y_ = x;
      return y_;
    }
    const double dt = t_s - t_;
    const double a = std::exp(-dt / tau_);
    const double b = 1.0 - tau_ * (1.0 - a) / dt;
    y_ = a * y_ + (1.0 - a) * x_ + b * (x - x_);
    t_ = t_s;
    x_ = x;
    return y_;
  }

 private:
  double tau_;
  bool started_ = false;
  double t_ = 0.0;
  T x_{}, y_{};
};

/// Standard normal numbers from a seeded 64-bit Mersenne Twister by the Box-Muller transform:
/// the same sequence on every platform (std::normal_distribution's algorithm is not specified).
class GaussianNoise {
 public:
  explicit GaussianNoise(uint64_t seed) : engine_(seed) {}

  /// The next N(0, 1) number.
  double Next() {
    if (have_spare_) {
      have_spare_ = false;
      return spare_;
    }
    // Two uniforms in (0, 1] from 53 random bits each.
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    const double radius = std::sqrt(-2.0 * std::log(u1));
    constexpr double kTwoPi = 6.283185307179586;
    spare_ = radius * std::sin(kTwoPi * u2);
    have_spare_ = true;
    return radius * std::cos(kTwoPi * u2);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool have_spare_ = false;
};

}  // namespace hotlap::sim
