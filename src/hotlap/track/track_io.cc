#include "hotlap/track/track_io.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "hotlap/common/data_path.h"
#include "hotlap/common/enum_names.h"
#include "hotlap/common/error.h"
#include "hotlap/track/fastest_lap_xml.h"
#include "hotlap/track/segment_track_io.h"
#include "hotlap/track/tum_csv.h"

namespace hotlap::track {

constexpr EnumNames<TrackFormat, 3> kTrackFormats{
    {{{TrackFormat::kSegments, "segments"},
      {TrackFormat::kTumCsv, "tum-csv"},
      {TrackFormat::kFastestLapXml, "fastest-lap-xml"}}}};

const char* TrackFormatName(TrackFormat format) { return kTrackFormats.Name(format); }

TrackFile LoadTrackFile(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".yaml" || ext == ".yml") {
    SegmentTrack loaded = LoadSegmentTrack(path);
    return {path, TrackFormat::kSegments, std::move(loaded.track), std::move(loaded.spans),
            std::move(loaded.unknowns)};
  }
  if (ext == ".csv") return {path, TrackFormat::kTumCsv, LoadTumTrack(path), {}, {}};
  if (ext == ".xml")
    return {path, TrackFormat::kFastestLapXml, LoadFastestLapCircuit(path), {}, {}};
  throw InputError(
      fmt::format("'{}': unknown track file type '{}': expected .yaml or .yml "
                  "(segments), .csv (TUM centre line) or .xml (fastest-lap circuit)",
                  path.string(), ext));
}

TrackFile LoadTrackByName(std::string_view name_or_path) {
  return LoadTrackFile(ResolveTrackFile(name_or_path));
}

Track LoadTrack(std::string_view name_or_path) { return LoadTrackByName(name_or_path).track; }

}  // namespace hotlap::track
