#pragma once
/// @file
/// The charts of the optimal-lap report: one or more runs overlaid (e.g. without and with the disc
/// limit).

#include <string>
#include <vector>

#include "hotlap/ocp/optimal_lap.h"
#include "hotlap/report/html_report.h"
#include "hotlap/track/track.h"

namespace hotlap::ocp {

/// Adds the map and the channel charts of `runs` (labelled `labels`, drawn solid then dashed) to
/// `page`: speed, drive power and braking force, offset, steer, front and rear tread and disc
/// temperatures, wear, against centre-line distance.
void AddOptimalLapCharts(report::HtmlReport& page, const std::vector<const OptimalLapRun*>& runs,
                         const std::vector<std::string>& labels, const track::Track& track);

}  // namespace hotlap::ocp
