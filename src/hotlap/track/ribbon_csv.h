#pragma once
/// @file
/// A track's sampled ribbon as CSV indexed by distance (`hotlap track info --out`,
/// docs/tracks.md).

#include <filesystem>

#include "hotlap/track/track_io.h"

namespace hotlap::track {

/// Writes the ribbon of `file`'s track atomically, one row per step of at most `step_m` (the last
/// at s = length): distance, position, heading, curvatures, bank and grade (deg), widths, with the
/// track, its file, format and length as metadata.
void WriteRibbonCsv(const std::filesystem::path& path, const TrackFile& file, double step_m);

}  // namespace hotlap::track
