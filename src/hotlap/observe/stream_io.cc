#include "hotlap/observe/stream_io.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "hotlap/brake/brake_thermal.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/logs/telemetry.h"

namespace hotlap::observe {

namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> SplitCells(std::string_view line) {
  std::vector<std::string_view> cells;
  size_t from = 0;
  while (true) {
    const size_t comma = line.find(',', from);
    cells.push_back(
        Trim(line.substr(from, comma == std::string_view::npos ? line.npos : comma - from)));
    if (comma == std::string_view::npos) break;
    from = comma + 1;
  }
  return cells;
}

}  // namespace

ObserverSample SampleFromRow(const Telemetry& t, size_t row, const ObserverSample* last,
                             const StreamDefaults& defaults, const std::string& source, int line) {
  // The value of a channel at the row, or NaN when the cell is empty.
  const auto Cell = [&](std::string_view quantity, std::optional<Corner> corner) {
    return t.Channel(quantity, corner)[row];
  };
  ObserverSample sample;
  sample.time = Cell("time", std::nullopt);
  if (last != nullptr && !(sample.time > last->time)) {
    throw InputError(fmt::format("{}:{}: time {:g} s does not increase (previous {:g} s)", source,
                                 line, sample.time, last->time));
  }
  // An input with an empty cell holds its last value.
  const auto input = [&](double value, double previous, bool have_previous,
                         const std::string& what) {
    if (std::isfinite(value)) return value;
    if (have_previous) return previous;
    throw InputError(
        fmt::format("{}:{}: '{}' is empty and no earlier line has a value", source, line, what));
  };
  const bool have = last != nullptr;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    const CornerInputs* prev = have ? &last->inputs[i] : nullptr;
    CornerInputs& in = sample.inputs[i];
    const bool corner_speed = t.Has("speed", c);
    const double speed = corner_speed ? Cell("speed", c) : Cell("speed", std::nullopt);
    in.speed = input(speed, have ? prev->speed : 0.0, have,
                     corner_speed ? t.ColumnOf("speed", c) : t.ColumnOf("speed"));
    in.fx = input(Cell("fx", c), have ? prev->fx : 0.0, have, t.ColumnOf("fx", c));
    in.fy = input(Cell("fy", c), have ? prev->fy : 0.0, have, t.ColumnOf("fy", c));
    in.fz = input(Cell("fz", c), have ? prev->fz : 0.0, have, t.ColumnOf("fz", c));
    in.slip_angle = input(Cell("slip_angle", c), have ? prev->slip_angle : 0.0, have,
                          t.ColumnOf("slip_angle", c));
    in.slip_ratio = input(Cell("slip_ratio", c), have ? prev->slip_ratio : 0.0, have,
                          t.ColumnOf("slip_ratio", c));
    // A logged braking power is the brake's input (sim/replay_io.h); an empty cell holds the
    // last one (none yet: the brake sees fx).
    if (t.Has("brake_power", c)) {
      const double power = Cell("brake_power", c);
      if (std::isfinite(power)) {
        in.brake_fx = brake::BrakeFxFromPower(in.speed, power, in.fx);
      } else if (have) {
        in.brake_fx = prev->brake_fx;
      }
    }
    CornerReadings& r = sample.readings[i];
    if (t.Has("tread_temp", c)) r.tread_temp = Cell("tread_temp", c);
    if (t.Has("disc_temp", c)) r.disc_temp = Cell("disc_temp", c);
    if (t.Has("calliper_temp", c)) r.calliper_temp = Cell("calliper_temp", c);
    if (t.Has("pressure", c)) r.pressure = Cell("pressure", c);
    if (t.Has("gas_temp", c)) r.gas_temp = Cell("gas_temp", c);
  }
  const auto whole_car = [&](const char* quantity, double fallback, double previous) {
    if (!t.Has(quantity)) return fallback;
    const double v = Cell(quantity, std::nullopt);
    return std::isfinite(v) ? v : have ? previous : fallback;
  };
  sample.ambient_temp =
      whole_car("ambient_temp", defaults.ambient_temp, have ? last->ambient_temp : 0.0);
  sample.track_temp = whole_car("track_temp", defaults.track_temp, have ? last->track_temp : 0.0);
  return sample;
}

TelemetryLineReader::TelemetryLineReader(std::istream& in, std::string source,
                                         const StreamDefaults& defaults)
    : in_(in), source_(std::move(source)), defaults_(defaults) {}

bool TelemetryLineReader::ReadHeader() {
  std::string text;
  while (std::getline(in_, text)) {
    ++line_;
    std::string_view s = text;
    if (line_ == 1 && s.substr(0, 3) == "\xEF\xBB\xBF") s.remove_prefix(3);
    s = Trim(s);
    if (s.empty()) continue;
    if (s.front() == '#') {
      s.remove_prefix(1);
      const size_t colon = s.find(':');
      if (colon == std::string_view::npos) {
        metadata_.emplace_back(std::string(Trim(s)), "");
      } else {
        metadata_.emplace_back(std::string(Trim(s.substr(0, colon))),
                               std::string(Trim(s.substr(colon + 1))));
      }
      continue;
    }
    for (std::string_view c : SplitCells(s)) {
      if (c.empty()) {
        throw InputError(fmt::format("{}:{}: empty column name in the header", source_, line_));
      }
      columns_.emplace_back(c);
    }
    header_read_ = true;
    return true;
  }
  return false;
}

