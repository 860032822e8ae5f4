#pragma once
/// @file
/// Periodic interpolation and smoothing on the knots of a closed track, used to turn sampled
/// centre lines into smooth ribbons. Internal to the track module.
///
/// Every function takes knots s_0 = 0 < s_1 < ... < s_{n-1} < period and the values there; the
/// value after s_{n-1} wraps to s_0 + period. They return the slope at each knot, for a cubic
/// Hermite between consecutive knots (track.h's CubicHermite).

#include <vector>

namespace hotlap::track::internal {

/// Slopes of the periodic cubic spline through (s_i, y_i): C2, the smoothest interpolant, for
/// channels that are already smooth (curvature of a smoothed centre line). Needs n >= 3.
/// Solves the cyclic tridiagonal system
/// h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1} = 3 (h_i d_{i-1} + h_{i-1} d_i),
/// h_i = s_{i+1} - s_i, d_i = (y_{i+1} - y_i) / h_i (de Boor, A Practical Guide to Splines, IV).
std::vector<double> PeriodicSplineSlopes(const std::vector<double>& s, const std::vector<double>& y,
                                         double period);

/// Slopes of the periodic monotone cubic (Fritsch-Carlson, as PCHIP): C1, never overshoots the
/// data between knots, for measured channels that may step (track widths). Needs n >= 3.
std::vector<double> PeriodicMonotoneSlopes(const std::vector<double>& s,
                                           const std::vector<double>& y, double period);

/// The value at x (wrapped into [0, period)) of the cubic Hermite through (s_i, y_i) with the
/// given slopes (from the functions above).
double PeriodicHermiteValue(const std::vector<double>& s, const std::vector<double>& y,
                            const std::vector<double>& slopes, double period, double x);

/// Periodic Whittaker smoother: the q minimising sum (q_i - y_i)^2 + lambda sum (D^3 q)_i^2,
/// with D^3 the cyclic third difference over the index. Its transfer function is
/// 1 / (1 + lambda (2 sin(w/2))^6) at w rad per sample: lambda = (wavelength / (2 pi spacing))^6
/// halves the amplitude of waves of that wavelength, leaves longer ones and removes shorter ones.
/// Needs n >= 7.
std::vector<double> PeriodicSmooth(const std::vector<double>& y, double lambda);

}  // namespace hotlap::track::internal
