// HTML reports render in a real browser: headless Chromium loads a report with every kind of
// block and chart and the page itself says that all its charts were drawn with no script error
// (#hotlap-status). Needs Debian's chromium (bash scripts/install-deps.sh --test); fails, never
// skips, without it.

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hotlap/report/html_report.h"
#include "report/chromium.h"
#include "test_util.h"

namespace hotlap::report {
namespace {

namespace fs = std::filesystem;

// Everything a report can hold: metadata, headings, text, a table, line charts with corner
// colours, dashes, gaps, fixed ranges and linked x, a long thinned series, an empty chart, a
// track map coloured by speed, and hostile strings everywhere.
HtmlReport EveryKindOfReport() {
  const std::string hostile = "</script><script>throw 1</script> \"q\" 'q' & \xE2\x80\xA8";
  HtmlReport page("Render check " + hostile);
  page.AddMetadata("telemetry", "/tmp/" + hostile + ".csv");
  page.AddHeading("Summary");
  page.AddText("A paragraph " + hostile);
  page.AddTable({.title = hostile, .header = {"corner", "peak"}, .rows = {{"fl", "98.1"}}});
  page.AddHeading("Histories");

  const size_t n = 90001;  // 30 laps at 100 Hz
  std::vector<double> time(n);
  for (size_t i = 0; i < n; ++i) time[i] = 0.01 * i;
  LineChart tread{.title = "Tread " + hostile,
                  .x_axis = {.label = "time", .unit = "s"},
                  .y_axis = {.label = "tread",
                             .unit = "\xC2\xB0"
                                     "C"},
                  .x_link = "time"};
  for (Corner c : kAllCorners) {
    std::vector<double> y(n);
    for (size_t i = 0; i < n; ++i) y[i] = 80 + 5 * CornerIndex(c) + 20 * std::sin(0.002 * i);
    for (size_t i = 40000; i < 40500; ++i) y[i] = NAN;  // a gap in the log
    tread.series.push_back({.label = std::string(CornerName(c)), .x = time, .y = y, .corner = c});
  }
  page.AddLineChart(tread);

  LineChart fixed{.title = "Fixed ranges, dashes",
                  .x_axis = {.label = "time", .unit = "s", .min = 0.0, .max = 900.0},
                  .y_axis = {.label = "grip", .min = 0.8, .max = 1.05},
                  .x_link = "time"};
  fixed.series.push_back({.label = hostile,
                          .x = {0, 300, 600, 900},
                          .y = {1, 0.95, 0.9, 0.92},
                          .style = LineStyle::kDashed});
  fixed.series.push_back(
      {.label = "dotted", .x = {0, 900}, .y = {0.85, 0.85}, .style = LineStyle::kDotted});
  page.AddLineChart(fixed);
  page.AddLineChart({.title = "Empty", .x_axis = {.label = "x"}, .y_axis = {.label = "y"}});
  page.AddLineChart({.title = "Wide",
                     .series = {{.label = "one", .x = {0, 1}, .y = {2, 3}}},
                     .width = ChartWidth::kFullRow});

  MapChart map{.title = "Track map " + hostile,
               .x_axis = {.label = "x", .unit = "m"},
               .y_axis = {.label = "y", .unit = "m"},
               .value_axis = {.label = "speed", .unit = "km/h"}};
  for (int i = 0; i < 30000; ++i) {  // an oval, 800 m by 300 m, slow in the turns
    const double a = 2 * M_PI * i / 3000.0;
    map.x.push_back(400 * std::cos(a));
    map.y.push_back(150 * std::sin(a));
    map.value.push_back(250 + 30 * std::cos(2 * a));
  }
  page.AddMapChart(map);
  return page;
}

TEST(HtmlReportRenderTest, EveryChartRendersWithoutScriptErrors) {
  const test::TempDir dir;
  const HtmlReport page = EveryKindOfReport();
  const fs::path html = dir.path() / "every kind & 'quoted'.html";
  page.Write(html);
  const auto status = test::RenderInChromium(html, dir.path());
  EXPECT_TRUE(test::RenderedCleanly(status, page.chart_count()));
  EXPECT_EQ(page.chart_count(), 5);
}

// The check itself works: a page with a broken script is reported, not passed.
TEST(HtmlReportRenderTest, ScriptErrorsAreReported) {
  const test::TempDir dir;
  HtmlReport page("broken");
  page.AddLineChart({.title = "c", .series = {{.label = "s", .x = {0, 1}, .y = {0, 1}}}});
  const std::string broken =
      test::ReplaceOnce(page.Render(), "</body>", "<script>undefinedFunction();</script></body>");
  const fs::path html = test::WriteTextFile(dir.path() / "broken.html", broken);
  const auto status = test::RenderInChromium(html, dir.path());
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(status->rendered, 1);
  EXPECT_EQ(status->errors, 1) << status->text;
  EXPECT_TRUE(test::Contains(status->text, "undefinedFunction"));
  EXPECT_FALSE(test::RenderedCleanly(status, 1));
}

// The interactive parts: dragging across a chart zooms it and the charts linked to it (and the y
// ranges follow the data in view), double-click zooms out, and the map keeps equal scales. A probe
// script drives the page's drag plugin through Chart.js's event entry point (headless Chromium
// does not run the animation frames Chart.js waits for before it handles real mouse events).
TEST(HtmlReportRenderTest, DragZoomsLinkedChartsAndMapKeepsEqualScales) {
  const test::TempDir dir;
  HtmlReport page("interaction");
  const auto ramp = [](double slope) {
    Series s{.label = "s"};
    for (int i = 0; i <= 1000; ++i) s.x.push_back(i), s.y.push_back(slope * i);
    return s;
  };
  page.AddLineChart({.title = "a", .series = {ramp(1)}, .x_link = "t"});
  page.AddLineChart({.title = "b", .series = {ramp(2)}, .x_link = "t"});
  page.AddLineChart({.title = "c", .series = {ramp(3)}});  // not linked
  MapChart map{.title = "map"};
  for (int i = 0; i < 400; ++i) {
    map.x.push_back(400 * std::cos(i * M_PI / 200));
    map.y.push_back(150 * std::sin(i * M_PI / 200));
    map.value.push_back(i);
  }
  page.AddMapChart(map);
  const std::string probe = R"(<script>
(function () {
  const charts = window.hotlapReport.charts;
  const range = (c) => [c.scales.x.min, c.scales.x.max, c.scales.y.min, c.scales.y.max];
  const send = (c, type, x) => c._eventHandler({type, x, y: (c.chartArea.top + c.chartArea.bottom) / 2, native: {type}});
  const a = charts[0], area = a.chartArea;
  const from = area.left + 0.25 * area.width, to = area.left + 0.5 * area.width;
  const want = [a.scales.x.getValueForPixel(from), a.scales.x.getValueForPixel(to)];
  send(a, 'mousedown', from); send(a, 'mousemove', to); send(a, 'mouseup', to);
  const zoomed = charts.map(range);
  send(a, 'dblclick', from);
  const reset = charts.map(range);
  const m = charts[3], ma = m.chartArea;
  const scales = [(m.scales.x.max - m.scales.x.min) / ma.width, (m.scales.y.max - m.scales.y.min) / ma.height];
  const p = document.createElement('p');
  p.id = 'probe';
  p.textContent = JSON.stringify({want, zoomed, reset, scales});
  document.body.appendChild(p);
})();
</script></body>)";
  const fs::path html = test::WriteTextFile(dir.path() / "interaction.html",
                                            test::ReplaceOnce(page.Render(), "</body>", probe));
  const auto status = test::RenderInChromium(html, dir.path());
  ASSERT_TRUE(test::RenderedCleanly(status, 4));
  const std::string open = "<p id=\"probe\">";
  const size_t begin = status->dom.find(open) + open.size();
  ASSERT_GE(begin, open.size()) << "no probe output";
  const nlohmann::json r =
      nlohmann::json::parse(status->dom.substr(begin, status->dom.find("</p>", begin) - begin));

