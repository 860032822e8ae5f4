#pragma once
/// @file
/// The observer's line-at-a-time input and output (docs/observer.md, "Streaming"): a telemetry
/// CSV (docs/telemetry-csv.md) read one line at a time from a file or a pipe, and the estimate
/// CSV written one line at a time, flushed after every line.
///
/// The reader never reads ahead: Next() returns as soon as the line it needs has arrived, so a
/// sample written into a pipe is estimated before the next one is sent. Each line goes through
/// Telemetry::FromTable (the same channel names, units and physical limits as every command). An
/// input channel (speed, forces, slips, ambient and track temperature) with an empty cell holds
/// its last value (there is no later sample to interpolate to when live); an empty temperature
/// cell is a dropout. The carcass_temp and wear columns of a log are not read: the car has no such
/// sensor (a synthetic log's are its truth).

#include <array>
#include <cstdio>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "hotlap/logs/telemetry.h"
#include "hotlap/observe/car_observer.h"

namespace hotlap::observe {

/// Values used where the log has no such column, K.
struct StreamDefaults {
  double ambient_temp = 298.15;
  double track_temp = 313.15;
};

class TelemetryLineReader {
 public:
  /// Reads from `in` (kept by reference); `source` names it in messages (a path or "stdin").
  TelemetryLineReader(std::istream& in, std::string source, const StreamDefaults& defaults);

  /// The next sample, or nullopt at the end of the input. The first call also reads the
  /// `# key: value` lines and the header. InputError naming the source, the line and the column
  /// for a missing header, a ragged row, a cell that is not a number, a missing channel, a time
  /// that does not increase, or an input channel empty before its first value.
  std::optional<ObserverSample> Next();

  /// 1-based line of the last sample returned.
  int line() const { return line_; }
  /// What reading did to values just outside their physical range (telemetry.h): one line per
  /// column as for a whole log (count and lines so far), at most 20; warning_count() counts them
  /// all.
  const std::vector<std::string>& warnings() const { return warnings_; }
  long warning_count() const { return warning_count_; }
  /// The header's metadata lines.
  const std::vector<std::pair<std::string, std::string>>& metadata() const { return metadata_; }

 private:
  bool ReadHeader();

  std::istream& in_;
  std::string source_;
  StreamDefaults defaults_;
  int line_ = 0;
  bool header_read_ = false;
  std::vector<std::string> columns_;
  std::vector<std::pair<std::string, std::string>> metadata_;
  std::optional<ObserverSample> last_;
  std::vector<Telemetry::LimitTreatment> treatments_;  // one per column, merged over the lines
  std::vector<std::string> warnings_;
  long warning_count_ = 0;
};

/// One row of a telemetry log as an observer sample: the inputs (an empty cell holds `last`'s
/// value; InputError if there is none), the readings present, ambient and track temperature (else
/// `last`'s, else the defaults). InputError naming `source` and `line` if the time does not
/// increase past `last`'s.
ObserverSample SampleFromRow(const Telemetry& t, size_t row, const ObserverSample* last,
                             const StreamDefaults& defaults, const std::string& source, int line);

/// A whole log read first (Telemetry::Read: hotlap CSV, MoTeC i2 CSV export or MoTeC `.ld`, with
/// a channel map and one lap selected, as replay and fit read logs), then handed out one sample at
/// a time as TelemetryLineReader does: for `hotlap observe --lap N`, `--channel-map FILE` and
/// MoTeC logs, which cannot be read a line at a time.
class TelemetryLogReader {
 public:
  /// Reads the log (Telemetry::Read's InputErrors).
  TelemetryLogReader(const std::filesystem::path& path, const TelemetryReadOptions& options,
                     const StreamDefaults& defaults);
  std::optional<ObserverSample> Next();
  /// The file line (or row) of the last sample returned.
  int line() const { return line_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  long warning_count() const { return warning_count_; }
  const std::vector<std::pair<std::string, std::string>>& metadata() const {
    return log_.metadata();
  }
  /// Rows in the log (after the lap selection).
  size_t size() const { return log_.size(); }

 private:
  Telemetry log_;
  std::string source_;
  StreamDefaults defaults_;
  size_t row_ = 0;
  int line_ = 0;
  std::optional<ObserverSample> last_;
  std::vector<std::string> warnings_;
  long warning_count_ = 0;
};

/// Writes CSV lines to a file (or standard output for "-") as they come, each flushed at once, so
/// a reader of the file or the pipe sees every line as soon as it is written. Not atomic: the file
/// grows as the run goes (a run that fails leaves the lines written so far).
class LineCsvWriter {
 public:
  /// Opens (truncates) `path`, "-" for standard output. InputError naming the path and the
  /// system's reason if it cannot.
  explicit LineCsvWriter(const std::string& path);
  /// Without Close() (an error stopped the run) the file is removed: an unfinished estimate
  /// file is not left behind under its name (standard output is left as it is).
  ~LineCsvWriter();
  LineCsvWriter(const LineCsvWriter&) = delete;
  LineCsvWriter& operator=(const LineCsvWriter&) = delete;

  void WriteHeader(const std::vector<std::string>& columns);
  /// Numbers in shortest round-trip form, rounded to 9 significant digits; NaN as an empty cell.
  void WriteRow(const std::vector<double>& values);
  /// Closes the file (checked: InputError if the data could not be written).
  void Close();

 private:
  void Put(const std::string& line);
  std::string path_;
  std::FILE* file_ = nullptr;
  bool is_stdout_ = false;
};

}  // namespace hotlap::observe
