#pragma once
/// @file
/// Piecewise-linear interpolation in a table with a scalar-templated query: the interval is
/// chosen on the plain value, the arithmetic is done in T so derivatives flow through.

#include <algorithm>
#include <span>

#include "hotlap/common/scalar.h"

namespace hotlap {

/// Linear interpolation of (xs, ys) at x, clamped to the end values outside [xs.front(),
/// xs.back()]. xs strictly increasing, at least two points (checked by whoever loads the table).
template <Scalar T>
T InterpolateClamped(std::span<const double> xs, std::span<const double> ys, const T& x) {
  const double xv = ValueOf(x);
  if (xv <= xs.front()) return T(ys.front());
  if (xv >= xs.back()) return T(ys.back());
  // First knot strictly greater than x; the interval is [i-1, i].
  const size_t i = std::upper_bound(xs.begin(), xs.end(), xv) - xs.begin();
  const double slope = (ys[i] - ys[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + slope * (x - xs[i - 1]);
}

}  // namespace hotlap
