#include "hotlap/logs/log_table.h"

#include <utility>

#include "hotlap/common/data_path.h"
#include "hotlap/logs/lap_select.h"
#include "hotlap/logs/motec_channel_map.h"
#include "hotlap/logs/motec_ld.h"
#include "hotlap/logs/motec_ld_table.h"
#include "hotlap/logs/telemetry.h"

namespace hotlap {

std::string_view LogFormatName(LogFormat format) {
  switch (format) {
    case LogFormat::kHotlapCsv:
      return "hotlap CSV";
    case LogFormat::kMotecCsv:
      return "MoTeC i2 CSV";
    case LogFormat::kMotecLd:
      return "MoTeC .ld";
  }
  return "?";
}

LogFormat LogFormatOf(const std::filesystem::path& path) {
  if (IsMotecLd(path)) return LogFormat::kMotecLd;
  if (IsMotecCsv(path)) return LogFormat::kMotecCsv;
  return LogFormat::kHotlapCsv;
}

LogTable ReadLogTable(const std::filesystem::path& path, const TelemetryReadOptions& options) {
  LogTable log;
  log.format = LogFormatOf(path);
  if (log.format == LogFormat::kHotlapCsv) {
    log.table = ReadCsv(path);
  } else {
    log.channel_map =
        options.channel_map.empty() ? MotecChannelMapPath(DataDir()) : options.channel_map;
    const MotecChannelMap map = LoadMotecChannelMap(log.channel_map);
    MotecTable motec = log.format == LogFormat::kMotecCsv
                           ? ReadMotecCsv(path, map)
                           : ReadMotecLdTable(path, map, {.rate_hz = options.ld_rate_hz});
    log.table = std::move(motec.table);
    log.channels = std::move(motec.channels);
    log.sources = std::move(motec.sources);
  }
  if (options.lap) SelectLap(log.table, *options.lap);
  return log;
}

void WriteLogCsv(const LogTable& log, const std::filesystem::path& out) {
  (void)Telemetry::FromTable(log.table);  // the checks of a read, before anything is written
  std::vector<std::pair<std::string, std::string>> metadata = log.table.metadata;
  metadata.emplace_back(
      "source", log.table.path.string() + " (" + std::string(LogFormatName(log.format)) + ")");
  WriteCsv(out, metadata, log.table.columns, log.table.values);
}

}  // namespace hotlap
