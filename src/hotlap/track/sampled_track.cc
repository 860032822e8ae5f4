#include "hotlap/track/sampled_track.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/track/periodic_spline.h"

namespace hotlap::track {

namespace {

// The closure correction is done when the end meets the start this closely; Track spreads the
// rest (rounding, 1e-12 m) over the lap.
constexpr double kPositionTolerance = 1e-8;  // m
constexpr double kHeadingTolerance = 1e-11;  // rad
constexpr int kMaxNewtonIterations = 20;

// A closed ribbon described by knots and per-interval curvature, before the closure correction.
struct ClosedRibbon {
  std::vector<double> s;            // knots, s[0] = 0
  double length = 0.0;              // the lap
  std::vector<CubicHermite> kappa;  // curvature over [s_i, s_{i+1}] (wrapping at the end)
  std::vector<double> wl, wr;       // widths at the knots
  TrackStart start;
};

// The pieces with curvature corrected by p = (a, b, c) (see the header).
std::vector<RibbonPiece> Pieces(const ClosedRibbon& in, const Eigen::Vector3d& p) {
  const size_t n = in.s.size();
  const std::vector<double> ml = internal::PeriodicMonotoneSlopes(in.s, in.wl, in.length);
  const std::vector<double> mr = internal::PeriodicMonotoneSlopes(in.s, in.wr, in.length);
  const double omega = 2.0 * kPi / in.length;
  const auto value = [&](double s) {
    return p[0] + p[1] * std::cos(omega * s) + p[2] * std::sin(omega * s);
  };
  const auto slope = [&](double s) {
    return omega * (p[2] * std::cos(omega * s) - p[1] * std::sin(omega * s));
  };
  std::vector<RibbonPiece> pieces(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const double s0 = in.s[i], s1 = j == 0 ? in.length : in.s[j];
    RibbonPiece& piece = pieces[i];
    piece.length_m = s1 - s0;
    const CubicHermite& k = in.kappa[i];
    piece.curvature = {k.value_start + value(s0), k.slope_start + slope(s0),
                       k.value_end + value(s1), k.slope_end + slope(s1)};
    piece.bank = CubicHermite::Constant(0.0);
    piece.grade = CubicHermite::Constant(0.0);
    piece.width_left = {in.wl[i], ml[i], in.wl[j], ml[j]};
    piece.width_right = {in.wr[i], mr[i], in.wr[j], mr[j]};
  }
  return pieces;
}

// Solves the closure correction and builds the track; closure_error() is the uncorrected gap.
Track CloseAndBuild(std::string name, const ClosedRibbon& in) {
  const double L = in.length;
  // Residual in metres: the heading gap is scaled by L / (2 pi).
  const auto residual = [&](const Track& t) {
    const ClosureError& e = t.spread_closure();
    return Eigen::Vector3d(e.dx_m, e.dy_m, e.heading_rad * L / (2.0 * kPi));
  };
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Track track = Track::FromPieces(name, Pieces(in, p), in.start);
  const ClosureError raw = track.spread_closure();
  for (int iteration = 0;; ++iteration) {
    const ClosureError& e = track.spread_closure();
    if (std::hypot(e.dx_m, e.dy_m) < kPositionTolerance &&
        std::abs(e.heading_rad) < kHeadingTolerance) {
      break;
    }
    if (iteration == kMaxNewtonIterations) {
      throw NumericalError(fmt::format(
          "track '{}': the closure correction did not converge (gap {:.3g} m, {:.3g} rad after "
          "{} iterations)",
          name, std::hypot(e.dx_m, e.dy_m), e.heading_rad, iteration));
    }
    // Forward-difference Jacobian: the problem is nearly linear in p.
    const Eigen::Vector3d r = residual(track);
    Eigen::Matrix3d jacobian;
    const double step = 1e-3 / (L * L);  // moves the end by about a millimetre
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d q = p;
      q[k] += step;
      jacobian.col(k) = (residual(Track::FromPieces(name, Pieces(in, q), in.start)) - r) / step;
    }
    p -= jacobian.fullPivLu().solve(r);
    track = Track::FromPieces(name, Pieces(in, p), in.start);
  }
  return Track::FromPieces(std::move(name), Pieces(in, p), in.start, raw);
}

}  // namespace

