#pragma once
/// @file
/// Loading a track from a built-in name or a file of any supported format.
///
/// How to use: `LoadTrack("darlington")` or `LoadTrack("path/to/file.csv")` gives the Track;
/// `LoadTrackByName(name_or_path)` and `LoadTrackFile(path)` also give what the file said beyond
/// the ribbon (segments and solved unknowns of a segment file), for reports. Formats by extension
/// (docs/tracks.md):
/// `.yaml`/`.yml` segment description, `.csv` TUM centre line, `.xml` fastest-lap circuit.

#include <filesystem>
#include <string_view>
#include <vector>

#include "hotlap/track/segment_loop.h"
#include "hotlap/track/track.h"

namespace hotlap::track {

enum class TrackFormat { kSegments, kTumCsv, kFastestLapXml };

/// "segments", "tum-csv" or "fastest-lap-xml".
const char* TrackFormatName(TrackFormat format);

/// A loaded track and what its file said beyond the ribbon.
struct TrackFile {
  std::filesystem::path path;
  TrackFormat format = TrackFormat::kSegments;
  Track track;
  /// Segment files only: each segment's place on the track, and the solved unknowns.
  std::vector<SegmentSpan> segments;
  std::vector<LoopUnknown> solved;
};

/// Loads `path` by its extension. Throws InputError for an unknown extension (listing the
/// supported ones) and for any problem in the file.
TrackFile LoadTrackFile(const std::filesystem::path& path);

/// A built-in name or a path: ResolveTrackFile (hotlap/common/data_path.h), then LoadTrackFile.
TrackFile LoadTrackByName(std::string_view name_or_path);

/// The track only: `LoadTrackByName(name_or_path).track`.
Track LoadTrack(std::string_view name_or_path);

}  // namespace hotlap::track
