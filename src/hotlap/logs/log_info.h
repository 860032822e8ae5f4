#pragma once
/// @file
/// What a log holds, for `hotlap log info` (docs/telemetry-formats.md): its format, metadata,
/// channels (name, unit, rate, samples, the hotlap column each becomes), laps and duration.
///
/// How to use: DescribeLog(ReadLogTable(path, options)) then PrintLogInfo() or LogInfoJson().

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hotlap/logs/log_table.h"

namespace hotlap {

/// One channel of a log.
struct LogChannelInfo {
  /// The name as logged: a MoTeC channel name, or a hotlap CSV's column.
  std::string name;
  /// The unit as logged (a hotlap CSV's: the unit part of a known column's name, "" otherwise).
  std::string unit;
  /// The column it becomes in hotlap's CSV: the hotlap channel in its canonical unit, or `name`
  /// where it is carried through.
  std::string column;
  /// True if hotlap knows the channel (a known quantity); false: carried through untouched.
  bool known = false;
  /// Samples per second: a `.ld` channel's own rate; otherwise that of the table (1 / the median
  /// time step); nullopt for a one-row table or one without time.
  std::optional<double> rate_hz;
  /// A `.ld` channel's own samples; otherwise the non-empty cells of its column.
  size_t samples = 0;
};

/// One lap of a log.
struct LogLapInfo {
  int lap = 0;
  /// Time of its first and last row, s.
  double start_s = 0.0;
  double end_s = 0.0;
  size_t rows = 0;
};

/// What a log holds.
struct LogInfo {
  std::filesystem::path path;
  LogFormat format = LogFormat::kHotlapCsv;
  std::vector<std::pair<std::string, std::string>> metadata;
  /// The channels in column order (the `lap` column of a MoTeC log is not one).
  std::vector<LogChannelInfo> channels;
  /// Rows of the table (samples on the time base for a `.ld` log).
  size_t rows = 0;
  /// First and last time, s (NaN without a time column).
  double start_s = 0.0;
  double end_s = 0.0;
  /// 1 / the median time step, Hz; nullopt for one row or without time.
  std::optional<double> rate_hz;
  /// The laps of the `lap` column in order of first appearance; empty without one.
  std::vector<LogLapInfo> laps;
  /// The channel map used (a MoTeC log); empty otherwise.
  std::filesystem::path channel_map;
};

/// Describes a log read by ReadLogTable.
LogInfo DescribeLog(const LogTable& log);

/// The text `hotlap log info` prints.
void PrintLogInfo(std::ostream& out, const LogInfo& info);

/// The `--json` summary of `hotlap log info` (keys in docs/json-output.md): `command`, `file`,
/// `format`, `metadata` (list of {key, value}), `rows`, `start_s`, `end_s`, `duration_s`,
/// `rate_hz`, `channels` (list of {name, unit, column, known, rate_hz, samples}), `laps` (list of
/// {lap, start_s, end_s, duration_s, rows}), `channel_map`.
nlohmann::json LogInfoJson(const LogInfo& info);

}  // namespace hotlap