  const double lo = r["want"][0], hi = r["want"][1];
  EXPECT_NEAR(lo, 250, 30);
  EXPECT_NEAR(hi, 500, 30);
  for (int linked : {0, 1}) {
    EXPECT_DOUBLE_EQ(r["zoomed"][linked][0].get<double>(), lo) << linked;
    EXPECT_DOUBLE_EQ(r["zoomed"][linked][1].get<double>(), hi) << linked;
    // The y axis follows the data in view: y = (1 + linked) x over [lo, hi].
    EXPECT_GE(r["zoomed"][linked][2].get<double>(), 0.9 * (1 + linked) * lo - 1e-9) << linked;
    EXPECT_LE(r["zoomed"][linked][3].get<double>(), 1.1 * (1 + linked) * hi) << linked;
    EXPECT_DOUBLE_EQ(r["reset"][linked][0].get<double>(), 0.0) << linked;
    EXPECT_DOUBLE_EQ(r["reset"][linked][1].get<double>(), 1000.0) << linked;
  }
  EXPECT_DOUBLE_EQ(r["zoomed"][2][0].get<double>(), 0.0);  // the unlinked chart stays
  EXPECT_DOUBLE_EQ(r["zoomed"][2][1].get<double>(), 1000.0);
  const double per_pixel_x = r["scales"][0], per_pixel_y = r["scales"][1];
  EXPECT_NEAR(per_pixel_x / per_pixel_y, 1.0, 0.01);  // a metre is as long across as up
}

}  // namespace
}  // namespace hotlap::report
