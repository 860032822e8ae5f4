#include "hotlap/report/html_report.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <stdexcept>

#include "hotlap/common/atomic_file.h"
#include "hotlap/report/assets.h"
#include "hotlap/report/decimate.h"
#include "hotlap/report/palette.h"
#include "hotlap/report/web_text.h"

namespace hotlap::report {

namespace {

/// A number for the JSON (axis limits): shortest exact form, or null.
std::string JsonNumber(std::optional<double> value) {
  if (!value || !std::isfinite(*value)) return "null";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, *value);
  return std::string(buffer, result.ptr);
}

std::string AxisTitle(const Axis& axis) {
  return axis.unit.empty() ? axis.label : axis.label + " (" + axis.unit + ")";
}

void CheckRange(const Axis& axis, const std::string& chart, const char* which) {
  if (axis.min && axis.max && !(*axis.min < *axis.max)) {
    throw std::invalid_argument("chart '" + chart + "': " + which + " axis min " +
                                JsonNumber(axis.min) + " is not below max " + JsonNumber(axis.max));
  }
}

std::string AxisJson(const Axis& axis) {
  return "{\"title\":" + JsonQuote(AxisTitle(axis)) + ",\"min\":" + JsonNumber(axis.min) +
         ",\"max\":" + JsonNumber(axis.max) +
         ",\"integer\":" + (axis.integer_ticks ? "true" : "false") + "}";
}

std::string DashJson(LineStyle style) {
  switch (style) {
    case LineStyle::kDashed:
      return "[6,3]";
    case LineStyle::kDotted:
      return "[2,2]";
    case LineStyle::kSolid:
      break;
  }
  return "[]";
}

/// A cell that reads as a number (possibly with a sign, decimals, exponent or a/b/c triples) is
/// right-aligned.
bool LooksNumeric(const std::string& cell) {
  if (cell.empty()) return false;
  return std::all_of(cell.begin(), cell.end(),
                     [](char c) {
                       return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' ||
                              c == 'e' || c == '/' || c == ' ';
                     }) &&
         std::any_of(cell.begin(), cell.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// "90001" -> "90 001", for notes.
std::string Grouped(size_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

}  // namespace

HtmlReport::HtmlReport(std::string title, ReportOptions options)
    : title_(std::move(title)), options_(options) {
  if (options_.max_points_per_series < 5) {
    throw std::invalid_argument("ReportOptions::max_points_per_series must be at least 5");
  }
}

LineChart TimeChart(const std::string& title, const std::string& label, const std::string& unit) {
  return LineChart{.title = title,
                   .x_axis = {.label = "time", .unit = "s"},
                   .y_axis = {.label = label, .unit = unit},
                   .x_link = "time"};
}

void HtmlReport::AddMetadata(std::string key, std::string value) {
  metadata_.emplace_back(std::move(key), std::move(value));
}

void HtmlReport::AddHeading(const std::string& text) {
  blocks_.push_back({BlockKind::kHtml, "<h2>" + EscapeHtml(text) + "</h2>\n"});
}

void HtmlReport::AddText(const std::string& text) {
  blocks_.push_back({BlockKind::kHtml, "<p>" + EscapeHtml(text) + "</p>\n"});
}

void HtmlReport::AddTable(const Table& table) {
  std::string html = "<div class=\"table-wrap\"><table>\n";
  if (!table.title.empty()) html += "<caption>" + EscapeHtml(table.title) + "</caption>\n";
  html += "<thead><tr>";
  for (const std::string& h : table.header) html += "<th>" + EscapeHtml(h) + "</th>";
  html += "</tr></thead>\n<tbody>\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    if (row.size() != table.header.size()) {
      throw std::invalid_argument("table '" + table.title + "': row " + std::to_string(r + 1) +
                                  " has " + std::to_string(row.size()) + " cells, the header " +
                                  std::to_string(table.header.size()));
    }
    html += "<tr>";
    for (const std::string& cell : row) {
      html += LooksNumeric(cell) ? "<td class=\"num\">" : "<td>";
      html += EscapeHtml(cell) + "</td>";
    }
    html += "</tr>\n";
  }
  html += "</tbody></table></div>\n";
  blocks_.push_back({BlockKind::kHtml, std::move(html)});
}

int HtmlReport::PoolArray(std::string json_array) {
  const auto [it, added] = array_index_.try_emplace(json_array, static_cast<int>(arrays_.size()));
  if (added) arrays_.push_back(std::move(json_array));
  return it->second;
}

std::string HtmlReport::DecimationNote(size_t longest, size_t shown) const {
  if (longest <= options_.max_points_per_series) return "";
  return "Thinned for display: " + Grouped(longest) + " samples per line drawn as " +
         Grouped(shown) +
         " points (the first, the last, and the lowest and highest of every bucket of about " +
         Grouped(2 * longest / options_.max_points_per_series) + ").";
}

void HtmlReport::AddChartBlock(const std::string& chart_json, const std::string& title,
                               const char* css_class, const std::string& note) {
  const std::string id = "hotlap-chart-" + std::to_string(chart_count_);
  std::string html = "<figure class=\"" + std::string(css_class) + "\">";
  if (!title.empty()) html += "<figcaption>" + EscapeHtml(title) + "</figcaption>";
  html += "<div class=\"chart-box\"><canvas id=\"" + id + "\" role=\"img\" aria-label=\"" +
          EscapeHtml(title) + "\"></canvas></div>";
  if (std::string(css_class).find("map") != std::string::npos) {
    html += "<div class=\"colour-bar\" id=\"" + id + "-bar\"></div>";
  }
  if (!note.empty()) html += "<p class=\"note\">" + EscapeHtml(note) + "</p>";
  html += "</figure>\n";
  blocks_.push_back({BlockKind::kChart, std::move(html)});
  charts_json_.push_back("{\"id\":" + JsonQuote(id) + "," + chart_json + "}");
  ++chart_count_;
}

void HtmlReport::AddLineChart(const LineChart& chart) {
  CheckRange(chart.x_axis, chart.title, "x");
  CheckRange(chart.y_axis, chart.title, "y");
  std::string series_json;
  size_t longest = 0, shown = 0, next_colour = 0;
  for (const Series& s : chart.series) {
    if (s.x.size() != s.y.size()) {
      throw std::invalid_argument("chart '" + chart.title + "', series '" + s.label +
                                  "': " + std::to_string(s.x.size()) + " x values but " +
                                  std::to_string(s.y.size()) + " y values");
    }
    const std::vector<size_t> keep = MinMaxDecimationIndices(s.y, options_.max_points_per_series);
    longest = std::max(longest, s.y.size());
    shown = std::max(shown, keep.size());
    const bool thinned = keep.size() < s.y.size();
    const int xi = PoolArray(
        JsonNumberArray(thinned ? PickIndices(s.x, keep) : s.x, options_.relative_resolution));
    const int yi = PoolArray(
        JsonNumberArray(thinned ? PickIndices(s.y, keep) : s.y, options_.relative_resolution));
    std::string colour = s.colour;
    if (colour.empty()) {
      colour = s.corner ? CornerColour(*s.corner) : PaletteColour(next_colour++);
    }
    if (!series_json.empty()) series_json += ",";
    series_json += "{\"label\":" + JsonQuote(s.label) + ",\"colour\":" + JsonQuote(colour) +
                   ",\"dash\":" + DashJson(s.style) + ",\"x\":" + std::to_string(xi) +
                   ",\"y\":" + std::to_string(yi) + "}";
  }
  const std::string json = "\"kind\":\"line\",\"link\":" + JsonQuote(chart.x_link) +
                           ",\"x\":" + AxisJson(chart.x_axis) + ",\"y\":" + AxisJson(chart.y_axis) +
                           ",\"series\":[" + series_json + "]";
  AddChartBlock(json, chart.title,
                chart.width == ChartWidth::kFullRow ? "chart line wide" : "chart line",
                DecimationNote(longest, shown));
}

void HtmlReport::AddMapChart(const MapChart& chart) {
  CheckRange(chart.value_axis, chart.title, "value");
  if (chart.x.size() != chart.y.size() || chart.x.size() != chart.value.size()) {
    throw std::invalid_argument(
        "map '" + chart.title + "': x, y and value have " + std::to_string(chart.x.size()) + ", " +
        std::to_string(chart.y.size()) + " and " + std::to_string(chart.value.size()) + " values");
  }
  const std::vector<size_t> keep =
      MinMaxDecimationIndices(chart.value, options_.max_points_per_series);
  const double r = options_.relative_resolution;
  const int xi = PoolArray(JsonNumberArray(PickIndices(chart.x, keep), r));
  const int yi = PoolArray(JsonNumberArray(PickIndices(chart.y, keep), r));
  const int vi = PoolArray(JsonNumberArray(PickIndices(chart.value, keep), r));
  const std::string json =
      "\"kind\":\"map\",\"x\":" + AxisJson(chart.x_axis) + ",\"y\":" + AxisJson(chart.y_axis) +
      ",\"value\":" + AxisJson(chart.value_axis) + ",\"px\":" + std::to_string(xi) +
      ",\"py\":" + std::to_string(yi) + ",\"pv\":" + std::to_string(vi);
  AddChartBlock(json, chart.title, "chart map wide",
                DecimationNote(chart.value.size(), keep.size()));
}

std::string HtmlReport::Render() const {
  std::string page;
  page.reserve(internal::ChartJsSource().size() + 64 * 1024);
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<meta name=\"generator\" content=\"hotlap " HOTLAP_VERSION "\">\n";
  page += "<title>" + EscapeHtml(title_) + "</title>\n<style>\n";
  page += internal::PageStyle();
  page += "</style>\n<script>\n";
  page += internal::ErrorHookScript();
  page += "</script>\n</head>\n<body>\n<header>\n<h1>" + EscapeHtml(title_) + "</h1>\n";
  if (!metadata_.empty()) {
    page += "<dl class=\"meta\">\n";
    for (const auto& [key, value] : metadata_) {
      page += "<div><dt>" + EscapeHtml(key) + "</dt><dd>" + EscapeHtml(value) + "</dd></div>\n";
    }
    page += "</dl>\n";
  }
  page += "</header>\n<main>\n";
  bool in_grid = false;
  for (const Block& block : blocks_) {
    const bool chart = block.kind == BlockKind::kChart;
    if (chart != in_grid) page += chart ? "<div class=\"grid\">\n" : "</div>\n";
    in_grid = chart;
    page += block.html;
  }
  if (in_grid) page += "</div>\n";
  page += "</main>\n<footer>\n<p id=\"hotlap-status\" data-expected=\"" +
          std::to_string(chart_count_) +
          "\" data-rendered=\"0\" data-errors=\"0\">The charts need JavaScript.</p>\n";
  page += "<p>Made by hotlap " HOTLAP_VERSION " with Chart.js ";
  page += EscapeHtml(std::string(internal::ChartJsVersion()));
  page +=
      " (MIT licence), embedded: this file works offline. Hover for values; drag across a chart "
      "to zoom in (linked charts follow), double-click to zoom out.</p>\n</footer>\n<script>\n";
  page += internal::ChartJsSource();
  page += "\n</script>\n<script type=\"application/json\" id=\"hotlap-data\">\n{\"charts\":[";
  for (size_t i = 0; i < charts_json_.size(); ++i) {
    page += (i > 0 ? ",\n" : "\n") + charts_json_[i];
  }
  page += "],\n\"arrays\":[";
  for (size_t i = 0; i < arrays_.size(); ++i) {
    page += (i > 0 ? ",\n" : "\n") + arrays_[i];
  }
  page += "]}\n</script>\n<script>\n";
  page += internal::PageScript();
  page += "</script>\n</body>\n</html>\n";
  return page;
}

void HtmlReport::Write(const std::filesystem::path& path) const {
  const std::string page = Render();
  WriteFileAtomically(path, [&](std::ostream& out) { out << page; });
}

}  // namespace hotlap::report
