#include "hotlap/logs/telemetry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/string_match.h"
#include "hotlap/common/telemetry_limits.h"
#include "hotlap/logs/log_table.h"

namespace hotlap {
namespace {

// A unit a file may use: si = value * scale + offset.
struct UnitInfo {
  std::string_view name;
  double scale;
  double offset;
};

// A quantity of the spec's table; units[0] is the canonical file unit.
struct QuantityInfo {
  std::string_view name;
  bool per_corner;  // false: whole car only (the index channels)
  std::span<const UnitInfo> units;
};

constexpr double kCelsiusToKelvin = 273.15;
constexpr UnitInfo kSeconds[] = {{"s", 1.0, 0.0}};
constexpr UnitInfo kMetres[] = {{"m", 1.0, 0.0}};
constexpr UnitInfo kSpeed[] = {{"mps", 1.0, 0.0}, {"kph", 1.0 / 3.6, 0.0}, {"mph", 0.44704, 0.0}};
constexpr UnitInfo kForce[] = {{"N", 1.0, 0.0}, {"kN", 1000.0, 0.0}};
constexpr UnitInfo kAngle[] = {{"rad", 1.0, 0.0}, {"deg", std::numbers::pi / 180.0, 0.0}};
constexpr UnitInfo kNone[] = {{"1", 1.0, 0.0}};
constexpr UnitInfo kTemperature[] = {{"C", 1.0, kCelsiusToKelvin}, {"K", 1.0, 0.0}};
constexpr UnitInfo kWear[] = {{"mm", 1.0, 0.0}};  // wear is held in mm
constexpr UnitInfo kLength[] = {{"m", 1.0, 0.0}, {"mm", 0.001, 0.0}};
constexpr UnitInfo kPower[] = {{"W", 1.0, 0.0}, {"kW", 1000.0, 0.0}};
constexpr UnitInfo kHeatFlow[] = {{"W", 1.0, 0.0}};
// Inflation pressure, gauge, held in Pa; kPa is the file's unit.
constexpr UnitInfo kPressure[] = {
    {"kPa", 1000.0, 0.0}, {"psi", 6894.757293168361, 0.0}, {"bar", 1.0e5, 0.0}};

constexpr QuantityInfo kQuantities[] = {
    {"time", false, kSeconds},
    {"distance", false, kMetres},
    {"speed", true, kSpeed},
    {"fx", true, kForce},
    {"fy", true, kForce},
    {"fz", true, kForce},
    {"slip_angle", true, kAngle},
    {"slip_ratio", true, kNone},
    {"ambient_temp", true, kTemperature},
    {"track_temp", true, kTemperature},
    {"tread_temp", true, kTemperature},
    {"carcass_temp", true, kTemperature},
    {"disc_temp", true, kTemperature},
    {"calliper_temp", true, kTemperature},
    {"gas_temp", true, kTemperature},  // the inflation gas (TPMS)
    {"rim_temp", true, kTemperature},
    {"pressure", true, kPressure},  // the inflation pressure, gauge (TPMS)
    {"wear", true, kWear},
    {"rolling_radius", true, kLength},
    {"grip_factor", true, kNone},
    {"brake_power", true, kPower},
    {"q1", true, kHeatFlow},
    {"q2", true, kHeatFlow},
    {"q3", true, kHeatFlow},
    {"q4", true, kHeatFlow},
    {"q5", true, kHeatFlow},
    {"q6", true, kHeatFlow},
    {"q7", true, kHeatFlow},
};

const QuantityInfo* FindQuantity(std::string_view name) {
  for (const QuantityInfo& q : kQuantities) {
    if (q.name == name) return &q;
  }
  return nullptr;
}

const QuantityInfo& KnownQuantity(std::string_view name) {
  const QuantityInfo* q = FindQuantity(name);
  if (q == nullptr) {
    throw std::invalid_argument("'" + std::string(name) +
                                "' is not a telemetry quantity of the spec's table");
  }
  return *q;
}

const UnitInfo* FindUnit(const QuantityInfo& q, std::string_view unit) {
  for (const UnitInfo& u : q.units) {
    if (u.name == unit) return &u;
  }
  return nullptr;
}

bool IsDimensionless(const QuantityInfo& q) { return q.units.front().name == "1"; }

// "FILE: " or "" when there is no file.
std::string FilePrefix(const std::filesystem::path& file) {
  return file.empty() ? std::string() : file.string() + ": ";
}

// Every column name the spec accepts for this channel, canonical unit first.
std::vector<std::string> ExpectedColumns(const QuantityInfo& q, std::optional<Corner> corner) {
  std::vector<std::string> names;
  for (const UnitInfo& u : q.units) names.push_back(ChannelColumn(q.name, corner, u.name));
  return names;
}

std::string AcceptedUnitList(const QuantityInfo& q) {
  if (IsDimensionless(q)) return "none (a dimensionless column has no unit suffix)";
  std::vector<std::string> names;
  for (const UnitInfo& u : q.units) names.emplace_back(u.name);
  return QuotedList(names);
}

std::string ChannelKey(std::string_view quantity, std::optional<Corner> corner) {
  std::string key(quantity);
  if (corner) key += "_" + std::string(CornerName(*corner));
  return key;
}

// Up to three columns of `columns` close to any of `expected`, best matches of the canonical
// name first.
std::vector<std::string> ClosestColumns(const std::vector<std::string>& expected,
                                        const std::vector<std::string>& columns) {
  std::vector<std::string> found;
  for (const std::string& name : expected) {
    for (std::string& c : ClosestNames(name, columns)) {
      if (found.size() < 3 && std::find(found.begin(), found.end(), c) == found.end()) {
        found.push_back(std::move(c));
      }
    }
  }
  return found;
}

std::string ClosestText(const std::vector<std::string>& expected,
                        const std::vector<std::string>& columns) {
  const std::vector<std::string> closest = ClosestColumns(expected, columns);
  if (closest.empty()) return "no similar column in the file";
  return "closest columns in the file: " + QuotedList(closest);
}

}  // namespace

std::optional<ChannelName> ParseChannelName(std::string_view column,
                                            const std::filesystem::path& file_for_messages) {
  // The longest known quantity that the column starts with, followed by '_' or the end.
  const QuantityInfo* quantity = nullptr;
  for (const QuantityInfo& q : kQuantities) {
    const bool matches = column.substr(0, q.name.size()) == q.name &&
                         (column.size() == q.name.size() || column[q.name.size()] == '_');
    if (matches && (quantity == nullptr || q.name.size() > quantity->name.size())) quantity = &q;
  }
  if (quantity == nullptr) return std::nullopt;

  // The rest, "", "<unit>", "<corner>" or "<corner>_<unit>".
  std::vector<std::string_view> parts;
  if (column.size() > quantity->name.size()) {
    std::string_view rest = column.substr(quantity->name.size() + 1);
    while (true) {
      const size_t underscore = rest.find('_');
      parts.push_back(rest.substr(0, underscore));
      if (underscore == std::string_view::npos) break;
      rest.remove_prefix(underscore + 1);
    }
  }
  ChannelName name{std::string(quantity->name), std::nullopt, "1"};
  std::optional<std::string_view> unit;
  if (parts.size() == 1) {
    name.corner = ParseCorner(parts[0]);
    if (!name.corner) unit = parts[0];
  } else if (parts.size() == 2) {
    name.corner = ParseCorner(parts[0]);
    // Not `<corner>_<unit>` (e.g. `time_of_day`): not a channel of the spec, carried through.
    if (!name.corner) return std::nullopt;
    unit = parts[1];
  } else if (parts.size() > 2) {
    return std::nullopt;
  }

  const std::string prefix = FilePrefix(file_for_messages) + "column '" + std::string(column) + "'";
  if (name.corner && !quantity->per_corner) {
    throw InputError(fmt::format(
        "{}: {} is for the whole car and takes no corner; write '{}'", prefix, quantity->name,
        ChannelColumn(quantity->name, std::nullopt, quantity->units.front().name)));
  }
  if (!unit) {
    if (IsDimensionless(*quantity)) return name;
    throw InputError(fmt::format("{} has no unit; write {}", prefix,
                                 QuotedList(ExpectedColumns(*quantity, name.corner))));
  }
  if (FindUnit(*quantity, *unit) == nullptr) {
    throw InputError(fmt::format("{}: unit '{}' is not accepted for {}; accepted units: {}", prefix,
                                 *unit, quantity->name, AcceptedUnitList(*quantity)));
  }
  name.unit = std::string(*unit);
  return name;
}

std::string ChannelColumn(std::string_view quantity, std::optional<Corner> corner,
                          std::string_view unit) {
  std::string column = ChannelKey(quantity, corner);
  if (!unit.empty() && unit != "1") column += "_" + std::string(unit);
  return column;
}

std::vector<std::string_view> AcceptedUnits(std::string_view quantity) {
  std::vector<std::string_view> units;
  for (const UnitInfo& u : KnownQuantity(quantity).units) units.push_back(u.name);
  return units;
}

std::string_view CanonicalUnit(std::string_view quantity) {
  return KnownQuantity(quantity).units.front().name;
}

double ConvertSiToCanonical(std::string_view quantity, double value_si) {
  const UnitInfo& canonical = KnownQuantity(quantity).units.front();
  return (value_si - canonical.offset) / canonical.scale;
}

Telemetry Telemetry::Read(const std::filesystem::path& path, std::string_view index_quantity,
                          const TelemetryReadOptions& options) {
  if (index_quantity != "time" && index_quantity != "distance") {
    throw std::invalid_argument(
        "Telemetry::Read: index quantity must be 'time' or 'distance', not '" +
        std::string(index_quantity) + "'");
  }
  LogTable read = ReadLogTable(path, options);
  Telemetry log = FromTable(std::move(read.table), index_quantity);
  log.source_names_ = std::move(read.sources);
  log.channel_map_ = std::move(read.channel_map);
  return log;
}

Telemetry Telemetry::FromTable(CsvTable table, std::string_view index_quantity) {
  if (index_quantity != "time" && index_quantity != "distance") {
    throw std::invalid_argument(
        "Telemetry::FromTable: index quantity must be 'time' or 'distance', not '" +
        std::string(index_quantity) + "'");
  }
  const std::filesystem::path path = table.path;
  const std::string file = path.string();
  if (table.values.size() != table.columns.size()) {
    throw std::invalid_argument("Telemetry::FromTable: one value vector per column");
  }
  const size_t rows = table.values.empty() ? 0 : table.values.front().size();
  for (size_t c = 0; c < table.columns.size(); ++c) {
    if (table.values[c].size() != rows) {
      throw InputError(fmt::format("{}: column '{}' has {} values, column '{}' {}", file,
                                   table.columns[c], table.values[c].size(), table.columns[0],
                                   rows));
    }
    for (size_t i = 0; i < rows; ++i) {
      if (std::isinf(table.values[c][i])) {
        throw InputError(fmt::format("{}: column '{}', row {}: {} is not a finite number", file,
                                     table.columns[c], i + 1, table.values[c][i]));
      }
    }
    for (size_t d = 0; d < c; ++d) {
      if (table.columns[d] == table.columns[c]) {
        throw InputError(fmt::format("{}: column '{}' given twice", file, table.columns[c]));
      }
    }
  }
  if (rows == 0) throw InputError(fmt::format("{}: no data rows", file));
  if (table.line_numbers.size() != rows) {
    // Columns given in memory: row i is "line" i + 2, as if under a header line.
    table.line_numbers.resize(rows);
    for (size_t i = 0; i < rows; ++i) table.line_numbers[i] = static_cast<int>(i) + 2;
  }

  Telemetry log;
  log.path_ = path;
  log.metadata_ = std::move(table.metadata);
  log.columns_ = table.columns;
  log.line_numbers_ = std::move(table.line_numbers);
  log.index_quantity_ = std::string(index_quantity);

  for (size_t c = 0; c < table.columns.size(); ++c) {
    const std::string& column = table.columns[c];
    const std::optional<ChannelName> name = ParseChannelName(column, path);
    if (!name) {
      log.unknown_columns_.emplace_back(column, std::move(table.values[c]));
      continue;
    }
    const std::string key = ChannelKey(name->quantity, name->corner);
    if (const auto it = log.channels_.find(key); it != log.channels_.end()) {
      throw InputError(fmt::format(
          "{}: columns '{}' (column {}) and '{}' (column {}) are the same "
          "channel; keep one",
          file, it->second.column, table.ColumnIndex(it->second.column) + 1, column, c + 1));
    }
    // Convert to SI; NaN (empty) stays NaN.
    const UnitInfo& unit = *FindUnit(KnownQuantity(name->quantity), name->unit);
    std::vector<double> values = std::move(table.values[c]);
    for (double& v : values) v = v * unit.scale + unit.offset;
    if (const std::optional<ChannelLimits> limits = LimitsOf(name->quantity)) {
      log.ApplyLimits(*limits, column, name->unit, unit.scale, unit.offset, values);
    }
    log.channels_.emplace(key, StoredChannel{column, std::move(values)});
  }

  // The index: present, complete, strictly increasing.
  const StoredChannel& index = log.Get(index_quantity, std::nullopt);
  for (size_t i = 0; i < index.values.size(); ++i) {
    if (std::isnan(index.values[i])) {
      throw InputError(
          fmt::format("{}:{}: '{}' is empty; the index column needs a value on every "
                      "row",
                      file, log.LineOf(i), index.column));
    }
    if (i > 0 && !(index.values[i] > index.values[i - 1])) {
      throw InputError(
          fmt::format("{}:{}: '{}' must be strictly increasing, but {} follows {} "
                      "(line {})",
                      file, log.LineOf(i), index.column, index.values[i], index.values[i - 1],
                      log.LineOf(i - 1)));
    }
  }
  return log;
}

void Telemetry::ApplyLimits(const ChannelLimits& limits, const std::string& column,
                            const std::string& unit, double scale, double offset,
                            std::vector<double>& values) {
  const std::string file = path_.string();
  // The limit in the column's own unit, for messages.
  const auto in_unit = [&](double si) { return (si - offset) / scale; };
  const std::string unit_text = unit == "1" ? std::string() : " " + unit;
  size_t treated = 0;
  int first_line = 0, last_line = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (std::isnan(v)) continue;
    if (v < limits.refuse_below || v > limits.refuse_above) {
      throw InputError(fmt::format("{}:{}: '{}' is {:g}{}: impossible ({}); fix or remove the row",
                                   file, LineOf(i), column, in_unit(v), unit_text, limits.reason));
    }
    if (v < limits.physical_min) {
      values[i] = limits.physical_min;
      if (treated++ == 0) first_line = LineOf(i);
      last_line = LineOf(i);
    }
  }
  if (treated > 0) {
    LimitTreatment t{file,
                     column,
                     treated,
                     first_line,
                     last_line,
                     fmt::format("from {:g} to below {:g}{}", in_unit(limits.refuse_below),
                                 in_unit(limits.physical_min), unit_text),
                     fmt::format("taken as {:g}{}: {}", in_unit(limits.physical_min), unit_text,
                                 limits.treated_as)};
    warnings_.push_back(t.Message());
    treatments_.push_back(std::move(t));
  }
}

