#include "hotlap/logs/motec_csv.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/common/string_match.h"
#include "hotlap/logs/telemetry.h"

namespace hotlap {
namespace {

constexpr std::string_view kSpace = " \t\r\f\v";

std::string_view Trim(std::string_view s) {
  const size_t begin = s.find_first_not_of(kSpace);
  if (begin == std::string_view::npos) return {};
  return s.substr(begin, s.find_last_not_of(kSpace) - begin + 1);
}

// The cells of one record: comma separated, each optionally in double quotes ("" inside quotes
// is one quote), space around a cell ignored.
std::vector<std::string> SplitRecord(std::string_view line, const std::string& where) {
  std::vector<std::string> cells;
  size_t i = 0;
  while (true) {
    while (i < line.size() && kSpace.find(line[i]) != std::string_view::npos) ++i;
    std::string cell;
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size()) {
          throw InputError(
              fmt::format("{}: cell {} has no closing quote", where, cells.size() + 1));
        }
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            cell += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        cell += line[i++];
      }
      while (i < line.size() && kSpace.find(line[i]) != std::string_view::npos) ++i;
      if (i < line.size() && line[i] != ',') {
        throw InputError(
            fmt::format("{}: text after the closing quote of cell {}", where, cells.size() + 1));
      }
    } else {
      const size_t comma = line.find(',', i);
      cell = std::string(Trim(line.substr(i, comma == std::string_view::npos ? comma : comma - i)));
      i = comma == std::string_view::npos ? line.size() : comma;
    }
    cells.push_back(std::move(cell));
    if (i >= line.size()) return cells;
    ++i;  // the comma
  }
}

// A number cell, or nullopt for text that is not a finite number.
std::optional<double> ParseNumber(std::string_view text) {
  text = Trim(text);
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  double value = kNaN;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

struct Record {
  int line = 0;
  std::vector<std::string> cells;
};

// The non-blank records of the file, in order.
std::vector<Record> ReadRecords(const std::filesystem::path& path) {
  const std::string text = ReadWholeFile(path);
  std::vector<Record> records;
  int line_number = 0;
  for (const std::string_view line : TextLines(text)) {
    ++line_number;
    if (Trim(line).empty()) continue;
    std::vector<std::string> cells =
        SplitRecord(line, fmt::format("{}:{}", path.string(), line_number));
    // A record of empty cells only (",,,") is blank too.
    if (std::all_of(cells.begin(), cells.end(), [](const std::string& c) { return c.empty(); })) {
      continue;
    }
    records.push_back({line_number, std::move(cells)});
  }
  return records;
}

// The key/value pairs of a metadata record: each run of non-empty cells is a key and its values
// ("Session","Race","","Origin Time","0.000","s" gives Session: Race and Origin Time: 0.000 s).
void AddMetadata(const Record& record, std::vector<std::pair<std::string, std::string>>& metadata) {
  size_t i = 0;
  const std::vector<std::string>& cells = record.cells;
  while (i < cells.size()) {
    if (cells[i].empty()) {
      ++i;
      continue;
    }
    std::string key = cells[i++];
    std::replace(key.begin(), key.end(), ':', '-');  // a metadata key holds no colon
    std::string value;
    // The first value may be empty ("Comment",""): a key's values run to the next empty cell
    // after at least one cell.
    bool first = true;
    while (i < cells.size() && (!cells[i].empty() || first)) {
      if (!cells[i].empty()) value += (value.empty() ? "" : " ") + cells[i];
      first = false;
      ++i;
    }
    metadata.emplace_back(std::move(key), std::move(value));
  }
}

std::vector<double> ParseBeacons(const Record& record, const std::string& file) {
  std::vector<double> beacons;
  for (size_t i = 1; i < record.cells.size(); ++i) {
    if (record.cells[i].empty()) continue;
    const std::optional<double> t = ParseNumber(record.cells[i]);
    if (!t) {
      throw InputError(fmt::format("{}:{}: Beacon Markers (column {}): '{}' is not a number", file,
                                   record.line, i + 1, record.cells[i]));
    }
    if (!beacons.empty() && !(*t > beacons.back())) {
      throw InputError(fmt::format(
          "{}:{}: Beacon Markers (column {}): {} s must follow {} s (they are lap crossing times, "
          "increasing)",
          file, record.line, i + 1, *t, beacons.back()));
    }
    beacons.push_back(*t);
  }
  return beacons;
}

}  // namespace

