#pragma once
/// @file
/// Self-contained HTML reports with interactive charts: one .html file that opens offline in any
/// browser, with Chart.js (Debian's libjs-chart.js, embedded in the library at build time), the
/// data as JSON and the page's own script all inside it.
///
/// How to use: make an HtmlReport, add blocks in the order they should appear (metadata lines go
/// under the title; headings, paragraphs, tables and charts go in order, consecutive charts share
/// a grid), then Write():
///
///   report::HtmlReport page("Replay of darlington_example.csv");
///   page.AddMetadata("car", "gen7");
///   page.AddTable({.header = {"corner", "peak tread, degC"}, .rows = {{"fl", "98.1"}}});
///   report::LineChart tread{.title = "Tread temperature",
///                           .x_axis = {.label = "time", .unit = "s"},
///                           .y_axis = {.label = "tread", .unit = "degC"},
///                           .x_link = "time"};
///   for (Corner c : kAllCorners) {
///     tread.series.push_back(
///         {.label = std::string(CornerName(c)), .x = time_s, .y = tread_C[CornerIndex(c)],
///          .corner = c});
///   }
///   page.AddLineChart(tread);
///   page.Write("out/replay.html");  // atomically: temporary file, then rename
///
/// Every field has a default, so designated initializers may leave any of them out (and GCC 12's
/// -Wmissing-field-initializers stays quiet).
///
/// Long series are thinned when they are added (decimate.h: each bucket's lowest and highest
/// value kept, at most ReportOptions::max_points_per_series per line; the chart says so), and
/// numbers are written to 1e-4 of each array's range, so the replay report of a 30-lap 100 Hz log
/// (7 charts of 4 lines of 87 000 samples) is under 800 kB and opens at once. Every string is
/// escaped (web_text.h).
///
/// In the page: hover for values; drag across a line chart to zoom its x range (charts with the
/// same x_link follow), double-click to zoom out. The page reports on itself in the element
/// `#hotlap-status` (data-expected, data-rendered and data-errors attributes: charts expected,
/// charts drawn, script errors seen), which is what the headless-browser tests read.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hotlap/common/corner.h"

namespace hotlap::report {

/// One chart axis. The axis title reads "label (unit)".
struct Axis {
  std::string label{};                 ///< e.g. "time"
  std::string unit{};                  ///< e.g. "s"; empty for none
  std::optional<double> min{}, max{};  ///< fixed range; from the data where empty
  bool integer_ticks = false;          ///< ticks on whole numbers only (laps, counts)
};

enum class LineStyle { kSolid, kDashed, kDotted };

/// One line y(x) of a line chart. `x` and `y` have the same length; `x` increases. Non-finite
/// values are drawn as gaps.
struct Series {
  std::string label{};  ///< legend entry
  std::vector<double> x{}, y{};
  std::optional<Corner> corner{};  ///< the corner's fixed colour (palette.h) if `colour` is empty
  std::string colour{};            ///< CSS colour; empty: the corner's, else the next palette one
  LineStyle style = LineStyle::kSolid;
};

/// How much of the grid's row a chart takes.
enum class ChartWidth { kCell, kFullRow };

/// Several series against one x axis, with a legend.
struct LineChart {
  std::string title{};
  Axis x_axis{}, y_axis{};
  std::vector<Series> series{};
  /// Charts with the same non-empty link zoom their x range together (drag to zoom).
  std::string x_link{};
  ChartWidth width = ChartWidth::kCell;
};

/// An empty chart of `label` (in `unit`) against time in seconds, zooming with the other charts
/// linked on "time".
LineChart TimeChart(const std::string& title, const std::string& label, const std::string& unit);

/// A path y(x) drawn with equal scales on both axes (a track map), coloured by `value` along
/// the way (viridis, low dark blue to high yellow), with a colour bar. x, y and value have the
/// same length. value_axis.min/max fix the colour scale; x_axis/y_axis ranges are ignored (the
/// map always shows the whole path at equal scale). Always takes a full grid row.
struct MapChart {
  std::string title{};
  Axis x_axis{}, y_axis{}, value_axis{};
  std::vector<double> x{}, y{}, value{};
};

/// A table of text cells. Every row has as many cells as `header`; cells that read as numbers
/// are right-aligned.
struct Table {
  std::string title{};  ///< caption; may be empty
  std::vector<std::string> header{};
  std::vector<std::vector<std::string>> rows{};
};

struct ReportOptions {
  /// Most points drawn per line-chart series or map (decimate.h); at least 5.
  size_t max_points_per_series = 2000;
  /// Numbers are written to this fraction of each array's range.
  double relative_resolution = 1e-4;
};

class HtmlReport {
 public:
  explicit HtmlReport(std::string title, ReportOptions options = {});

  /// A "key: value" line under the title (the input file, the car, the program version, ...).
  void AddMetadata(std::string key, std::string value);
  /// A section heading; the charts after it start a new grid.
  void AddHeading(const std::string& text);
  /// A paragraph of plain text.
  void AddText(const std::string& text);
  /// Throws std::invalid_argument if a row's width differs from the header's.
  void AddTable(const Table& table);
  /// Decimates and formats the data now. Throws std::invalid_argument if a series' x and y
  /// differ in length or an axis has min >= max.
  void AddLineChart(const LineChart& chart);
  /// Decimates (by `value`) and formats the data now. Throws std::invalid_argument if x, y and
  /// value differ in length or the value axis has min >= max.
  void AddMapChart(const MapChart& chart);

  /// Charts added so far: what the page's status element expects to see drawn.
  int chart_count() const { return chart_count_; }

  /// The whole page.
  std::string Render() const;

  /// Writes Render() to `path` atomically (atomic_file.h): on any failure `path` is left as it
  /// was, no temporary is left behind, and InputError names the path.
  void Write(const std::filesystem::path& path) const;

 private:
  enum class BlockKind { kHtml, kChart };
  struct Block {
    BlockKind kind;
    std::string html;
  };
  /// Index of `json_array` in the pool of data arrays, adding it if it is new (identical arrays,
  /// e.g. the time axis of every series, are stored once).
  int PoolArray(std::string json_array);
  /// The decimation note under a chart; empty if nothing was thinned.
  std::string DecimationNote(size_t longest, size_t shown) const;
  void AddChartBlock(const std::string& chart_json, const std::string& title, const char* css_class,
                     const std::string& note);

  std::string title_;
  ReportOptions options_;
  std::vector<std::pair<std::string, std::string>> metadata_;
  std::vector<Block> blocks_;
  std::vector<std::string> charts_json_;
  std::vector<std::string> arrays_;
  std::unordered_map<std::string, int> array_index_;
  int chart_count_ = 0;
};

}  // namespace hotlap::report