std::string Telemetry::LimitTreatment::Message() const {
  return fmt::format("{}: '{}': {} value{} {} (lines {}-{}) {}", file, column, count,
                     count == 1 ? "" : "s", range, first_line, last_line, treatment);
}

const Telemetry::StoredChannel* Telemetry::Find(std::string_view quantity,
                                                std::optional<Corner> corner) const {
  const QuantityInfo& q = KnownQuantity(quantity);
  if (corner && !q.per_corner) {
    throw std::invalid_argument("telemetry quantity '" + std::string(quantity) +
                                "' has no corners");
  }
  const auto it = channels_.find(ChannelKey(quantity, corner));
  return it == channels_.end() ? nullptr : &it->second;
}

const Telemetry::StoredChannel& Telemetry::Get(std::string_view quantity,
                                               std::optional<Corner> corner) const {
  if (const StoredChannel* channel = Find(quantity, corner)) return *channel;
  const std::vector<std::string> expected = ExpectedColumns(KnownQuantity(quantity), corner);
  throw InputError(fmt::format("{}: missing column {}; {}{}", path_.string(), QuotedList(expected),
                               ClosestText(expected, columns_),
                               SourceText({ChannelKey(quantity, corner)})));
}

bool Telemetry::Has(std::string_view quantity, std::optional<Corner> corner) const {
  return Find(quantity, corner) != nullptr;
}

