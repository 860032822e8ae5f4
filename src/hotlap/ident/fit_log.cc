#include "hotlap/ident/fit_log.h"
#include "hotlap/common/special_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <fmt/format.h>

#include "hotlap/common/error.h"

namespace hotlap::ident {

namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> SplitCommas(std::string_view text) {
  std::vector<std::string_view> parts;
  while (true) {
    const size_t comma = text.find(',');
    parts.push_back(Trim(text.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return parts;
}

Corner CornerOrThrow(std::string_view name, std::string_view option) {
  if (auto c = ParseCorner(name)) return *c;
  throw InputError(
      fmt::format("{}: unknown corner '{}' (expected fl, fr, rl or rr)", option, name));
}

}  // namespace

int LoggedChannel::Count() const {
  return static_cast<int>(
      std::count_if(values.begin(), values.end(), [](double v) { return std::isfinite(v); }));
}

LoggedChannel ReadLoggedChannel(const Telemetry& log, std::string_view quantity, Corner corner,
                                double min_si, double max_si, double flat_tolerance_si) {
  LoggedChannel ch;
  ch.quantity = std::string(quantity);
  ch.corner = corner;
  ch.values.assign(log.size(), kNaN);
  if (!log.Has(quantity, corner)) {
    ch.problem = "the log has no such column";
    return ch;
  }
  ch.column = log.ColumnOf(quantity, corner);
  const std::vector<double>& raw = log.Channel(quantity, corner);
  std::unordered_map<double, int> counts;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t k = 0; k < raw.size(); ++k) {
    const double v = raw[k];
    if (!std::isfinite(v)) {
      ++ch.empty_cells;
      continue;
    }
    if (v < min_si || v > max_si) {
      ++ch.implausible;
      continue;
    }
    ch.values[k] = v;
    ++counts[v];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  const int n = ch.Count();
  const int needed = std::max(10, static_cast<int>(0.05 * static_cast<double>(log.size())));
  int most = 0;
  double mode = 0.0;
  for (const auto& [v, c] : counts) {
    if (c > most) {
      most = c;
      mode = v;
    }
  }
  if (n < needed) {
    ch.problem =
        fmt::format("only {} usable values of {} (at least {} needed)", n, log.size(), needed);
  } else if (hi - lo <= flat_tolerance_si) {
    ch.problem = fmt::format("constant at {:g} over the whole log: a dead or stuck sensor?", lo);
  } else if (2 * most >= n) {
    ch.problem =
        fmt::format("stuck: {} of its {} values are exactly {:g} (a dead sensor?)", most, n, mode);
  }
  ch.usable = ch.problem.empty();
  if (!ch.usable) std::fill(ch.values.begin(), ch.values.end(), kNaN);
  return ch;
}

std::string DescribeChannelProblems(const LoggedChannel& ch) {
  const std::string name =
      ch.column.empty() ? fmt::format("{}_{}", ch.quantity, CornerName(ch.corner)) : ch.column;
  if (!ch.usable) return fmt::format("{}: excluded from the fit: {}", name, ch.problem);
  if (ch.implausible > 0) {
    return fmt::format("{}: {} implausible values dropped (outside the sensor's plausible range)",
                       name, ch.implausible);
  }
  return {};
}

std::vector<double> TrapezoidWeights(std::span<const double> time) {
  const size_t n = time.size();
  std::vector<double> w(n, 1.0);
  if (n < 2) return w;
  std::vector<double> dt(n - 1);
  for (size_t k = 0; k + 1 < n; ++k) dt[k] = time[k + 1] - time[k];
  std::vector<double> sorted = dt;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double cap = 2.0 * sorted[sorted.size() / 2];
  double sum = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const double left = k > 0 ? std::min(dt[k - 1], cap) : 0.0;
    const double right = k + 1 < n ? std::min(dt[k], cap) : 0.0;
    w[k] = 0.5 * (left + right);
    sum += w[k];
  }
  for (double& x : w) x *= static_cast<double>(n) / sum;
  return w;
}

double RobustFirstValue(std::span<const double> time, std::span<const double> values) {
  std::vector<double> first;
  double t0 = kNaN;
  for (size_t k = 0; k < values.size() && first.size() < 5; ++k) {
    if (!std::isfinite(values[k])) continue;
    if (first.empty()) t0 = time[k];
    if (time[k] - t0 > 1.0) break;
    first.push_back(values[k]);
  }
  if (first.empty()) return kNaN;
  std::sort(first.begin(), first.end());
  return first.size() % 2 == 1 ? first[first.size() / 2]
                               : 0.5 * (first[first.size() / 2 - 1] + first[first.size() / 2]);
}

std::vector<double> SmoothedForGuess(std::span<const double> values) {
  const size_t n = values.size();
  std::vector<double> filled(values.begin(), values.end());
  // Linear fill between measured neighbours (by index), held at the ends.
  size_t last = n;
  for (size_t k = 0; k < n; ++k) {
    if (!std::isfinite(filled[k])) continue;
    if (last == n) {
      for (size_t j = 0; j < k; ++j) filled[j] = filled[k];
    } else {
      for (size_t j = last + 1; j < k; ++j) {
        const double f = static_cast<double>(j - last) / static_cast<double>(k - last);
        filled[j] = filled[last] + f * (filled[k] - filled[last]);
      }
    }
    last = k;
  }
  if (last == n) return filled;  // nothing measured
  for (size_t j = last + 1; j < n; ++j) filled[j] = filled[last];
  std::vector<double> out(n);
  for (size_t k = 0; k < n; ++k) {
    const size_t a = k >= 2 ? k - 2 : 0, b = std::min(n, k + 3);
    double window[5];
    size_t m = 0;
    for (size_t j = a; j < b; ++j) window[m++] = filled[j];
    std::nth_element(window, window + m / 2, window + m);
    out[k] = window[m / 2];
  }
  return out;
}

std::vector<Corner> ParseCornerList(std::string_view text, std::string_view option) {
  text = Trim(text);
  if (text.empty() || text == "all") return {kAllCorners.begin(), kAllCorners.end()};
  std::vector<Corner> corners;
  for (std::string_view part : SplitCommas(text)) {
    const Corner c = CornerOrThrow(part, option);
    if (std::find(corners.begin(), corners.end(), c) == corners.end()) corners.push_back(c);
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

std::map<Corner, double> ParseCornerValues(std::string_view text, std::string_view option) {
  std::map<Corner, double> values;
  if (Trim(text).empty()) return values;
  for (std::string_view part : SplitCommas(text)) {
    const size_t eq = part.find('=');
    if (eq == std::string_view::npos) {
      throw InputError(fmt::format("{}: '{}' is not CORNER=VALUE (e.g. fl=0.03)", option, part));
    }
    const Corner c = CornerOrThrow(Trim(part.substr(0, eq)), option);
    const std::string_view number = Trim(part.substr(eq + 1));
    double v = 0.0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
    if (ec != std::errc() || end != number.data() + number.size() || !std::isfinite(v)) {
      throw InputError(fmt::format("{}: '{}' is not a number", option, number));
    }
    values[c] = v;
  }
  return values;
}

std::optional<int> MetadataInt(const Telemetry& log, std::string_view key) {
  for (const auto& [k, v] : log.metadata()) {
    if (k != key) continue;
    int value = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
    if (ec == std::errc() && end == v.data() + v.size()) return value;
  }
  return std::nullopt;
}

}  // namespace hotlap::ident
