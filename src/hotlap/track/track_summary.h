#pragma once
/// @file
/// Figures that describe a track at a glance (for `hotlap track info` and reports): length,
/// closure, tightest radius, banking and width ranges, and the turns.

#include <vector>

#include "hotlap/track/track.h"

namespace hotlap::track {

/// A turn: a stretch where the radius drops below SummaryOptions::turn_radius_m, extended back to
/// where the curvature starts to rise (its entry) and on to where it has fallen again (its exit).
struct TrackTurn {
  int direction = 1;          ///< +1 left, -1 right
  double entry_m = 0.0;       ///< where |curvature| starts rising (e.g. a clothoid's start)
  double apex_m = 0.0;        ///< where the radius is smallest
  double exit_m = 0.0;        ///< where |curvature| stops falling; may be < entry_m (wraps)
  double min_radius_m = 0.0;  ///< smallest radius of the centre line in the turn
  double max_bank_rad = 0.0;  ///< largest bank (left edge down) between entry and exit
};

/// The at-a-glance figures of a track.
struct TrackSummary {
  double length_m = 0.0;
  int winding = 0;            ///< +1 anticlockwise, -1 clockwise
  ClosureError closure;       ///< Track::closure_error()
  double min_radius_m = 0.0;  ///< 1 / max |curvature| over the lap (infinite if straight)
  double min_radius_at_m = 0.0;
  double bank_min_rad = 0.0, bank_min_at_m = 0.0;
  double bank_max_rad = 0.0, bank_max_at_m = 0.0;
  double width_min_m = 0.0;      ///< smallest left + right width
  double width_max_m = 0.0;      ///< largest left + right width
  std::vector<TrackTurn> turns;  ///< in order of entry along the lap
};

struct SummaryOptions {
  double step_m = 0.25;          ///< sampling step; entries and exits at a zero of curvature
                                 ///< are refined from the curvature rate
  double turn_radius_m = 500.0;  ///< a turn is where the radius is below this
};

/// Samples the track every `step_m` (or finer) and summarises it.
TrackSummary Summarize(const Track& track, const SummaryOptions& options = {});

}  // namespace hotlap::track
