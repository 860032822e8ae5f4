#pragma once
/// @file
/// Where `hotlap observe` takes its samples from: a hotlap CSV file or standard input ("-") read
/// a line at a time, or a whole log read first (a MoTeC log, one lap of any log, or a log with a
/// channel map), as replay and fit read logs (docs/telemetry-formats.md). Only a regular file is
/// sniffed for its format: a named pipe is read a line at a time, from its first line.

#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hotlap/logs/telemetry.h"
#include "hotlap/observe/stream_io.h"

namespace hotlap::observe {

class SampleSource {
 public:
  /// Opens `telemetry` (a path, or "-" for standard input). InputError if the file cannot be
  /// read, or if a lap or a channel map is asked of standard input (a stream is hotlap CSV).
  SampleSource(const std::string& telemetry, const TelemetryReadOptions& read,
               const StreamDefaults& defaults);
  SampleSource(const SampleSource&) = delete;
  SampleSource& operator=(const SampleSource&) = delete;

  /// The next sample, or nullopt at the end.
  std::optional<ObserverSample> Next();
  /// The line (or row) of the last sample returned.
  int line() const;
  /// What reading did to values just outside their range (at most 20 lines), and how many such
  /// warnings there were in all.
  const std::vector<std::string>& warnings() const;
  long warning_count() const;
  /// The log's `# key: value` lines (read with the first sample).
  const std::vector<std::pair<std::string, std::string>>& metadata() const;
  /// The source in messages: the path, or "stdin".
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  std::ifstream file_;
  std::optional<TelemetryLineReader> line_reader_;
  std::optional<TelemetryLogReader> log_reader_;
};

}  // namespace hotlap::observe