std::optional<ObserverSample> TelemetryLineReader::Next() {
  if (!header_read_ && !ReadHeader()) {
    throw InputError(fmt::format("{}: no header line (the CSV header must come first)", source_));
  }
  std::string text;
  std::string_view s;
  while (true) {
    if (!std::getline(in_, text)) return std::nullopt;
    ++line_;
    s = Trim(text);
    if (!s.empty()) break;
  }
  const std::vector<std::string_view> cells = SplitCells(s);
  if (cells.size() != columns_.size()) {
    throw InputError(fmt::format("{}:{}: {} cells, the header has {} columns", source_, line_,
                                 cells.size(), columns_.size()));
  }
  CsvTable table;
  table.path = source_;
  table.columns = columns_;
  table.line_numbers = {line_};
  table.values.resize(columns_.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    double v = kNaN;
    if (!cells[i].empty()) {
      const std::optional<double> parsed = ParseYamlNumber(cells[i]);
      if (!parsed) {
        throw InputError(fmt::format("{}:{}: column '{}' (column {}): '{}' is not a number",
                                     source_, line_, columns_[i], i + 1, cells[i]));
      }
      v = *parsed;
    }
    table.values[i] = {v};
  }
  const Telemetry t = Telemetry::FromTable(std::move(table));
  // One warning per column, as a whole log's: this line's treatments merged into the column's.
  for (const Telemetry::LimitTreatment& w : t.treatments()) {
    const auto it = std::find_if(treatments_.begin(), treatments_.end(),
                                 [&](const auto& u) { return u.column == w.column; });
    if (it == treatments_.end()) {
      treatments_.push_back(w);
      if (warnings_.size() < 20) warnings_.push_back(w.Message());
      ++warning_count_;
      continue;
    }
    it->count += w.count;
    it->last_line = w.last_line;
    const size_t k = static_cast<size_t>(it - treatments_.begin());
    if (k < warnings_.size()) warnings_[k] = it->Message();
  }

  ObserverSample sample = SampleFromRow(t, 0, last_ ? &*last_ : nullptr, defaults_, source_, line_);
  last_ = sample;
  return sample;
}

TelemetryLogReader::TelemetryLogReader(const std::filesystem::path& path,
                                       const TelemetryReadOptions& options,
                                       const StreamDefaults& defaults)
    : log_(Telemetry::Read(path, "time", options)), source_(path.string()), defaults_(defaults) {
  for (const std::string& w : log_.warnings()) {
    if (warnings_.size() < 20) warnings_.push_back(w);
  }
  warning_count_ = static_cast<long>(log_.warnings().size());
}

std::optional<ObserverSample> TelemetryLogReader::Next() {
  if (row_ >= log_.size()) return std::nullopt;
  line_ = log_.LineOf(row_);
  ObserverSample sample =
      SampleFromRow(log_, row_, last_ ? &*last_ : nullptr, defaults_, source_, line_);
  ++row_;
  last_ = sample;
  return sample;
}

LineCsvWriter::LineCsvWriter(const std::string& path) : path_(path) {
  if (path == "-") {
    file_ = stdout;
    is_stdout_ = true;
    return;
  }
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) {
    throw InputError(fmt::format("cannot write '{}': {}", path, std::strerror(errno)));
  }
}

LineCsvWriter::~LineCsvWriter() {
  // Not closed: the run stopped on an error, so the file is unfinished: removed, not left.
  if (file_ != nullptr && !is_stdout_) {
    std::fclose(file_);
    std::remove(path_.c_str());
  }
}

void LineCsvWriter::Put(const std::string& line) {
  if (file_ == nullptr) throw std::logic_error("LineCsvWriter: write after Close()");
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0) {
    throw InputError(fmt::format("cannot write '{}': {}", path_, std::strerror(errno)));
  }
}

void LineCsvWriter::WriteHeader(const std::vector<std::string>& columns) {
  std::string line;
  for (size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) line += ',';
    line += columns[i];
  }
  line += '\n';
  Put(line);
}

void LineCsvWriter::WriteRow(const std::vector<double>& values) {
  std::string line;
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0) line += ',';
    if (std::isfinite(values[i])) line += fmt::format("{}", RoundSignificant(values[i], 9));
  }
  line += '\n';
  Put(line);
}

void LineCsvWriter::Close() {
  if (file_ == nullptr) return;
  if (is_stdout_) {
    std::fflush(file_);
    file_ = nullptr;
    return;
  }
  const int rc = std::fclose(file_);
  file_ = nullptr;
  if (rc != 0) throw InputError(fmt::format("cannot write '{}': {}", path_, std::strerror(errno)));
}

}  // namespace hotlap::observe
