#pragma once
/// @file
/// The road a lap simulation drives on, sampled from a track's centre line.

#include <vector>

#include "hotlap/sim/qss_lap.h"
#include "hotlap/track/racing_line.h"
#include "hotlap/track/track.h"

namespace hotlap::sim {

/// The centre line at round(length / step_m) equal intervals (at least 16), from the start line;
/// the point after the last is the first (a closed lap). InputError if step_m is not positive or
/// is longer than a sixteenth of the lap.
std::vector<RoadPoint> SampleRoad(const track::Track& track, double step_m);

/// The road along a racing line at about `step_m` spacing along the line (track::SampleLine):
/// the line's own horizontal curvature, the ribbon's bank and grade at its cross-sections.
std::vector<RoadPoint> SampleRoadAlongLine(const track::Track& track, const track::RacingLine& line,
                                           double step_m);

}  // namespace hotlap::sim
