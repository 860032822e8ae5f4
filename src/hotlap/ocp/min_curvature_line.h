#pragma once
/// @file
/// The minimum-curvature racing line, the classic first answer to "where does the car drive"
/// (Heilmeier et al., "Minimum curvature trajectory planning and control for an autonomous race
/// car", VSD 2020): the closed path inside the track limits with the least integral of squared
/// curvature over its length. On an oval it runs along the outside on the straights, reaches the
/// inside mid-turn and so turns with a larger radius than the centre line. The curvature is that of
/// the path itself (points at the centre line's cross-sections, spacing included), so the line is
/// not drawn to the inside merely because the inside is shorter. Solved with Ipopt (exact second
/// derivatives; the problem is badly conditioned for first-order or projected methods).

#include "hotlap/track/racing_line.h"

namespace hotlap::ocp {

struct MinimumCurvatureOptions {
  double step_m = 2.0;    ///< spacing of the line's points along the centre line
  double margin_m = 1.5;  ///< kept between the line and each edge (half the car's width and more)
};

/// InputError if the track is narrower than twice the margin somewhere; NumericalError if the
/// solve fails.
track::RacingLine MinimumCurvatureLine(const track::Track& track,
                                       const MinimumCurvatureOptions& options);

}  // namespace hotlap::ocp