bool IsMotecCsv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line)) return false;
  std::string_view first = line;
  if (first.substr(0, 3) == "\xEF\xBB\xBF") first.remove_prefix(3);
  // An export in a locale whose list separator is ';' (and decimal mark ','): not readable as
  // either format, so say what it is rather than fail on its first number.
  const std::string_view format_cell = first.substr(0, first.find(';'));
  if ((format_cell == "\"Format\"" || format_cell == "Format") &&
      first.find("MoTeC CSV File") != std::string_view::npos) {
    throw InputError(fmt::format(
        "{}:1: a MoTeC CSV export with ';' between its cells (a Windows locale's list separator, "
        "with ',' as its decimal mark): export it again with ',' between cells and '.' decimals",
        path.string()));
  }
  try {
    const std::vector<std::string> cells = SplitRecord(first, path.string());
    return cells.size() >= 2 && cells[0] == "Format" && cells[1] == "MoTeC CSV File";
  } catch (const InputError&) {
    return false;
  }
}

int MotecLapAt(double t, const std::vector<double>& beacons) {
  return 1 +
         static_cast<int>(std::upper_bound(beacons.begin(), beacons.end(), t) - beacons.begin());
}

namespace {

void CheckWidth(const Record& record, std::string_view what, const Record& names,
                const std::string& file) {
  const size_t width = names.cells.size();
  if (record.cells.size() != width) {
    throw InputError(fmt::format("{}:{}: {} has {} cells, but the channel names row (line {}) {}",
                                 file, record.line, what, record.cells.size(), names.line, width));
  }
}

// The units row under the channel names row records[r], which must have data rows under it.
const Record& UnitsRow(const std::vector<Record>& records, size_t r, const std::string& file) {
  const Record& names = records[r];
  if (r + 1 == records.size()) {
    throw InputError(fmt::format("{}:{}: no units row under the channel names", file, names.line));
  }
  const Record& units = records[r + 1];
  // A units row of numbers only is a data row: the units row is missing.
  if (std::all_of(units.cells.begin(), units.cells.end(),
                  [](const std::string& c) { return c.empty() || ParseNumber(c); })) {
    throw InputError(fmt::format(
        "{}:{}: expected the units row (\"s\",\"km/h\",...) under the channel names (line {}), "
        "found numbers",
        file, units.line, names.line));
  }
  CheckWidth(units, "the units row", names, file);
  if (r + 2 == records.size()) {
    throw InputError(fmt::format("{}:{}: no data rows under the units row", file, units.line));
  }
  return units;
}

// The channels' names: each named, no two the same.
std::vector<std::string> ChannelNames(const Record& names, const std::string& file) {
  const size_t width = names.cells.size();
  std::vector<std::string> channel_names(width);
  for (size_t c = 0; c < width; ++c) {
    channel_names[c] = names.cells[c];
    if (channel_names[c].empty()) {
      throw InputError(fmt::format("{}:{}: channel {} has no name", file, names.line, c + 1));
    }
    for (size_t d = 0; d < c; ++d) {
      if (channel_names[d] == channel_names[c]) {
        throw InputError(fmt::format("{}:{}: channel '{}' (column {}) is also column {}", file,
                                     names.line, channel_names[c], c + 1, d + 1));
      }
    }
  }
  return channel_names;
}

// The data rows from records[first] on into table's values (converted by the plans). An unmapped
// channel with text in it (a gear shown as "N") cannot be carried as numbers: it is marked in
// the result, to be left out; a mapped one's text is an error.
std::vector<bool> ReadDataRows(const std::vector<Record>& records, size_t first,
                               const Record& names, const std::vector<std::string>& channel_names,
                               const std::vector<MotecChannelPlan>& plans, const std::string& file,
                               CsvTable& table) {
  const size_t width = names.cells.size();
  table.values.assign(width, {});
  std::vector<bool> text_channel(width, false);
  for (size_t d = first; d < records.size(); ++d) {
    const Record& row = records[d];
    CheckWidth(row, "this row", names, file);
    for (size_t c = 0; c < width; ++c) {
      double value = kNaN;
      if (!row.cells[c].empty()) {
        const std::optional<double> number = ParseNumber(row.cells[c]);
        if (!number && plans[c].entry == nullptr && c > 0) {
          text_channel[c] = true;
          table.values[c].push_back(kNaN);
          continue;
        }
        if (!number) {
          throw InputError(fmt::format("{}:{}: channel '{}' (column {}): '{}' is not a number",
                                       file, row.line, channel_names[c], c + 1, row.cells[c]));
        }
        value = plans[c].entry != nullptr ? plans[c].conversion.Apply(*number) : *number;
      }
      table.values[c].push_back(value);
    }
    table.line_numbers.push_back(row.line);
  }
  return text_channel;
}

// Leaves the text channels out (and off the unmapped list); returns their names.
std::string DropTextChannels(const std::vector<bool>& text_channel,
                             const std::vector<std::string>& channel_names, MotecTable& out,
                             std::vector<std::string>& unmapped) {
  CsvTable& table = out.table;
  std::string dropped;
  for (size_t c = text_channel.size(); c-- > 0;) {
    if (!text_channel[c]) continue;
    dropped = channel_names[c] + (dropped.empty() ? "" : ", ") + dropped;
    table.columns.erase(table.columns.begin() + static_cast<std::ptrdiff_t>(c));
    table.values.erase(table.values.begin() + static_cast<std::ptrdiff_t>(c));
    out.channels.erase(out.channels.begin() + static_cast<std::ptrdiff_t>(c));
    const auto it = std::find(unmapped.begin(), unmapped.end(), channel_names[c]);
    if (it != unmapped.end()) unmapped.erase(it);
  }
  return dropped;
}

// Lap numbers from the beacons, by the logged time: the "lap" column; returns the last lap.
int AddLapColumn(const std::vector<double>& beacons, const std::string& file, CsvTable& table) {
  std::vector<double> laps;
  int last_lap = 0;
  for (size_t i = 0; i < table.line_numbers.size(); ++i) {
    const double t = table.values[0][i];
    if (std::isnan(t)) {
      throw InputError(
          fmt::format("{}:{}: channel 'Time' (column 1) is empty", file, table.line_numbers[i]));
    }
    const int lap = MotecLapAt(t, beacons);  // Time is converted to s
    laps.push_back(lap);
    last_lap = std::max(last_lap, lap);
  }
  table.columns.push_back("lap");
  table.values.push_back(std::move(laps));
  return last_lap;
}

}  // namespace

