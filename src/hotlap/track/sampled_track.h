#pragma once
/// @file
/// Tracks from sampled data: curvature samples (fastest-lap circuits) or a polyline centre line
/// with widths (TUM racetrack-database). The file readers (tum_csv.h, fastest_lap_xml.h) parse and
/// validate their files and call these.
///
/// Method. The centre line is the integral of the heading, which is the integral of the
/// curvature; widths are a periodic monotone cubic through their samples (no overshoot).
/// - Curvature samples (TrackFromCurvature) are joined linearly: the heading is then their
///   trapezoidal integral, exactly as fastest-lap computes its `yaw` from `yaw_dot`, so the
///   imported headings equal the file's at every point. Curvature is C0 (what such a source
///   defines); a C1 spline through the same samples would move the heading by up to 0.03 rad
///   from the file's on fastest-lap's 9 m Catalunya grid.
/// - A polyline (TrackFromCentreLine) is smoothed (periodic Whittaker smoother on x and y, see
///   CentreLineOptions), then the heading at each point is the bisector of its two chords and the
///   heading between points the periodic C2 cubic spline through those (after removing the
///   2 pi * winding trend): curvature is its derivative, C1, and the heading turns through exactly
///   the polyline's whole turns. The arc length of each chord is that of the circular arc with the
///   chord's mean turning.
///
/// Closure: the integrated centre line never closes exactly, so the curvature is corrected by
/// a + b cos(2 pi s / L) + c sin(2 pi s / L), with (a, b, c) solved by Newton's method so that the
/// end meets the start in x, y and heading (to 1e-8 m, 1e-11 rad). The correction is smooth and
/// periodic and, for real tracks, tiny (about 1e-6 1/m for a 1 m gap over 5 km).
/// Track::closure_error() reports the gap before it.

#include <string>
#include <vector>

#include "hotlap/track/track.h"

namespace hotlap::track {

/// Curvature and widths sampled at distances along a closed centre line.
struct CurvatureSamples {
  /// Knots: s_m[0] = 0, strictly increasing, last < length_m; at least 3.
  std::vector<double> s_m;
  double length_m = 0.0;                ///< the lap; the samples wrap after it
  std::vector<double> curvature_per_m;  ///< kappa_h at each knot, positive turning left
  std::vector<double> width_left_m;     ///< > 0 at each knot
  std::vector<double> width_right_m;    ///< > 0 at each knot
  TrackStart start;                     ///< position and heading at s = 0
};

/// Builds the closed track through the samples, curvature linear between them (see the file
/// comment). Throws NumericalError if the closure correction does not converge (curvature samples
/// that do not describe a loop).
Track TrackFromCurvature(std::string name, const CurvatureSamples& samples);

/// A closed polyline centre line with its widths; the last point does not repeat the first.
struct CentreLinePoints {
  std::vector<double> x_m, y_m;       ///< world frame, y left of x
  std::vector<double> width_left_m;   ///< > 0
  std::vector<double> width_right_m;  ///< > 0
};

/// How a polyline is smoothed.
struct CentreLineOptions {
  /// Wavelength along the track whose amplitude the smoother halves, m: shorter wiggles are
  /// removed, longer shapes kept. 40 m keeps the centre line within 1.3 m of TUM's Catalunya
  /// points (2.6 m at worst on its other F1 circuits, at hairpins) and removes the kinks of a
  /// 5 m polyline from the curvature.
  double smoothing_wavelength_m = 40.0;
};

/// Builds a closed track from a polyline (see the file comment). The caller has checked the
/// points: at least 7, consecutive points distinct, the loop's last gap comparable to the others.
Track TrackFromCentreLine(std::string name, const CentreLinePoints& points,
                          const CentreLineOptions& options = {});

}  // namespace hotlap::track
