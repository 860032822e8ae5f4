#include "hotlap/common/csv.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/common/special_values.h"

namespace hotlap {
namespace {

std::string_view Trim(std::string_view s) {
  constexpr std::string_view kSpace = " \t\r\n\f\v";
  const size_t begin = s.find_first_not_of(kSpace);
  if (begin == std::string_view::npos) return {};
  const size_t end = s.find_last_not_of(kSpace);
  return s.substr(begin, end - begin + 1);
}

std::vector<std::string_view> SplitCells(std::string_view line) {
  std::vector<std::string_view> cells;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      cells.push_back(Trim(line.substr(start)));
      return cells;
    }
    cells.push_back(Trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

// A `#` line before the header: "key: value", or a comment kept whole as the key.
std::pair<std::string, std::string> ParseMetadata(std::string_view line) {
  const std::string_view text = Trim(line.substr(1));
  const size_t colon = text.find(':');
  if (colon == std::string_view::npos) return {std::string(text), std::string()};
  return {std::string(Trim(text.substr(0, colon))), std::string(Trim(text.substr(colon + 1)))};
}

// Parses one trimmed, non-empty cell; throws the "is not a number" / "is not finite" errors.
double ParseCell(std::string_view cell, const std::string& where) {
  std::string_view digits = cell;
  // std::from_chars rejects a leading '+', which other tools do write.
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);
  }
  double value = kNaN;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const bool whole = end == digits.data() + digits.size();
  if (ec == std::errc::result_out_of_range && whole) {
    const size_t exponent = digits.find_first_of("eE");
    const bool underflow = exponent != std::string_view::npos && exponent + 1 < digits.size() &&
                           digits[exponent + 1] == '-';
    if (underflow) return digits[0] == '-' ? -0.0 : 0.0;
    throw InputError(where + ": '" + std::string(cell) +
                     "' is not finite (out of the range of a double)");
  }
  if (ec != std::errc() || !whole) {
    throw InputError(where + ": '" + std::string(cell) + "' is not a number");
  }
  if (!std::isfinite(value)) {
    throw InputError(where + ": '" + std::string(cell) +
                     "' is not finite (leave the cell empty where nothing was measured)");
  }
  return value;
}

// Throws std::invalid_argument when `text` contains any of `forbidden`.
void CheckText(std::string_view text, std::string_view forbidden, std::string_view what) {
  if (text.find_first_of(forbidden) != std::string_view::npos) {
    throw std::invalid_argument("WriteCsv: " + std::string(what) + " '" + std::string(text) +
                                "' contains a character that would not read back");
  }
}

}  // namespace

int CsvTable::ColumnIndex(std::string_view name) const {
  for (size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return static_cast<int>(i);
  }
  return -1;
}

const std::vector<double>& CsvTable::Column(std::string_view name) const {
  const int i = ColumnIndex(name);
  if (i < 0) throw InputError(fmt::format("{}: no column '{}'", path.string(), name));
  return values[static_cast<size_t>(i)];
}

size_t CsvTable::RowCount() const { return line_numbers.size(); }

