// `hotlap log info|convert`: what a log holds (any format hotlap reads: hotlap CSV, MoTeC i2 CSV,
// MoTeC .ld), and the log written as hotlap's telemetry CSV.

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/logs/log_info.h"
#include "hotlap/logs/log_table.h"
#include "hotlap/logs/telemetry.h"

namespace hotlap::app {

namespace {

struct LogArgs {
  std::string file;
  std::string out;
  std::string json;
  std::string channel_map;
  std::optional<int> lap;
  std::optional<double> rate_hz;

  TelemetryReadOptions ReadOptions() const {
    return {.channel_map = channel_map, .lap = lap, .ld_rate_hz = rate_hz};
  }
};

int RunLogInfo(const LogArgs& a) {
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  const LogTable log = ReadLogTable(a.file, a.ReadOptions());
  // The reader's checks, as convert and every command that reads the log make them (a repeated
  // time, a value out of its range): what info describes is a log the others read.
  (void)Telemetry::FromTable(log.table);
  const LogInfo info = DescribeLog(log);
  PrintLogInfo(std::cout, info);
  if (!a.json.empty()) WriteJsonFileAndSay(a.json, LogInfoJson(info));
  return 0;
}

int RunLogConvert(const LogArgs& a) {
  CheckOutputFolder(a.out, "--out");
  const LogTable log = ReadLogTable(a.file, a.ReadOptions());
  WriteLogCsv(log, a.out);
  const LogInfo info = DescribeLog(log);
  size_t known = 0;
  for (const LogChannelInfo& c : info.channels) known += c.known ? 1 : 0;
  fmt::print("{} ({}): {} rows, {:.3f} to {:.3f} s, {} channels ({} hotlap, {} carried through)\n",
             a.file, LogFormatName(log.format), info.rows, info.start_s, info.end_s,
             info.channels.size(), known, info.channels.size() - known);
  fmt::print("wrote {}\n", a.out);
  return 0;
}

void AddReadOptions(CLI::App* sub, LogArgs& a) {
  sub->add_option("FILE", a.file, "The log: hotlap CSV, MoTeC i2 CSV export or MoTeC .ld")
      ->required();
  AddTelemetryReadOptions(sub, a.channel_map, a.lap);
  sub->add_option("--rate-hz", a.rate_hz,
                  "Time base of a .ld log, Hz (default: its fastest channel's rate)")
      ->check(CLI::PositiveNumber);
}

}  // namespace

CommandRunner RegisterLogCommand(CLI::App& app) {
  auto info_args = std::make_shared<LogArgs>();
  auto convert_args = std::make_shared<LogArgs>();
  CLI::App* log = app.add_subcommand(
      "log", "Logs (hotlap CSV, MoTeC i2 CSV, MoTeC .ld): inspect, convert to hotlap CSV");
  log->require_subcommand(1);
  CLI::App* info = log->add_subcommand(
      "info", "Format, metadata, channels (rate, unit, samples), laps and duration of a log");
  AddReadOptions(info, *info_args);
  info->add_option("--json", info_args->json,
                   "Write the description as JSON (docs/json-output.md)");
  CLI::App* convert = log->add_subcommand(
      "convert", "Write a log as hotlap's telemetry CSV (docs/telemetry-csv.md)");
  AddReadOptions(convert, *convert_args);
  convert->add_option("--out", convert_args->out, "The CSV to write")->required();
  return [info, info_args, convert, convert_args] {
    if (info->parsed()) return RunLogInfo(*info_args);
    if (convert->parsed()) return RunLogConvert(*convert_args);
    return 1;
  };
}

}  // namespace hotlap::app
