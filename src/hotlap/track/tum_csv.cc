#include "hotlap/track/tum_csv.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"

namespace hotlap::track {

namespace {

constexpr const char* kHeader = "x_m,y_m,w_tr_right_m,w_tr_left_m";
constexpr size_t kMinPoints = 20;
// Largest gap between consecutive points, as a multiple of the median gap.
constexpr double kMaxSpacingRatio = 20.0;

std::string_view Trim(std::string_view t) {
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
  return t;
}

std::vector<std::string_view> Split(std::string_view line) {
  std::vector<std::string_view> cells;
  size_t start = 0;
  for (;;) {
    const size_t comma = line.find(',', start);
    cells.push_back(Trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

}  // namespace

CentreLinePoints ReadTumCentreLine(const std::filesystem::path& path) {
  const std::string text = ReadWholeFile(path);
  const std::string file = path.string();
  const std::vector<std::string> columns = {"x_m", "y_m", "w_tr_right_m", "w_tr_left_m"};
  CentreLinePoints p;
  std::vector<int> lines;
  bool header_seen = false;
  size_t next = 0;  // start of the next line in `text`
  for (int line_number = 1; next < text.size(); ++line_number) {
    const size_t end = std::min(text.find('\n', next), text.size());
    std::string_view line = std::string_view(text).substr(next, end - next);
    next = end + 1;
    if (line_number == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // BOM
    line = Trim(line);
    if (line.empty()) continue;
    if (!header_seen) {
      if (line.front() == '#') line = Trim(line.substr(1));
      std::string compact;
      for (char c : line) {
        if (!std::isspace(static_cast<unsigned char>(c))) compact += c;
      }
      if (compact != kHeader) {
        throw InputError(fmt::format("{}:{}: expected the TUM header '# {}', found '{}'", file,
                                     line_number, kHeader, line));
      }
      header_seen = true;
      continue;
    }
    if (line.front() == '#') continue;  // a comment after the header
    const std::vector<std::string_view> cells = Split(line);
    if (cells.size() != 4) {
      throw InputError(fmt::format("{}:{}: {} cells, expected 4 ({})", file, line_number,
                                   cells.size(), kHeader));
    }
    double v[4];
    for (int c = 0; c < 4; ++c) {
      const std::string_view cell = cells[c];
      const char* begin = cell.data() + (!cell.empty() && cell.front() == '+' ? 1 : 0);
      const auto [ptr, ec] = std::from_chars(begin, cell.data() + cell.size(), v[c]);
      if (cell.empty() || ec != std::errc() || ptr != cell.data() + cell.size() ||
          !std::isfinite(v[c])) {
        throw InputError(fmt::format("{}:{}: column '{}' (column {}): '{}' is not a number", file,
                                     line_number, columns[c], c + 1, cell));
      }
      if (c >= 2 && !(v[c] > 0.0)) {
        throw InputError(
            fmt::format("{}:{}: column '{}' (column {}): value {:g} is out of range: "
                        "must be > 0 m",
                        file, line_number, columns[c], c + 1, v[c]));
      }
    }
    p.x_m.push_back(v[0]);
    p.y_m.push_back(v[1]);
    p.width_right_m.push_back(v[2]);
    p.width_left_m.push_back(v[3]);
    lines.push_back(line_number);
  }
  if (!header_seen) throw InputError(fmt::format("{}: empty file, expected '# {}'", file, kHeader));

  // A loop written with its first point repeated at the end: drop the repeat.
  size_t n = p.x_m.size();
  if (n > 1 && std::hypot(p.x_m[n - 1] - p.x_m[0], p.y_m[n - 1] - p.y_m[0]) < 1e-3) {
    for (auto* v : {&p.x_m, &p.y_m, &p.width_left_m, &p.width_right_m}) v->pop_back();
    lines.pop_back();
    --n;
  }
  if (n < kMinPoints) {
    throw InputError(fmt::format("{}: {} points; a track needs at least {}", file, n, kMinPoints));
  }
  std::vector<double> gaps(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    gaps[i] = std::hypot(p.x_m[j] - p.x_m[i], p.y_m[j] - p.y_m[i]);
    if (i + 1 < n && gaps[i] < 1e-3) {
      throw InputError(
          fmt::format("{}:{}: the point repeats the one on line {} (less than 1 mm "
                      "apart); consecutive points must differ",
                      file, lines[j], lines[i]));
    }
  }
  std::vector<double> sorted = gaps;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double median = sorted[n / 2];
  if (gaps[n - 1] > 5.0 * median) {
    throw InputError(fmt::format(
        "{}: not a closed loop: the last point (line {}) is {:.1f} m from the first (line {}), "
        "more than 5 times the median spacing {:.2f} m",
        file, lines[n - 1], gaps[n - 1], lines[0], median));
  }
  // A point far off the line (a typo, a lost sign) would stretch the track by kilometres, and
  // building it would take minutes: a centre line is sampled evenly.
  for (size_t i = 0; i + 1 < n; ++i) {
    if (gaps[i] > kMaxSpacingRatio * median) {
      throw InputError(fmt::format(
          "{}:{}: the point is {:.1f} m from the one on line {}, more than {:g} times the median "
          "spacing {:.2f} m",
          file, lines[i + 1], gaps[i], lines[i], kMaxSpacingRatio, median));
    }
  }
  return p;
}

Track LoadTumTrack(const std::filesystem::path& path, const CentreLineOptions& options) {
  const CentreLinePoints points = ReadTumCentreLine(path);
  try {
    return TrackFromCentreLine(path.stem().string(), points, options);
  } catch (const NumericalError& e) {
    // Points that no closed ribbon fits (a loop that turns a fraction of a turn, a point far
    // out) are a fault of the file.
    throw InputError(
        fmt::format("{}: no track can be built from these points: {}", path.string(), e.what()));
  }
}

}  // namespace hotlap::track