CsvTable ReadCsv(const std::filesystem::path& path) {
  const std::string text = ReadWholeFile(path);
  const std::string file = path.string();

  CsvTable table;
  table.path = path;
  bool have_header = false;
  int header_line = 0;
  int line_number = 0;
  for (const std::string_view line : TextLines(text)) {
    ++line_number;

    const std::string_view trimmed = Trim(line);
    if (trimmed.empty()) continue;
    if (trimmed[0] == '#') {
      if (have_header) {
        throw InputError(
            fmt::format("{}:{}: '#' lines are only allowed before the header (line {})", file,
                        line_number, header_line));
      }
      table.metadata.push_back(ParseMetadata(trimmed));
      continue;
    }

    const std::vector<std::string_view> cells = SplitCells(line);
    if (!have_header) {
      // The header: unique, non-empty names.
      for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].empty()) {
          throw InputError(
              fmt::format("{}:{}: column {} of the header has no name", file, line_number, i + 1));
        }
        for (size_t j = 0; j < i; ++j) {
          if (cells[j] == cells[i]) {
            throw InputError(fmt::format("{}:{}: the header names '{}' twice (columns {} and {})",
                                         file, line_number, cells[i], j + 1, i + 1));
          }
        }
        table.columns.emplace_back(cells[i]);
      }
      table.values.resize(table.columns.size());
      have_header = true;
      header_line = line_number;
      continue;
    }

    if (cells.size() != table.columns.size()) {
      throw InputError(fmt::format("{}:{}: {} cells, but the header (line {}) has {} columns", file,
                                   line_number, cells.size(), header_line, table.columns.size()));
    }
    for (size_t c = 0; c < cells.size(); ++c) {
      if (cells[c].empty()) {
        table.values[c].push_back(kNaN);
        continue;
      }
      const std::string where =
          fmt::format("{}:{}: column '{}' (column {})", file, line_number, table.columns[c], c + 1);
      table.values[c].push_back(ParseCell(cells[c], where));
    }
    table.line_numbers.push_back(line_number);
  }

  if (!have_header) {
    throw InputError(file + ": no header row (the file is empty or has only '#' lines)");
  }
  if (table.line_numbers.empty()) throw InputError(file + ": no data rows");
  return table;
}

void WriteCsv(const std::filesystem::path& path,
              const std::vector<std::pair<std::string, std::string>>& metadata,
              const std::vector<std::string>& columns,
              const std::vector<std::vector<double>>& values) {
  // Check everything before the file is touched.
  if (values.size() != columns.size()) {
    throw std::invalid_argument(fmt::format("WriteCsv('{}'): {} columns named but {} given",
                                            path.string(), columns.size(), values.size()));
  }
  const size_t rows = values.empty() ? 0 : values.front().size();
  for (size_t c = 0; c < columns.size(); ++c) {
    CheckText(columns[c], ",\r\n", "column name");
    if (columns[c].empty()) {
      throw std::invalid_argument(
          fmt::format("WriteCsv('{}'): column {} has an empty name", path.string(), c + 1));
    }
    if (values[c].size() != rows) {
      throw std::invalid_argument(
          fmt::format("WriteCsv('{}'): column '{}' has {} values but column '{}' has {}",
                      path.string(), columns[c], values[c].size(), columns[0], rows));
    }
    for (size_t r = 0; r < rows; ++r) {
      if (columns.size() == 1 && std::isnan(values[c][r])) {
        // The row would be a blank line, which readers skip.
        throw std::invalid_argument(
            fmt::format("WriteCsv('{}'): a file with one column cannot hold an empty cell (row {})",
                        path.string(), r + 1));
      }
      if (std::isinf(values[c][r])) {
        throw NumericalError(fmt::format("cannot write '{}': column '{}' is infinite in row {}",
                                         path.string(), columns[c], r + 1));
      }
    }
  }
  for (const auto& [key, value] : metadata) {
    CheckText(key, ":\r\n", "metadata key");
    CheckText(value, "\r\n", "metadata value");
  }

  WriteFileAtomically(path, [&](std::ostream& out) {
    for (const auto& [key, value] : metadata) {
      out << (value.empty() ? fmt::format("# {}\n", key) : fmt::format("# {}: {}\n", key, value));
    }
    std::string line;
    for (size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) line += ',';
      line += columns[c];
    }
    out << line << '\n';
    for (size_t r = 0; r < rows; ++r) {
      line.clear();
      for (size_t c = 0; c < columns.size(); ++c) {
        if (c > 0) line += ',';
        // Shortest text that reads back to the same double; empty for "not measured".
        if (!std::isnan(values[c][r])) fmt::format_to(std::back_inserter(line), "{}", values[c][r]);
      }
      out << line << '\n';
    }
  });
}

}  // namespace hotlap