MotecTable ReadMotecCsv(const std::filesystem::path& path, const MotecChannelMap& map) {
  const std::string file = path.string();
  const std::vector<Record> records = ReadRecords(path);

  // Metadata up to the channel names row (first cell "Time").
  MotecTable out;
  CsvTable& table = out.table;
  table.path = path;
  std::vector<double> beacons;
  size_t r = 0;
  for (; r < records.size() && records[r].cells[0] != "Time"; ++r) {
    if (records[r].cells[0] == "Beacon Markers") beacons = ParseBeacons(records[r], file);
    AddMetadata(records[r], table.metadata);
  }
  if (r == records.size()) {
    throw InputError(fmt::format(
        "{}: no channel names row (a record whose first cell is \"Time\") after the metadata",
        file));
  }
  const Record& names = records[r];
  const Record& units = UnitsRow(records, r, file);
  const size_t width = names.cells.size();

  // Which channel becomes which column (PlanMotecChannels).
  const std::vector<std::string> channel_names = ChannelNames(names, file);
  const std::vector<MotecChannelPlan> plans =
      PlanMotecChannels(channel_names, units.cells, map, [&](size_t c) {
        return fmt::format("{}:{}: channel '{}' (column {})", file, units.line, channel_names[c],
                           c + 1);
      });
  std::vector<std::string> unmapped;
  for (size_t c = 0; c < width; ++c) {
    table.columns.push_back(plans[c].column);
    if (plans[c].entry == nullptr) unmapped.push_back(channel_names[c]);
    out.channels.push_back({channel_names[c], units.cells[c], std::nan(""), 0});
  }

  const std::vector<bool> text_channel =
      ReadDataRows(records, r + 2, names, channel_names, plans, file, table);
  const std::string dropped = DropTextChannels(text_channel, channel_names, out, unmapped);
  const int last_lap = AddLapColumn(beacons, file, table);
  table.metadata.emplace_back("laps", std::to_string(last_lap));
  if (!unmapped.empty()) {
    std::string list;
    for (const std::string& name : unmapped) list += (list.empty() ? "" : ", ") + name;
    table.metadata.emplace_back("unmapped channels", list);
  }
  if (!dropped.empty())
    table.metadata.emplace_back("channels left out (text, not numbers)", dropped);
  table.metadata.emplace_back("channel map", map.path.string());

  out.sources = MotecSources(map);
  return out;
}

}  // namespace hotlap
