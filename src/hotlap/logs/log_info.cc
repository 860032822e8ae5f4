#include "hotlap/logs/log_info.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "hotlap/common/json_output.h"
#include "hotlap/common/median.h"
#include "hotlap/logs/telemetry.h"

namespace hotlap {
namespace {

// The time column of a hotlap table, or -1.
int TimeColumn(const CsvTable& table) {
  for (size_t c = 0; c < table.columns.size(); ++c) {
    const std::optional<ChannelName> name = ParseChannelName(table.columns[c], table.path);
    if (name && name->quantity == "time" && !name->corner) return static_cast<int>(c);
  }
  return -1;
}

}  // namespace

LogInfo DescribeLog(const LogTable& log) {
  const CsvTable& table = log.table;
  LogInfo info;
  info.path = table.path;
  info.format = log.format;
  info.metadata = table.metadata;
  info.rows = table.RowCount();
  info.channel_map = log.channel_map;
  info.start_s = info.end_s = std::nan("");

  const int time_column = TimeColumn(table);
  const std::vector<double>* time =
      time_column >= 0 ? &table.values[static_cast<size_t>(time_column)] : nullptr;
  if (time != nullptr && !time->empty()) {
    info.start_s = time->front();
    info.end_s = time->back();
    if (time->size() > 1) {
      std::vector<double> steps;
      for (size_t i = 1; i < time->size(); ++i) steps.push_back((*time)[i] - (*time)[i - 1]);
      const double step = Median(steps);
      if (step > 0.0) info.rate_hz = 1.0 / step;
    }
  }

  const bool motec = log.format != LogFormat::kHotlapCsv;
  for (size_t c = 0; c < table.columns.size(); ++c) {
    if (motec && c >= log.channels.size()) break;  // the `lap` column hotlap adds
    LogChannelInfo ch;
    ch.column = table.columns[c];
    const std::optional<ChannelName> parsed = ParseChannelName(ch.column, table.path);
    ch.known = parsed.has_value();
    if (motec) {
      ch.name = log.channels[c].name;
      ch.unit = log.channels[c].unit;
    } else {
      ch.name = ch.column;
      ch.unit = parsed && parsed->unit != "1" ? parsed->unit : "";
    }
    if (motec && log.channels[c].samples > 0) {
      ch.rate_hz = log.channels[c].rate_hz;
      ch.samples = log.channels[c].samples;
    } else {
      ch.rate_hz = info.rate_hz;
      ch.samples = static_cast<size_t>(std::count_if(table.values[c].begin(), table.values[c].end(),
                                                     [](double v) { return !std::isnan(v); }));
    }
    info.channels.push_back(std::move(ch));
  }

  const int lap_column = table.ColumnIndex("lap");
  if (lap_column >= 0) {
    const std::vector<double>& laps = table.values[static_cast<size_t>(lap_column)];
    std::map<int, size_t> index;  // lap -> position in info.laps
    for (size_t i = 0; i < laps.size(); ++i) {
      if (std::isnan(laps[i])) continue;
      const int lap = static_cast<int>(std::lround(laps[i]));
      const double t = time != nullptr ? (*time)[i] : std::nan("");
      auto [it, inserted] = index.emplace(lap, info.laps.size());
      if (inserted) info.laps.push_back({lap, t, t, 0});
      LogLapInfo& l = info.laps[it->second];
      l.start_s = std::fmin(l.start_s, t);
      l.end_s = std::fmax(l.end_s, t);
      ++l.rows;
    }
  }
  return info;
}

void PrintLogInfo(std::ostream& out, const LogInfo& info) {
  fmt::print(out, "log '{}' ({})\n", info.path.string(), LogFormatName(info.format));
  for (const auto& [key, value] : info.metadata) fmt::print(out, "  {}: {}\n", key, value);
  fmt::print(out, "  rows            {}\n", info.rows);
  fmt::print(out, "  time            {:.3f} to {:.3f} s ({:.3f} s)\n", info.start_s, info.end_s,
             info.end_s - info.start_s);
  if (info.rate_hz) fmt::print(out, "  rate            {:.6g} Hz\n", *info.rate_hz);
  fmt::print(out, "  channels: {}\n    {:<32} {:<10} {:>9} {:>9}  {}\n", info.channels.size(),
             "name", "unit", "rate_Hz", "samples", "hotlap column");
  for (const LogChannelInfo& c : info.channels) {
    fmt::print(out, "    {:<32} {:<10} {:>9} {:>9}  {}\n", c.name, c.unit.empty() ? "-" : c.unit,
               c.rate_hz ? fmt::format("{:.6g}", *c.rate_hz) : "-", c.samples,
               c.known ? c.column : "(carried through)");
  }
  if (info.laps.empty()) {
    fmt::print(out, "  laps: none (no lap column)\n");
  } else {
    fmt::print(out, "  laps: {}\n    {:>4} {:>10} {:>10} {:>10} {:>8}\n", info.laps.size(), "lap",
               "start_s", "end_s", "length_s", "rows");
    for (const LogLapInfo& l : info.laps) {
      fmt::print(out, "    {:>4} {:>10.3f} {:>10.3f} {:>10.3f} {:>8}\n", l.lap, l.start_s, l.end_s,
                 l.end_s - l.start_s, l.rows);
    }
  }
}

nlohmann::json LogInfoJson(const LogInfo& info) {
  const auto number = [](double x) {
    return std::isfinite(x) ? nlohmann::json(RoundSignificant(x)) : nlohmann::json(nullptr);
  };
  nlohmann::json j;
  j["command"] = "log info";
  j["file"] = info.path.string();
  j["format"] = LogFormatName(info.format);
  j["metadata"] = nlohmann::json::array();
  for (const auto& [key, value] : info.metadata) {
    j["metadata"].push_back({{"key", key}, {"value", value}});
  }
  j["rows"] = info.rows;
  j["start_s"] = number(info.start_s);
  j["end_s"] = number(info.end_s);
  j["duration_s"] = number(info.end_s - info.start_s);
  j["rate_hz"] = JsonOrNull(info.rate_hz);
  j["channels"] = nlohmann::json::array();
  for (const LogChannelInfo& c : info.channels) {
    j["channels"].push_back({{"name", c.name},
                             {"unit", c.unit},
                             {"column", c.column},
                             {"known", c.known},
                             {"rate_hz", JsonOrNull(c.rate_hz)},
                             {"samples", c.samples}});
  }
  j["laps"] = nlohmann::json::array();
  for (const LogLapInfo& l : info.laps) {
    j["laps"].push_back({{"lap", l.lap},
                         {"start_s", number(l.start_s)},
                         {"end_s", number(l.end_s)},
                         {"duration_s", number(l.end_s - l.start_s)},
                         {"rows", l.rows}});
  }
  j["channel_map"] = info.channel_map.empty() ? nlohmann::json(nullptr)
                                              : nlohmann::json(info.channel_map.string());
  return j;
}

}  // namespace hotlap
