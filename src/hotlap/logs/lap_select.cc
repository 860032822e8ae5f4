#include "hotlap/logs/lap_select.h"

#include <cmath>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "hotlap/common/error.h"

namespace hotlap {

void SelectLap(CsvTable& table, int lap) {
  const int column = table.ColumnIndex("lap");
  if (column < 0) {
    throw InputError(fmt::format(
        "{}: lap {} asked for, but the log has no 'lap' column (a MoTeC CSV export has one from "
        "its Beacon Markers)",
        table.path.string(), lap));
  }
  const std::vector<double> laps = table.values[static_cast<size_t>(column)];
  std::set<long long> present;
  std::vector<size_t> keep;
  for (size_t i = 0; i < laps.size(); ++i) {
    // A lap number beyond 1e9 is not one (and would overflow the arithmetic below).
    if (std::isnan(laps[i]) || std::abs(laps[i]) > 1e9) continue;
    present.insert(std::llround(laps[i]));
    if (laps[i] == lap) keep.push_back(i);
  }
  if (keep.empty()) {
    std::string there = "none";
    if (!present.empty()) {
      const bool contiguous =
          *present.rbegin() - *present.begin() + 1 == static_cast<long long>(present.size());
      if (present.size() == 1) {
        there = fmt::format("lap {}", *present.begin());
      } else if (contiguous) {
        there = fmt::format("laps {} to {}", *present.begin(), *present.rbegin());
      } else {
        there = fmt::format("laps {}", fmt::join(present, ", "));
      }
    }
    throw InputError(
        fmt::format("{}: lap {}: no such lap; the log has {}", table.path.string(), lap, there));
  }
  for (std::vector<double>& values : table.values) {
    std::vector<double> kept;
    kept.reserve(keep.size());
    for (size_t i : keep) kept.push_back(values[i]);
    values = std::move(kept);
  }
  std::vector<int> lines;
  for (size_t i : keep) lines.push_back(table.line_numbers[i]);
  table.line_numbers = std::move(lines);
}

}  // namespace hotlap