const std::vector<double>& Telemetry::Channel(std::string_view quantity,
                                              std::optional<Corner> corner) const {
  return Get(quantity, corner).values;
}

const std::string& Telemetry::ColumnOf(std::string_view quantity,
                                       std::optional<Corner> corner) const {
  return Get(quantity, corner).column;
}

std::vector<double> Telemetry::Fill(const StoredChannel& channel) const {
  std::vector<double> values = channel.values;
  const std::vector<double>& x = index();
  // Rows that hold a value.
  std::vector<size_t> measured;
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isnan(values[i])) measured.push_back(i);
  }
  if (measured.empty()) {
    throw InputError(
        fmt::format("{}: column '{}' has no value on any row", path_.string(), channel.column));
  }
  // Constant before the first and after the last measured sample.
  for (size_t i = 0; i < measured.front(); ++i) values[i] = values[measured.front()];
  for (size_t i = measured.back() + 1; i < values.size(); ++i) values[i] = values[measured.back()];
  // Linear in the index between measured neighbours.
  for (size_t k = 0; k + 1 < measured.size(); ++k) {
    const size_t a = measured[k];
    const size_t b = measured[k + 1];
    for (size_t i = a + 1; i < b; ++i) {
      const double w = (x[i] - x[a]) / (x[b] - x[a]);
      values[i] = values[a] + w * (values[b] - values[a]);
    }
  }
  return values;
}

