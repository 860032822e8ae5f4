#pragma once
/// @file
/// SecondOrder<N>: a scalar that carries its value, gradient and Hessian with respect to N
/// variables through every arithmetic operation and elementary function (forward-mode automatic
/// differentiation to second order). The optimal-control code evaluates the scalar-templated
/// models on it to get exact Hessians of small functions ("elements", ocp/element.h).
///
/// Why not nested ceres::Jet: Ceres 2.1's Jet<Jet<double, N>, N> has no arithmetic with plain
/// doubles (`0.5 * x` does not compile), which every model uses, and it stores and updates the
/// Hessian twice plus the gradient twice ((N + 1)^2 numbers); this type stores
/// 1 + N + N (N + 1) / 2 and does half the work.
///
/// How to use: seed inputs with SecondOrder<N>::Variable(value, index), evaluate, read `a` (the
/// value), `v[i]` (d/dx_i) and Hessian(i, j). Math functions are found by argument-dependent
/// lookup after `using std::sin;` etc., as for Jets. Branch only on ValueOf(x).

#include <array>
#include <cmath>

namespace hotlap {

template <int N>
struct SecondOrder {
  static constexpr int kPacked = N * (N + 1) / 2;
  double a = 0.0;             ///< value
  std::array<double, N> v{};  ///< gradient
  std::array<double, kPacked>
      h{};  ///< Hessian, packed lower triangle: (i, j), i >= j at i(i+1)/2 + j

  SecondOrder() = default;
  SecondOrder(double value) : a(value) {}  // NOLINT: implicit, as a double is a constant

  /// The variable x_index at `value`.
  static SecondOrder Variable(double value, int index) {
    SecondOrder s(value);
    s.v[index] = 1.0;
    return s;
  }
  double Hessian(int i, int j) const {
    return i >= j ? h[i * (i + 1) / 2 + j] : h[j * (j + 1) / 2 + i];
  }

  SecondOrder& operator+=(const SecondOrder& b) {
    a += b.a;
    for (int i = 0; i < N; ++i) v[i] += b.v[i];
    for (int k = 0; k < kPacked; ++k) h[k] += b.h[k];
    return *this;
  }
  SecondOrder& operator-=(const SecondOrder& b) {
    a -= b.a;
    for (int i = 0; i < N; ++i) v[i] -= b.v[i];
    for (int k = 0; k < kPacked; ++k) h[k] -= b.h[k];
    return *this;
  }
  SecondOrder& operator*=(const SecondOrder& b) { return *this = *this * b; }
  SecondOrder& operator/=(const SecondOrder& b) { return *this = *this / b; }
  SecondOrder& operator+=(double b) {
    a += b;
    return *this;
  }
  SecondOrder& operator-=(double b) {
    a -= b;
    return *this;
  }
  SecondOrder& operator*=(double b) {
    a *= b;
    for (double& x : v) x *= b;
    for (double& x : h) x *= b;
    return *this;
  }
  SecondOrder& operator/=(double b) { return *this *= 1.0 / b; }

  friend SecondOrder operator-(SecondOrder x) {
    x *= -1.0;
    return x;
  }
  friend SecondOrder operator+(const SecondOrder& x) { return x; }
  friend SecondOrder operator+(SecondOrder x, const SecondOrder& y) { return x += y; }
  friend SecondOrder operator-(SecondOrder x, const SecondOrder& y) { return x -= y; }
  friend SecondOrder operator+(SecondOrder x, double y) { return x += y; }
  friend SecondOrder operator+(double y, SecondOrder x) { return x += y; }
  friend SecondOrder operator-(SecondOrder x, double y) { return x -= y; }
  friend SecondOrder operator-(double y, const SecondOrder& x) { return -x + y; }
  friend SecondOrder operator*(SecondOrder x, double y) { return x *= y; }
  friend SecondOrder operator*(double y, SecondOrder x) { return x *= y; }
  friend SecondOrder operator/(SecondOrder x, double y) { return x *= 1.0 / y; }

