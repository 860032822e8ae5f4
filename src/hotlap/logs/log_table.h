#pragma once
/// @file
/// A log of any format hotlap reads (hotlap CSV, MoTeC i2 CSV export, MoTeC `.ld`) as one hotlap
/// table: the step under Telemetry::Read, and what `hotlap log info|convert` work on.
///
/// How to use: ReadLogTable(path, options) tells the format by content (LogFormatOf), reads it,
/// maps a MoTeC log's channels through the channel map and keeps one lap if asked;
/// WriteLogCsv() writes the table as hotlap's telemetry CSV.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hotlap/common/csv.h"
#include "hotlap/logs/motec_csv.h"

namespace hotlap {

struct TelemetryReadOptions;  // telemetry.h

/// The formats of a log.
enum class LogFormat { kHotlapCsv, kMotecCsv, kMotecLd };

/// "hotlap CSV", "MoTeC i2 CSV" or "MoTeC .ld".
std::string_view LogFormatName(LogFormat format);

/// The format of the file: MoTeC `.ld` (IsMotecLd: the marker or the extension), MoTeC i2 CSV
/// (IsMotecCsv: the first record), else hotlap CSV.
LogFormat LogFormatOf(const std::filesystem::path& path);

/// A log as a hotlap table.
struct LogTable {
  LogFormat format = LogFormat::kHotlapCsv;
  /// The hotlap table: canonical columns, metadata, values; one lap's rows if a lap was asked for.
  CsvTable table;
  /// For a MoTeC log: the logged channel of each column but `lap`, in column order; empty for a
  /// hotlap CSV.
  std::vector<MotecSourceChannel> channels;
  /// For a MoTeC log: hotlap channel key -> the MoTeC names that map to it (MotecTable::sources).
  std::map<std::string, std::vector<std::string>, std::less<>> sources;
  /// For a MoTeC log: the channel map used; empty for a hotlap CSV.
  std::filesystem::path channel_map;
};

/// Reads a log of any format: a hotlap CSV by ReadCsv, a MoTeC export by ReadMotecCsv, a `.ld`
/// log by ReadMotecLdTable (both with `options.channel_map`, default the shipped
/// DataDir()/motec_channels.yaml); then SelectLap for `options.lap`. Throws those readers'
/// InputErrors.
LogTable ReadLogTable(const std::filesystem::path& path, const TelemetryReadOptions& options);

/// Writes `table` as hotlap's telemetry CSV at `out` (WriteCsv: atomically, shortest round-trip
/// numbers), with its metadata plus `source: FILE (FORMAT)`. The table is first checked as
/// Telemetry::FromTable checks it (column names and units, a strictly increasing time), so a
/// written file always reads back.
void WriteLogCsv(const LogTable& log, const std::filesystem::path& out);

}  // namespace hotlap
