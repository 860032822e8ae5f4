#include "hotlap/track/periodic_spline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace hotlap::track::internal {

namespace {

// Knot spacing h_i = s_{i+1} - s_i with the wrap-around interval last.
std::vector<double> Spacings(const std::vector<double>& s, double period) {
  const size_t n = s.size();
  std::vector<double> h(n);
  for (size_t i = 0; i + 1 < n; ++i) h[i] = s[i + 1] - s[i];
  h[n - 1] = period - s[n - 1] + s[0];
  return h;
}

// Solves the cyclic tridiagonal system a_i x_{i-1} + b_i x_i + c_i x_{i+1} = r_i (indices mod n,
// n >= 3) by the Sherman-Morrison correction of the Thomas algorithm (Numerical Recipes 2.7).
std::vector<double> SolveCyclicTridiagonal(const std::vector<double>& a, std::vector<double> b,
                                           const std::vector<double>& c,
                                           const std::vector<double>& r) {
  const size_t n = b.size();
  const double alpha = c[n - 1];  // bottom-left corner
  const double beta = a[0];       // top-right corner
  const double gamma = -b[0];
  b[0] -= gamma;
  b[n - 1] -= alpha * beta / gamma;
  const auto thomas = [&](const std::vector<double>& rhs) {
    std::vector<double> cp(n), x(n);
    double denom = b[0];
    x[0] = rhs[0] / denom;
    for (size_t i = 1; i < n; ++i) {
      cp[i - 1] = c[i - 1] / denom;
      denom = b[i] - a[i] * cp[i - 1];
      x[i] = (rhs[i] - a[i] * x[i - 1]) / denom;
    }
    for (size_t i = n - 1; i-- > 0;) x[i] -= cp[i] * x[i + 1];
    return x;
  };
  std::vector<double> x = thomas(r);
  std::vector<double> u(n, 0.0);
  u[0] = gamma;
  u[n - 1] = alpha;
  const std::vector<double> z = thomas(u);
  const double factor = (x[0] + beta * x[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
  for (size_t i = 0; i < n; ++i) x[i] -= factor * z[i];
  return x;
}

void CheckSizes(const std::vector<double>& s, const std::vector<double>& y, size_t min_n) {
  if (s.size() != y.size() || s.size() < min_n) {
    throw std::invalid_argument("periodic spline: need matching knots and values, at least " +
                                std::to_string(min_n));
  }
}

}  // namespace

std::vector<double> PeriodicSplineSlopes(const std::vector<double>& s, const std::vector<double>& y,
                                         double period) {
  CheckSizes(s, y, 3);
  const size_t n = s.size();
  const std::vector<double> h = Spacings(s, period);
  std::vector<double> d(n), a(n), b(n), c(n), r(n);
  for (size_t i = 0; i < n; ++i) d[i] = (y[(i + 1) % n] - y[i]) / h[i];
  for (size_t i = 0; i < n; ++i) {
    const size_t prev = (i + n - 1) % n;
    a[i] = h[i];
    b[i] = 2.0 * (h[prev] + h[i]);
    c[i] = h[prev];
    r[i] = 3.0 * (h[i] * d[prev] + h[prev] * d[i]);
  }
  return SolveCyclicTridiagonal(a, b, c, r);
}

std::vector<double> PeriodicMonotoneSlopes(const std::vector<double>& s,
                                           const std::vector<double>& y, double period) {
  CheckSizes(s, y, 3);
  const size_t n = s.size();
  const std::vector<double> h = Spacings(s, period);
  std::vector<double> d(n), m(n);
  for (size_t i = 0; i < n; ++i) d[i] = (y[(i + 1) % n] - y[i]) / h[i];
  for (size_t i = 0; i < n; ++i) {
    const size_t prev = (i + n - 1) % n;
    // Zero slope at a local extremum or flat step; otherwise the weighted harmonic mean of the
    // neighbouring secants (Fritsch and Butland), which keeps every interval monotone.
    if (d[prev] * d[i] <= 0.0) {
      m[i] = 0.0;
    } else {
      const double w1 = 2.0 * h[i] + h[prev], w2 = h[i] + 2.0 * h[prev];
      m[i] = (w1 + w2) / (w1 / d[prev] + w2 / d[i]);
    }
  }
  return m;
}

std::vector<double> PeriodicSmooth(const std::vector<double>& y, double lambda) {
  const int n = static_cast<int>(y.size());
  if (n < 7) throw std::invalid_argument("periodic smoothing: need at least 7 values");
  // A = I + lambda D'D with D the cyclic third difference (1, -3, 3, -1): a symmetric positive
  // definite band of half-width 3 with wrapped corners.
  constexpr double kDiff[4] = {-1.0, 3.0, -3.0, 1.0};
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(n) * 17);
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 1.0);
  for (int row = 0; row < n; ++row) {  // row of D touches columns row..row+3 (mod n)
    for (int p = 0; p < 4; ++p) {
      for (int q = 0; q < 4; ++q) {
        entries.emplace_back((row + p) % n, (row + q) % n, lambda * kDiff[p] * kDiff[q]);
      }
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("periodic smoothing: factorisation failed");
  }
  const Eigen::VectorXd rhs = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
  const Eigen::VectorXd q = solver.solve(rhs);
  return std::vector<double>(q.data(), q.data() + n);
}

double PeriodicHermiteValue(const std::vector<double>& s, const std::vector<double>& y,
                            const std::vector<double>& slopes, double period, double x) {
  x = std::fmod(x, period);
  if (x < 0.0) x += period;
  const size_t n = s.size();
  const size_t i = static_cast<size_t>(std::upper_bound(s.begin(), s.end(), x) - s.begin()) - 1;
  const size_t j = (i + 1) % n;
  const double h = (j == 0 ? period : s[j]) - s[i];
  const double t = (x - s[i]) / h, t2 = t * t, t3 = t2 * t;
  return (2.0 * t3 - 3.0 * t2 + 1.0) * y[i] + (t3 - 2.0 * t2 + t) * h * slopes[i] +
         (-2.0 * t3 + 3.0 * t2) * y[j] + (t3 - t2) * h * slopes[j];
}

}  // namespace hotlap::track::internal