Track TrackFromCurvature(std::string name, const CurvatureSamples& in) {
  const size_t n = in.s_m.size();
  if (n < 3 || in.curvature_per_m.size() != n || in.width_left_m.size() != n ||
      in.width_right_m.size() != n || in.s_m.front() != 0.0 || !(in.s_m.back() < in.length_m)) {
    throw std::invalid_argument("TrackFromCurvature: inconsistent samples for '" + name + "'");
  }
  ClosedRibbon ribbon{in.s_m, in.length_m, {}, in.width_left_m, in.width_right_m, in.start};
  ribbon.kappa.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const double h = (j == 0 ? in.length_m : in.s_m[j]) - in.s_m[i];
    const double k0 = in.curvature_per_m[i], k1 = in.curvature_per_m[j];
    ribbon.kappa[i] = {k0, (k1 - k0) / h, k1, (k1 - k0) / h};
  }
  return CloseAndBuild(std::move(name), ribbon);
}

Track TrackFromCentreLine(std::string name, const CentreLinePoints& points,
                          const CentreLineOptions& options) {
  const size_t n = points.x_m.size();
  if (n < 7 || points.y_m.size() != n || points.width_left_m.size() != n ||
      points.width_right_m.size() != n) {
    throw std::invalid_argument("TrackFromCentreLine: inconsistent points for '" + name + "'");
  }
  double perimeter = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    perimeter += std::hypot(points.x_m[j] - points.x_m[i], points.y_m[j] - points.y_m[i]);
  }
  const double lambda = std::pow(options.smoothing_wavelength_m / (2.0 * kPi * perimeter / n), 6);
  const std::vector<double> x = internal::PeriodicSmooth(points.x_m, lambda);
  const std::vector<double> y = internal::PeriodicSmooth(points.y_m, lambda);

  // Chord i runs from point i to point i + 1; unwrap its heading so that consecutive chords
  // differ by less than pi.
  std::vector<double> chord(n), chord_heading(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    chord[i] = std::hypot(x[j] - x[i], y[j] - y[i]);
    if (!(chord[i] > 0.0)) {
      throw NumericalError(
          fmt::format("track '{}': smoothed points {} and {} coincide", name, i + 1, j + 1));
    }
    chord_heading[i] = std::atan2(y[j] - y[i], x[j] - x[i]);
    if (i > 0) {
      chord_heading[i] =
          chord_heading[i - 1] + std::remainder(chord_heading[i] - chord_heading[i - 1], 2.0 * kPi);
    }
  }
  // Turn at each point, from the chord before it to the chord after it.
  std::vector<double> turn(n);
  for (size_t i = 0; i < n; ++i) {
    const double before = i == 0 ? chord_heading[n - 1] : chord_heading[i - 1];
    turn[i] = std::remainder(chord_heading[i] - before, 2.0 * kPi);
  }
  // Heading at each point: the chords' bisector. Knots at the points; arc of each chord from its
  // mean turning, c * (a/2) / sin(a/2).
  ClosedRibbon ribbon;
  ribbon.s.resize(n);
  std::vector<double> heading(n);
  double s = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    heading[i] = chord_heading[i] - turn[i] / 2.0;
    const double a = 0.5 * (turn[i] + turn[j]);
    ribbon.s[i] = s;
    s += std::abs(a) < 1e-8 ? chord[i] : chord[i] * (a / 2.0) / std::sin(a / 2.0);
  }
  ribbon.length = s;
  const double total_turn = heading[n - 1] + turn[0] / 2.0 + turn[n - 1] / 2.0 - heading[0];
  const double trend = total_turn / ribbon.length;  // 2 pi winding / L
  // Periodic C2 spline through the heading less its trend; curvature is its derivative.
  std::vector<double> periodic(n);
  for (size_t i = 0; i < n; ++i) periodic[i] = heading[i] - trend * ribbon.s[i];
  const std::vector<double> slope =
      internal::PeriodicSplineSlopes(ribbon.s, periodic, ribbon.length);
  ribbon.kappa.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const double h = (j == 0 ? ribbon.length : ribbon.s[j]) - ribbon.s[i];
    const double secant = (periodic[j] - periodic[i]) / h;  // periodic: wraps exactly
    // Heading cubic a0 + a1 t + a2 t^2 + a3 t^3 on the interval; curvature = its derivative.
    const double a2 = (3.0 * secant - 2.0 * slope[i] - slope[j]) / h;
    const double a3 = (slope[i] + slope[j] - 2.0 * secant) / (h * h);
    ribbon.kappa[i] = {slope[i] + trend, 2.0 * a2, slope[j] + trend, 2.0 * a2 + 6.0 * a3 * h};
  }
  ribbon.wl = points.width_left_m;
  ribbon.wr = points.width_right_m;
  ribbon.start = {x[0], y[0], 0.0, heading[0]};
  return CloseAndBuild(std::move(name), ribbon);
}

}  // namespace hotlap::track
