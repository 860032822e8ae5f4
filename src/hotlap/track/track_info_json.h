#pragma once
/// @file
/// The JSON summary of `hotlap track info --json` (docs/tracks.md): a track's at-a-glance figures
/// (track_summary.h), its turns and, for a segment file, its segments and solved unknowns.

#include <string>

#include <nlohmann/json.hpp>

#include "hotlap/track/track_io.h"
#include "hotlap/track/track_summary.h"

namespace hotlap::track {

/// The summary `summary` (made with `options`) of `file`'s track: lengths and radii in m, angles in
/// deg, each turn and segment, the solved unknowns; `out` (the ribbon CSV) when not empty.
nlohmann::json TrackInfoJson(const TrackFile& file, const TrackSummary& summary,
                             const SummaryOptions& options, const std::string& out = "");

/// "left" for a positive direction, else "right".
const char* TurnDirectionName(int direction);

}  // namespace hotlap::track