  friend SecondOrder operator*(const SecondOrder& x, const SecondOrder& y) {
    SecondOrder r;
    r.a = x.a * y.a;
    for (int i = 0; i < N; ++i) r.v[i] = x.a * y.v[i] + y.a * x.v[i];
    int k = 0;
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j <= i; ++j, ++k) {
        r.h[k] = x.a * y.h[k] + y.a * x.h[k] + x.v[i] * y.v[j] + x.v[j] * y.v[i];
      }
    }
    return r;
  }
  friend SecondOrder operator/(const SecondOrder& x, const SecondOrder& y) {
    return x * Reciprocal(y);
  }
  friend SecondOrder operator/(double c, const SecondOrder& y) { return Reciprocal(y) * c; }

  /// f(x) given f(x.a), f'(x.a), f''(x.a): the chain rule to second order.
  static SecondOrder Chain(const SecondOrder& x, double f, double f1, double f2) {
    SecondOrder r;
    r.a = f;
    for (int i = 0; i < N; ++i) r.v[i] = f1 * x.v[i];
    int k = 0;
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j <= i; ++j, ++k) r.h[k] = f1 * x.h[k] + f2 * x.v[i] * x.v[j];
    }
    return r;
  }

  friend SecondOrder Reciprocal(const SecondOrder& x) {
    const double r = 1.0 / x.a;
    return Chain(x, r, -r * r, 2.0 * r * r * r);
  }
  friend SecondOrder sqrt(const SecondOrder& x) {
    const double s = std::sqrt(x.a);
    return Chain(x, s, 0.5 / s, -0.25 / (s * x.a));
  }
  friend SecondOrder exp(const SecondOrder& x) {
    const double e = std::exp(x.a);
    return Chain(x, e, e, e);
  }
  friend SecondOrder expm1(const SecondOrder& x) {
    const double e = std::exp(x.a);
    return Chain(x, std::expm1(x.a), e, e);
  }
  friend SecondOrder log(const SecondOrder& x) {
    return Chain(x, std::log(x.a), 1.0 / x.a, -1.0 / (x.a * x.a));
  }
  friend SecondOrder sin(const SecondOrder& x) {
    const double s = std::sin(x.a), c = std::cos(x.a);
    return Chain(x, s, c, -s);
  }
  friend SecondOrder cos(const SecondOrder& x) {
    const double s = std::sin(x.a), c = std::cos(x.a);
    return Chain(x, c, -s, -c);
  }
  friend SecondOrder tan(const SecondOrder& x) {
    const double t = std::tan(x.a), d = 1.0 + t * t;
    return Chain(x, t, d, 2.0 * t * d);
  }
  friend SecondOrder atan(const SecondOrder& x) {
    const double d = 1.0 / (1.0 + x.a * x.a);
    return Chain(x, std::atan(x.a), d, -2.0 * x.a * d * d);
  }
  friend SecondOrder cosh(const SecondOrder& x) {
    return Chain(x, std::cosh(x.a), std::sinh(x.a), std::cosh(x.a));
  }
  friend SecondOrder sinh(const SecondOrder& x) {
    return Chain(x, std::sinh(x.a), std::cosh(x.a), std::sinh(x.a));
  }
  friend SecondOrder tanh(const SecondOrder& x) {
    const double t = std::tanh(x.a), d = 1.0 - t * t;
    return Chain(x, t, d, -2.0 * t * d);
  }
  /// |x| with the derivatives of the side x is on (+ at 0).
  friend SecondOrder abs(const SecondOrder& x) { return x.a < 0.0 ? -x : x; }
  friend SecondOrder pow(const SecondOrder& x, double p) {
    const double f = std::pow(x.a, p);
    return Chain(x, f, p * f / x.a, p * (p - 1.0) * f / (x.a * x.a));
  }
  friend SecondOrder pow(const SecondOrder& x, const SecondOrder& p) { return exp(p * log(x)); }
  friend SecondOrder atan2(const SecondOrder& y, const SecondOrder& x) {
    // atan(y / x) shifted by pi where x < 0: the derivatives are those of atan(y / x).
    SecondOrder r = atan(y / x);
    r.a = std::atan2(y.a, x.a);
    return r;
  }
  friend SecondOrder fmax(const SecondOrder& x, const SecondOrder& y) { return x.a >= y.a ? x : y; }
  friend SecondOrder fmin(const SecondOrder& x, const SecondOrder& y) { return x.a <= y.a ? x : y; }
};

/// The plain value, for branching.
template <int N>
double ValueOf(const SecondOrder<N>& x) {
  return x.a;
}

}  // namespace hotlap
