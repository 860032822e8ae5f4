#pragma once
/// @file
/// Reading the MoTeC i2 CSV export (docs/telemetry-formats.md) into the CsvTable of a hotlap CSV
/// with the same numbers, for Telemetry::Read to take on from there.
///
/// How to use: IsMotecCsv(path) tells the format by its first record, `"Format","MoTeC CSV
/// File"`; ReadMotecCsv(path, map) reads it. The metadata records become `# key: value`
/// metadata (key as i2 writes it, value cells joined by spaces), plus `laps` and `unmapped
/// channels`; the channels in the map become hotlap columns in the canonical file units; the
/// others are carried through under their MoTeC names with their values as logged; a `lap`
/// column numbers the samples from the Beacon Markers.
///
/// Lap numbers: as i2 counts them, the samples before the first beacon are lap 1 (the out lap)
/// and a sample at or after beacon k (and before beacon k + 1) is lap k + 1.

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "hotlap/common/csv.h"
#include "hotlap/logs/motec_channel_map.h"

namespace hotlap {

/// One channel of a MoTeC log as logged, before mapping.
struct MotecSourceChannel {
  /// The MoTeC name, e.g. "Ground Speed".
  std::string name;
  /// The unit as logged, e.g. "km/h".
  std::string unit;
  /// The logged rate, Hz, where the format records it per channel (`.ld`); NaN otherwise.
  double rate_hz;
  /// The logged samples where the format records them per channel (`.ld`); 0 otherwise.
  size_t samples = 0;
};

/// A MoTeC export (or `.ld` log, motec_ld_table.h) as a hotlap table.
struct MotecTable {
  /// The table with hotlap column names; line numbers are the export's.
  CsvTable table;
  /// For each hotlap channel key (`speed`, `disc_temp_fl`, ...), the MoTeC names of the map that
  /// would give it, for the message when it is missing.
  std::map<std::string, std::vector<std::string>, std::less<>> sources;
  /// The logged channel of each column of `table` but the last (`lap`), in column order.
  std::vector<MotecSourceChannel> channels;
};

/// True if the file's first record (after a byte-order mark) is `"Format","MoTeC CSV File"`.
/// False for a file that cannot be read (the CSV reader then says why). InputError for a MoTeC
/// export with ';' between its cells (a Windows locale's), which neither reader can read.
bool IsMotecCsv(const std::filesystem::path& path);

/// The lap number of time `t` given the beacon times (ascending): 1 + the number of beacons at
/// or before `t`.
int MotecLapAt(double t, const std::vector<double>& beacons);

/// Reads a MoTeC i2 CSV export. Throws InputError naming the file and line (and column, with its
/// MoTeC channel name) for: no channel names row (a record whose first cell is "Time"), a missing
/// units row, no data rows, a ragged row, a cell that is not a finite number, a Beacon Markers
/// cell that is not a number or not increasing, a mapped channel with an unknown or unfitting
/// unit (MotecConversionFor), or two channels of the same name.
MotecTable ReadMotecCsv(const std::filesystem::path& path, const MotecChannelMap& map);

}  // namespace hotlap
