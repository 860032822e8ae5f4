#pragma once
/// @file
/// A closed 3-D ribbon as functions of the distance s along its centre line.
///
/// How to use: load one with hotlap/track/track_io.h (`LoadTrack("darlington")`), then ask
/// `track.At(s)` for the centre line, heading, curvature, banking, grade and widths at any
/// distance; s wraps onto [0, length). Sign conventions are in track_point.h.
///
/// How it is built: a loader describes the ribbon as consecutive pieces, each with its curvature,
/// bank, grade and widths as cubic polynomials in s (Hermite data at both ends). The heading is the
/// exact integral of the curvature (a quartic per piece); the centre line is integrated once, when
/// the track is built, with 8-point Gauss-Legendre per piece (pieces at most 2.5 m long), and
/// between knots it is the quintic Hermite interpolant of position, heading and curvature. So At()
/// is only polynomial evaluation after a binary search: no trigonometry, no integration, and
/// every channel is exactly as smooth as the loader made it: bank and widths C1 on every shipped
/// source; curvature C1 on TUM centre lines, and C0 (piecewise linear, its rate jumping at knots)
/// on segment tracks (clothoids) and fastest-lap circuits (which define it so).
///
/// Closure: the integrated centre line of a real source never closes exactly. closure_error()
/// reports the gap in position and heading before any correction; whatever gap is left when the
/// track is built (the loaders keep it below 1 cm and 1e-6 rad) is spread linearly over the lap,
/// so At(length) == At(0) in position and heading (heading + 2 pi * winding).
///
/// Pitfalls: heading_rad is continuous, not wrapped into (-pi, pi]. Curvature is per metre of
/// centre line (3-D distance); every shipped track has zero grade.

#include <optional>
#include <string>
#include <vector>

#include "hotlap/track/track_point.h"

namespace hotlap::track {

/// A cubic over one piece, given by its values and slopes (per metre) at the piece's two ends.
struct CubicHermite {
  double value_start = 0.0;
  double slope_start = 0.0;
  double value_end = 0.0;
  double slope_end = 0.0;

  /// The constant `value` (zero slopes).
  static CubicHermite Constant(double value) { return {value, 0.0, value, 0.0}; }
};

/// One piece of a ribbon: each channel is the cubic in distance given by its Hermite data.
struct RibbonPiece {
  double length_m = 0.0;     ///< > 0
  CubicHermite curvature;    ///< kappa_h, 1/m (slopes 1/m^2), positive turning left
  CubicHermite bank;         ///< rad (slopes rad/m), positive = left edge down
  CubicHermite grade;        ///< rad (slopes rad/m), positive uphill
  CubicHermite width_left;   ///< m (slopes m/m), > 0
  CubicHermite width_right;  ///< m (slopes m/m), > 0
};

/// Where the centre line starts (s = 0) in the world frame.
struct TrackStart {
  double x_m = 0.0;
  double y_m = 0.0;
  double z_m = 0.0;
  double heading_rad = 0.0;  ///< anticlockwise from world x
};

/// Gap between the end of the integrated centre line (s = length) and its start.
struct ClosureError {
  double dx_m = 0.0;         ///< x(end) - x(start)
  double dy_m = 0.0;         ///< y(end) - y(start)
  double dz_m = 0.0;         ///< z(end) - z(start)
  double heading_rad = 0.0;  ///< heading(end) - heading(start) - 2 pi * winding
  /// Distance between end and start, m.
  double position_m() const;
};

/// A closed ribbon: centre line, heading, curvature, banking, grade and widths as functions of s.
/// Copyable, immutable after construction; At() is thread-safe.
class Track {
 public:
  /// Builds a track from consecutive pieces, starting at `start`. `closure_before_correction` is
  /// the gap of the source's own centre line before a loader corrected it (nullopt when the
  /// loader did not: the gap of these pieces is reported). Throws NumericalError if a piece has a
  /// non-positive length, a non-finite value or a non-positive width, or if the pieces do not
  /// turn through a whole number of turns to within 0.1 rad.
  static Track FromPieces(std::string name, const std::vector<RibbonPiece>& pieces,
                          const TrackStart& start,
                          const std::optional<ClosureError>& closure_before_correction = {});

  /// The same ribbon driven `laps` times as one track (a stint: ocp/stint.h): length and winding
  /// times `laps`, the centre line's position repeating and its heading continuing by the turns of
  /// the laps before. InputError unless laps >= 1.
  Track Repeated(int laps) const;
  /// Laps this track repeats (1 unless made by Repeated()).
  int laps() const { return laps_; }

  /// The track's name (from its file).
  const std::string& name() const { return name_; }
  /// Length of the centre line over one lap, m.
  double length_m() const { return length_; }
  /// Total turning over a lap in whole turns: +1 anticlockwise, -1 clockwise (0 for a figure 8).
  int winding() const { return winding_; }
  /// The gap of the centre line before any correction (see the file comment).
  const ClosureError& closure_error() const { return closure_before_; }
  /// The gap of these pieces' centre line that was spread over the lap when building.
  const ClosureError& spread_closure() const { return spread_; }

  /// `s_m` wrapped onto [0, length).
  double Wrap(double s_m) const;
  /// The ribbon at distance `s_m` (any value: wrapped onto [0, length) first; the returned
  /// point's s_m is the wrapped one). Cost: a binary search and a few polynomials.
  TrackPoint At(double s_m) const;
  /// `intervals` + 1 points at s = i * length / intervals, i = 0..intervals; the last point
  /// repeats the first except for s_m (= length) and heading (+ 2 pi * winding), so a plot closes.
  std::vector<TrackPoint> Sample(int intervals) const;
  /// Distances of the polynomial pieces' ends (0 first, length last): curvature, bank and
  /// widths are polynomials between consecutive knots.
  const std::vector<double>& knots_m() const { return knots_; }

 private:
  // One piece after subdivision: polynomial coefficients in the local t = s - s0.
  struct Piece {
    double kappa[4];                  // kappa_h = k0 + k1 t + k2 t^2 + k3 t^3
    double heading0;                  // heading at t = 0
    double heading_correction_per_m;  // - spread heading gap / length
    double bank[4], grade[4], width_left[4], width_right[4];
    double x[6], y[6], z[6];  // quintic Hermite in t
  };

  Track() = default;
  TrackPoint EvalPiece(size_t i, double t) const;

  std::string name_;
  double length_ = 0.0;
  int winding_ = 0;
  int laps_ = 1;
  ClosureError closure_before_;
  ClosureError spread_;
  std::vector<double> knots_;  // size pieces + 1
  std::vector<Piece> pieces_;
};

namespace internal {

/// End of the centre line integrated over `pieces` from `start`, exactly as Track::FromPieces
/// integrates it but without its checks on whole turns and widths (for the closure solvers).
struct CentreLineEnd {
  double x_m, y_m, z_m, heading_rad, length_m;
};
CentreLineEnd IntegrateCentreLine(const std::vector<RibbonPiece>& pieces, const TrackStart& start);

}  // namespace internal

}  // namespace hotlap::track
