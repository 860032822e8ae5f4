#pragma once
/// @file
/// Reading and writing the numeric CSV files of docs/spec telemetry-csv.md: optional `# key: value`
/// metadata lines, one header row, then one row of numbers per sample.
///
/// How to use: ReadCsv() gives a column-major table of doubles in which NaN marks an empty cell
/// ("not measured"); every other problem (a ragged row, `nan`, `inf`, text that is not a number,
/// a duplicate header name) is an InputError naming the file, the line and the column. This layer
/// knows nothing about column names or units; hotlap/logs/telemetry.h adds those.
///
/// Pitfalls: the values are stored as `values[column][row]`, not row-major; NaN in a read table
/// always means an empty cell, never a `nan` in the file (that is rejected).

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hotlap {

/// A numeric CSV file as read: metadata, header and values by column.
struct CsvTable {
  /// The file it was read from, for messages.
  std::filesystem::path path;
  /// The `# key: value` lines before the header, in file order, key and value trimmed. A `#` line
  /// without a colon is a comment: its whole trimmed text is the key and the value is empty.
  std::vector<std::pair<std::string, std::string>> metadata;
  /// Header names as in the file (trimmed), unique and non-empty.
  std::vector<std::string> columns;
  /// values[column][row]; NaN marks an empty cell.
  std::vector<std::vector<double>> values;
  /// 1-based file line of each data row.
  std::vector<int> line_numbers;

  /// Position of the column named exactly `name`, or -1 if there is none.
  int ColumnIndex(std::string_view name) const;
  /// The values of the column named exactly `name`; InputError naming the file if there is none.
  const std::vector<double>& Column(std::string_view name) const;
  /// Number of data rows.
  size_t RowCount() const;
};

/// Reads a numeric CSV file (UTF-8 with or without BOM, LF or CRLF line ends, comma separated).
/// Blank lines are skipped; cells are trimmed; an empty cell reads as NaN. Numbers are parsed
/// independently of the locale. Throws InputError when the file cannot be read, has no header or
/// no data rows, has an empty or duplicate header name, a row whose cell count differs from the
/// header, or a cell that is not a finite number (`FILE:LINE: column 'NAME' (column N): 'TEXT' is
/// not a number`).
CsvTable ReadCsv(const std::filesystem::path& path);

/// Writes `# key: value` metadata lines (`# key` where the value is empty), the header, then one
/// row per sample, with `values[column][row]`. Numbers are written in the shortest form that reads
/// back to the identical double; NaN is written as an empty cell. The file is written to a
/// temporary beside `path` and renamed into place (WriteFileAtomically), so a failed write never
/// leaves a partial file. Everything is checked before the file is touched: throws
/// std::invalid_argument (a programming error) when the column count or the column lengths
/// disagree, a column name is empty or holds a comma or a line break, a metadata key holds a colon
/// or a line break, or a one-column table has an empty cell (it would be a blank line, which
/// readers skip); NumericalError when a value is infinite. Throws InputError when the file cannot
/// be written.
void WriteCsv(const std::filesystem::path& path,
              const std::vector<std::pair<std::string, std::string>>& metadata,
              const std::vector<std::string>& columns,
              const std::vector<std::vector<double>>& values);

}  // namespace hotlap
