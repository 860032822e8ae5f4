#include "hotlap/track/periodic_spline.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/common/units.h"

namespace hotlap::track::internal {
namespace {

// Value of the cubic Hermite with slopes m between knots i and i + 1 at fraction u.
double Hermite(const std::vector<double>& s, const std::vector<double>& y,
               const std::vector<double>& m, double period, size_t i, double u) {
  const size_t j = (i + 1) % s.size();
  const double h = (j == 0 ? period : s[j]) - s[i];
  return (2 * u * u * u - 3 * u * u + 1) * y[i] + (u * u * u - 2 * u * u + u) * h * m[i] +
         (-2 * u * u * u + 3 * u * u) * y[j] + (u * u * u - u * u) * h * m[j];
}

// Uneven knots on [0, 100) and a smooth periodic function on them.
struct Periodic {
  std::vector<double> s, y;
  double period = 100.0;
};

Periodic SineOnUnevenKnots(int n) {
  Periodic p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int i = 0; i < n; ++i) {
    p.s.push_back(p.period * (i + (i == 0 ? 0.0 : jitter(rng))) / n);
    p.y.push_back(std::sin(2 * kPi * p.s.back() / p.period));
  }
  return p;
}

TEST(PeriodicSplineTest, SplineSlopesConvergeToTheDerivative) {
  for (int n : {20, 40}) {
    const Periodic p = SineOnUnevenKnots(n);
    const std::vector<double> m = PeriodicSplineSlopes(p.s, p.y, p.period);
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
      const double exact = 2 * kPi / p.period * std::cos(2 * kPi * p.s[i] / p.period);
      worst = std::max(worst, std::abs(m[i] - exact));
    }
    EXPECT_LT(worst, n == 20 ? 2e-4 : 2e-5) << n;  // fourth order in the spacing
  }
}

TEST(PeriodicSplineTest, SplineIsC2AcrossEveryKnotIncludingTheWrap) {
  const Periodic p = SineOnUnevenKnots(15);
  const std::vector<double> m = PeriodicSplineSlopes(p.s, p.y, p.period);
  const size_t n = p.s.size();
  for (size_t i = 0; i < n; ++i) {  // second derivative at knot i+1 from both sides
    const size_t j = (i + 1) % n, k = (i + 2) % n;
    const double h0 = (j == 0 ? p.period : p.s[j]) - p.s[i];
    const double h1 = (k == 0 ? p.period : p.s[k]) - p.s[j];
    const double left = (2 * m[i] + 4 * m[j]) / h0 - 6 * (p.y[j] - p.y[i]) / (h0 * h0);
    const double right = -(4 * m[j] + 2 * m[k]) / h1 + 6 * (p.y[k] - p.y[j]) / (h1 * h1);
    EXPECT_NEAR(left, right, 1e-12) << i;
  }
}

TEST(PeriodicSplineTest, MonotoneSlopesNeverOvershoot) {
  // A step, as a track width that changes at a pit entry: no value outside [4, 6] anywhere.
  std::vector<double> s, y;
  for (int i = 0; i < 30; ++i) {
    s.push_back(i * 5.0);
    y.push_back(i >= 10 && i < 20 ? 6.0 : 4.0);
  }
  const std::vector<double> m = PeriodicMonotoneSlopes(s, y, 150.0);
  for (size_t i = 0; i < s.size(); ++i) {
    for (double u = 0; u <= 1.0; u += 0.05) {
      const double v = Hermite(s, y, m, 150.0, i, u);
      EXPECT_GE(v, 4.0 - 1e-12);
      EXPECT_LE(v, 6.0 + 1e-12);
    }
  }
  // The C2 spline does overshoot the same data, which is why widths do not use it.
  const std::vector<double> c2 = PeriodicSplineSlopes(s, y, 150.0);
  double top = 0.0;
  for (double u = 0; u <= 1.0; u += 0.05) top = std::max(top, Hermite(s, y, c2, 150.0, 10, u));
  EXPECT_GT(top, 6.0);
}

TEST(PeriodicSplineTest, SmootherKeepsLongWavesAndRemovesShortOnes) {
  const int n = 400;
  const double spacing = 5.0, wavelength = 40.0;
  const double lambda = std::pow(wavelength / (2 * kPi * spacing), 6);
  std::vector<double> longwave(n), shortwave(n), constant(n, 3.0);
  for (int i = 0; i < n; ++i) {
    longwave[i] = std::sin(2 * kPi * i / 100.0);  // 500 m
    shortwave[i] = std::sin(2 * kPi * i / 4.0);   // 20 m
  }
  const auto amplitude = [](const std::vector<double>& v) {
    double a = 0;
    for (double x : v) a = std::max(a, std::abs(x));
    return a;
  };
  const auto gain = [&](double samples_per_wave) {  // the documented transfer function
    return 1.0 / (1.0 + lambda * std::pow(2 * std::sin(kPi / samples_per_wave), 6));
  };
  EXPECT_NEAR(amplitude(PeriodicSmooth(longwave, lambda)), gain(100), 1e-9);
  EXPECT_NEAR(amplitude(PeriodicSmooth(shortwave, lambda)), gain(4), 1e-9);
  EXPECT_LT(gain(4), 0.1);
  EXPECT_GT(gain(100), 0.999);
  // Half amplitude at the chosen wavelength, by construction of lambda.
  EXPECT_NEAR(gain(wavelength / spacing), 0.5, 0.05);
  for (double v : PeriodicSmooth(constant, lambda)) EXPECT_NEAR(v, 3.0, 1e-12);
}

}  // namespace
}  // namespace hotlap::track::internal