std::vector<double> Telemetry::FilledChannel(std::string_view quantity,
                                             std::optional<Corner> corner) const {
  return Fill(Get(quantity, corner));
}

std::vector<double> Telemetry::CornerSpeed(Corner corner) const {
  if (const StoredChannel* speed = Find("speed", corner)) return Fill(*speed);
  if (const StoredChannel* speed = Find("speed", std::nullopt)) return Fill(*speed);
  const QuantityInfo& q = KnownQuantity("speed");
  std::vector<std::string> expected = ExpectedColumns(q, corner);
  const std::vector<std::string> whole_car = ExpectedColumns(q, std::nullopt);
  const std::string message =
      fmt::format("{}: missing the speed at {}: expected {}, or the whole-car {}; ", path_.string(),
                  CornerName(corner), QuotedList(expected), QuotedList(whole_car));
  expected.insert(expected.end(), whole_car.begin(), whole_car.end());
  throw InputError(message + ClosestText(expected, columns_) +
                   SourceText({ChannelKey("speed", corner), "speed"}));
}

std::string Telemetry::SourceText(const std::vector<std::string>& keys) const {
  if (channel_map_.empty()) return {};
  std::vector<std::string> names;
  for (const std::string& key : keys) {
    if (const auto it = source_names_.find(key); it != source_names_.end()) {
      names.insert(names.end(), it->second.begin(), it->second.end());
    }
  }
  if (names.empty()) {
    return fmt::format(
        " (no MoTeC channel maps to it in the channel map '{}'; add one there or "
        "give --channel-map)",
        channel_map_.string());
  }
  return fmt::format(" (the MoTeC channels that map to it, by the channel map '{}': {})",
                     channel_map_.string(), QuotedList(names));
}

std::optional<double> Telemetry::FirstValue(std::string_view quantity,
                                            std::optional<Corner> corner) const {
  const StoredChannel* channel = Find(quantity, corner);
  if (channel == nullptr) return std::nullopt;
  for (double v : channel->values) {
    if (!std::isnan(v)) return v;
  }
  return std::nullopt;
}

}  // namespace hotlap
