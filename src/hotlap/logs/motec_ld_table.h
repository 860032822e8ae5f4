#pragma once
/// @file
/// A MoTeC `.ld` log as a hotlap table (docs/telemetry-formats.md): every channel resampled onto
/// one time base, mapped and converted through the MoTeC channel map like the CSV export, laps
/// from the companion `.ldx` file's beacons.
///
/// How to use: ReadMotecLdTable(path, map) gives the same MotecTable as ReadMotecCsv gives for an
/// i2 export, for Telemetry::Read to take on from there. ResampleLinear() is the one resampling
/// step, exposed for tests.
///
/// Pitfalls: a channel is only known over its own samples: on the time base, before its first
/// sample (never: all start at 0 s) and after its last (a slow channel ends up to one of its
/// periods earlier than a fast one) its cells are empty ("not measured"), which the hotlap reader
/// fills by holding the nearest value where a channel must be complete.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/logs/motec_channel_map.h"
#include "hotlap/logs/motec_csv.h"
#include "hotlap/logs/motec_ld.h"

namespace hotlap {

/// The values of a channel logged at `rate_hz` (sample i at i / rate_hz s), at the times k /
/// `base_rate_hz` for k = 0 .. `base_count` - 1: linear interpolation between the two neighbouring
/// samples, the sample itself where a time falls on one (to within 1e-9 of a sample period); NaN
/// after the last sample, or where a neighbour used is NaN.
std::vector<double> ResampleLinear(const std::vector<double>& values, double rate_hz,
                                   double base_rate_hz, size_t base_count);

/// How a `.ld` log becomes a table.
struct LdTableOptions {
  /// The time base's rate, Hz; nullopt: the fastest channel's.
  std::optional<double> rate_hz;
};

/// The beacon times (s, ascending) of the companion `.ldx` file of `ld_path` (same name, `.ldx`
/// extension, any case), or nullopt where there is none. Read: the `Time` attributes (in
/// microseconds, as i2 writes them) of the `Marker` elements of the `MarkerGroup` named
/// "Beacons", or of every `Marker` where no group is so named. Throws InputError "FILE:LINE: ..."
/// for malformed XML, a Time that is not a finite number, or times not increasing.
std::optional<std::vector<double>> ReadLdxBeacons(const std::filesystem::path& ld_path);

/// Reads a `.ld` log (ReadMotecLd) as a hotlap table: a `time_s` column at the time base (the
/// fastest channel's rate, or `options.rate_hz`), from 0 to the last sample of the longest
/// channel; every channel resampled (a channel without samples is an empty column) onto it
/// (ResampleLinear), then mapped and converted as PlanMotecChannels does (the unit being the
/// descriptor's); a `lap` column from the `.ldx` beacons (MotecLapAt; all lap 1 without an `.ldx`).
/// Metadata: `Format: MoTeC .ld`, Venue, Vehicle, Driver, Device, Log Date, Log Time, Event,
/// Session, Short Comment (those that are not empty), `Sample Rate` (the time base, Hz), `laps`,
/// `lap source`, `unmapped channels`, `channel map`. Line numbers are the row numbers + 1. Throws
/// ParseMotecLd's errors; InputError for a channel named `Time` (the time base's name), a log whose
/// channels have no samples at all, an `options.rate_hz` that is not positive and finite, a time
/// base of more than 10^8 rows, and the unit errors of a mapped channel
/// ("FILE: channel 'NAME' (descriptor at byte N): ...").
MotecTable ReadMotecLdTable(const std::filesystem::path& path, const MotecChannelMap& map,
                            const LdTableOptions& options = {});

/// The same from a log already read (`ldx_beacons` as ReadLdxBeacons gives them).
MotecTable MotecLdTable(const LdLog& log, const MotecChannelMap& map,
                        const std::optional<std::vector<double>>& ldx_beacons,
                        const LdTableOptions& options = {});

}  // namespace hotlap
