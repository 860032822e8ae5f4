#pragma once
/// @file
/// A racing line: the car's lateral offset from the centre line along the lap, and points along
/// it. The minimum-curvature line itself is an optimisation (ocp/min_curvature_line.h).
///
/// How to use: SampleLine(track, line, 1.0) for points at equal spacing along the path.

#include <filesystem>
#include <span>
#include <vector>

#include "hotlap/track/track.h"

namespace hotlap::track {

/// Lateral offsets n (m, positive left, in the ribbon plane) at centre-line distances s (m,
/// equally spaced from 0, the lap closing after the last).
struct RacingLine {
  std::vector<double> s_m;
  std::vector<double> offset_m;

  /// The offset at centre-line distance s (wrapped), linear between the points.
  double OffsetAt(double s, double length_m) const;
};

/// The centre line itself (zero offset) at `step_m` spacing.
RacingLine CentreLine(const Track& track, double step_m);

/// The line through offsets n at increasing centre-line distances s in [0, lap length] (sizes
/// equal, 4 or more), resampled at round(length / step_m) equal intervals on the periodic cubic
/// spline through them (C2, wrapping round the start line; a last point one lap after the first
/// is dropped as the first again), so that the line's curvature is smooth where the points are.
RacingLine ResampleLine(std::span<const double> s, std::span<const double> n, const Track& track,
                        double step_m);

/// A line read from a CSV file with columns `distance_m` (centre-line distance, increasing, within
/// [0, lap length]) and `offset_m` (lateral offset, positive left), such as the channels of
/// `hotlap optimise`; resampled at round(length / step_m) equal intervals (ResampleLine's
/// periodic cubic spline). InputError naming the file and row when a column is
/// missing, a cell empty, the distances not increasing or outside the lap, or an offset off the
/// track.
RacingLine ReadRacingLine(const std::filesystem::path& path, const Track& track, double step_m);

/// A point of a racing line.
struct LinePoint {
  double path_m = 0.0;           ///< distance along the line from the start line
  double s_m = 0.0;              ///< centre-line distance of the same cross-section
  double offset_m = 0.0;         ///< lateral offset, positive left
  double x_m = 0.0, y_m = 0.0;   ///< position, world frame
  double curvature_per_m = 0.0;  ///< horizontal curvature of the line, positive turning left
  double bank_rad = 0.0;         ///< the ribbon's bank there
  double grade_rad = 0.0;        ///< the centre line's grade there
  double heading_rad = 0.0;      ///< direction of the line, continuous
};

/// Points at round(path length / step_m) equal intervals along the line (the lap closing after
/// the last), curvature from the line's heading (smoothed over about 3 step lengths).
std::vector<LinePoint> SampleLine(const Track& track, const RacingLine& line, double step_m);

}  // namespace hotlap::track
