#pragma once
/// @file
/// Importing a centre line in the TUM racetrack-database format (TUMFTM/racetrack-database,
/// LGPL-3.0, data/tracks/LICENSE-tumftm.txt), such as data/tracks/catalunya.csv.
///
/// Format: a `#` header line `# x_m,y_m,w_tr_right_m,w_tr_left_m`, then one row of four numbers
/// per point: centre-line position (m, right-handed x-y, y left of x) and the distances from the
/// centre line to the right and left track edges (m). The points form a closed loop and the last
/// does not repeat the first (if it does, it is dropped). A header without `#` is accepted too.
/// The track is built as sampled_track.h's TrackFromCentreLine describes: smoothed, with
/// continuous curvature, closed, widths kept, bank and grade zero.

#include <filesystem>

#include "hotlap/track/sampled_track.h"

namespace hotlap::track {

/// The points of a TUM file, validated. Throws InputError naming the file, the line and the
/// column for a wrong header, a row without four cells, a cell that is not a finite number, a
/// width that is not positive, two consecutive points less than 1 mm apart, fewer than 20 points,
/// a closing gap (last point to first) more than 5 times the median spacing (not a closed
/// loop), or a gap between consecutive points more than 20 times the median spacing (a point far
/// off the line).
CentreLinePoints ReadTumCentreLine(const std::filesystem::path& path);

/// ReadTumCentreLine, then TrackFromCentreLine; the track is named after the file's stem. Points
/// from which no closed track can be built (TrackFromCentreLine's NumericalError, e.g. a track
/// over 100 km long) are an InputError naming the file.
Track LoadTumTrack(const std::filesystem::path& path, const CentreLineOptions& options = {});

}  // namespace hotlap::track
