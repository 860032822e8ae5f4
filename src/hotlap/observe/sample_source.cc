#include "hotlap/observe/sample_source.h"

#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/logs/log_table.h"

namespace hotlap::observe {

SampleSource::SampleSource(const std::string& telemetry, const TelemetryReadOptions& read,
                           const StreamDefaults& defaults)
    : name_(telemetry == "-" ? "stdin" : telemetry) {
  const bool stream = telemetry == "-";
  const bool selects = read.lap.has_value() || !read.channel_map.empty();
  if (stream && selects) {
    throw InputError(
        "--lap and --channel-map need a log file: a stream on standard input is read a line at a "
        "time as hotlap CSV");
  }
  const bool whole_log = !stream && (selects || (std::filesystem::is_regular_file(telemetry) &&
                                                 LogFormatOf(telemetry) != LogFormat::kHotlapCsv));
  if (whole_log) {
    log_reader_.emplace(telemetry, read, defaults);
    return;
  }
  std::istream* in = &std::cin;
  if (!stream) {
    file_.open(telemetry);
    if (!file_) throw InputError(fmt::format("cannot read '{}'", telemetry));
    in = &file_;
  }
  line_reader_.emplace(*in, name_, defaults);
}

std::optional<ObserverSample> SampleSource::Next() {
  return log_reader_ ? log_reader_->Next() : line_reader_->Next();
}

int SampleSource::line() const { return log_reader_ ? log_reader_->line() : line_reader_->line(); }

const std::vector<std::string>& SampleSource::warnings() const {
  return log_reader_ ? log_reader_->warnings() : line_reader_->warnings();
}

long SampleSource::warning_count() const {
  return log_reader_ ? log_reader_->warning_count() : line_reader_->warning_count();
}

const std::vector<std::pair<std::string, std::string>>& SampleSource::metadata() const {
  return log_reader_ ? log_reader_->metadata() : line_reader_->metadata();
}

}  // namespace hotlap::observe
