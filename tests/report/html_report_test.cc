// HtmlReport: one self-contained file (Chart.js embedded, no external resources), data embedded
// as JSON that parses back, user strings escaped, long series thinned, written atomically.
// Rendering in a browser is checked in html_report_render_test.cc.

#include "hotlap/report/html_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/error.h"
#include "hotlap/report/palette.h"
#include "test_util.h"

namespace hotlap::report {
namespace {

namespace fs = std::filesystem;
using test::Contains;

std::vector<double> Ramp(size_t n, double step) {
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = step * static_cast<double>(i);
  return v;
}

// A chart of the four corners against one time axis, with n samples.
LineChart CornerChart(size_t n) {
  LineChart chart{.title = "Tread temperature",
                  .x_axis = {.label = "time", .unit = "s"},
                  .y_axis = {.label = "tread",
                             .unit = "\xC2\xB0"
                                     "C"},
                  .x_link = "time"};
  const std::vector<double> time = Ramp(n, 0.01);
  for (Corner c : kAllCorners) {
    std::vector<double> y(n);
    for (size_t i = 0; i < n; ++i) y[i] = 80.0 + CornerIndex(c) + 20.0 * std::sin(0.003 * i);
    chart.series.push_back({.label = std::string(CornerName(c)), .x = time, .y = y, .corner = c});
  }
  return chart;
}

// The JSON between <script type="application/json" id="hotlap-data"> and </script>.
nlohmann::json EmbeddedData(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"hotlap-data\">";
  const size_t begin = page.find(open);
  EXPECT_NE(begin, std::string::npos);
  const size_t end = page.find("</script>", begin);
  return nlohmann::json::parse(page.substr(begin + open.size(), end - begin - open.size()));
}

TEST(HtmlReportTest, IsOneSelfContainedFile) {
  HtmlReport page("Replay");
  page.AddLineChart(CornerChart(100));
  const std::string html = page.Render();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_TRUE(Contains(html, "Chart.js v3"));  // the library's banner: embedded, not linked
  EXPECT_TRUE(Contains(html, "<meta charset=\"utf-8\">"));
  for (const char* external : {"src=", "href=", "@import", "url(", "//cdn"}) {
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  }
  EXPECT_TRUE(Contains(html, "id=\"hotlap-status\" data-expected=\"1\""));
}

TEST(HtmlReportTest, EmbedsDataAsJson) {
  HtmlReport page("Replay");
  page.AddLineChart(CornerChart(100));
  LineChart other{.title = "Other",
                  .x_axis = {.label = "x", .min = 0.0, .max = 2.0, .integer_ticks = true}};
  other.series.push_back({.label = "a", .x = {0, 1, 2}, .y = {1, NAN, 3}});
  other.series.push_back(
      {.label = "b", .x = {0, 1, 2}, .y = {3, 2, 1}, .style = LineStyle::kDashed});
  other.series.push_back({.label = "c", .x = {0, 1}, .y = {0, 0}, .colour = "black"});
  page.AddLineChart(other);
  EXPECT_EQ(page.chart_count(), 2);

  const nlohmann::json data = EmbeddedData(page.Render());
  ASSERT_EQ(data["charts"].size(), 2u);
  const nlohmann::json& corners = data["charts"][0];
  EXPECT_EQ(corners["kind"], "line");
  EXPECT_EQ(corners["link"], "time");
  EXPECT_EQ(corners["x"]["title"], "time (s)");
  EXPECT_EQ(corners["y"]["title"],
            "tread (\xC2\xB0"
            "C)");
  EXPECT_TRUE(corners["x"]["min"].is_null());
  EXPECT_EQ(corners["x"]["integer"], false);  // ticks anywhere unless asked for whole numbers
  ASSERT_EQ(corners["series"].size(), 4u);
  for (Corner c : kAllCorners) {
    const nlohmann::json& s = corners["series"][CornerIndex(c)];
    EXPECT_EQ(s["label"], CornerName(c));
    EXPECT_EQ(s["colour"], CornerColour(c));       // the same corner colour in every chart
    EXPECT_EQ(s["x"], corners["series"][0]["x"]);  // one shared time array
  }
  const nlohmann::json& time = data["arrays"][corners["series"][0]["x"].get<int>()];
  ASSERT_EQ(time.size(), 100u);
  EXPECT_DOUBLE_EQ(time[99].get<double>(), 0.99);

  const nlohmann::json& o = data["charts"][1];
  EXPECT_EQ(o["x"]["min"], 0.0);
  EXPECT_EQ(o["x"]["max"], 2.0);
  EXPECT_EQ(o["x"]["integer"], true);
  EXPECT_EQ(o["series"][0]["colour"], PaletteColour(0));
  EXPECT_EQ(o["series"][1]["colour"], PaletteColour(1));
  EXPECT_EQ(o["series"][2]["colour"], "black");
  EXPECT_EQ(o["series"][1]["dash"].size(), 2u);
  EXPECT_TRUE(data["arrays"][o["series"][0]["y"].get<int>()][1].is_null());  // NaN is a gap
}

TEST(HtmlReportTest, EscapesUserStrings) {
  const std::string hostile = "</script><script>alert(\"x\")</script><!-- & 'q'";
  HtmlReport page(hostile);
  page.AddMetadata(hostile, hostile);
  page.AddHeading(hostile);
  page.AddText(hostile);
  page.AddTable({.title = hostile, .header = {hostile}, .rows = {{hostile}}});
  LineChart chart{.title = hostile, .x_axis = {.label = hostile, .unit = hostile}};
  chart.series.push_back({.label = hostile, .x = {0, 1}, .y = {0, 1}, .colour = hostile});
  page.AddLineChart(chart);
  const std::string html = page.Render();
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_EQ(html.find("<!-- &"), std::string::npos);
  EXPECT_TRUE(Contains(html, "<title>&lt;/script&gt;&lt;script&gt;alert(&quot;x&quot;)"));
  // The embedded JSON still parses and gives the strings back unchanged.
  const nlohmann::json data = EmbeddedData(html);
  EXPECT_EQ(data["charts"][0]["series"][0]["label"], hostile);
  EXPECT_EQ(data["charts"][0]["x"]["title"], hostile + " (" + hostile + ")");
}

TEST(HtmlReportTest, TablesAlignNumbersRight) {
  HtmlReport page("t");
  page.AddTable({.title = "Summary",
                 .header = {"corner", "tread pk/mean/end", "wear mm"},
                 .rows = {{"fl", "98.1/85.0/90.2", "0.0123"}, {"rr", "-", "1e-3"}}});
  const std::string html = page.Render();
  EXPECT_TRUE(Contains(html, "<caption>Summary</caption>"));
  EXPECT_TRUE(Contains(html, "<td>fl</td><td class=\"num\">98.1/85.0/90.2</td>"));
  EXPECT_TRUE(Contains(html, "<td>-</td><td class=\"num\">1e-3</td>"));
}

TEST(HtmlReportTest, ThinsLongSeriesAndSaysSo) {
  HtmlReport page("30 laps");
  page.AddLineChart(CornerChart(90001));
  const std::string html = page.Render();
  EXPECT_TRUE(Contains(html, "Thinned for display: 90 001 samples per line drawn as"));
  const nlohmann::json data = EmbeddedData(html);
  for (const nlohmann::json& s : data["charts"][0]["series"]) {
    const nlohmann::json& x = data["arrays"][s["x"].get<int>()];
    const nlohmann::json& y = data["arrays"][s["y"].get<int>()];
    EXPECT_LE(x.size(), 2000u);
    EXPECT_EQ(x.size(), y.size());
    EXPECT_DOUBLE_EQ(x.back().get<double>(), 900.0);  // the last sample is kept
  }
  // 4 x 90 001 samples make a page of Chart.js (~200 kB) plus well under 200 kB of data.
  EXPECT_LT(html.size(), 420'000u);
}

TEST(HtmlReportTest, MapIsThinnedByValue) {
  HtmlReport page("map", {.max_points_per_series = 500});
  MapChart map{.title = "Track", .value_axis = {.label = "speed", .unit = "km/h"}};
  for (int i = 0; i < 20000; ++i) {
    const double a = 2 * M_PI * i / 20000.0;
    map.x.push_back(400 * std::cos(a));
    map.y.push_back(150 * std::sin(a));
    map.value.push_back(250 + 30 * std::cos(2 * a));
  }
  page.AddMapChart(map);
  const std::string html = page.Render();
  EXPECT_TRUE(Contains(html, "class=\"colour-bar\" id=\"hotlap-chart-0-bar\""));
  const nlohmann::json data = EmbeddedData(html);
  const nlohmann::json& chart = data["charts"][0];
  EXPECT_EQ(chart["kind"], "map");
  const nlohmann::json& v = data["arrays"][chart["pv"].get<int>()];
  EXPECT_LE(v.size(), 500u);
  double peak = 0.0;
  for (const nlohmann::json& speed : v) peak = std::max(peak, speed.get<double>());
  EXPECT_NEAR(peak, 280.0, 1e-2);  // the peak speed is kept
}

TEST(HtmlReportTest, RejectsInconsistentInput) {
  HtmlReport page("bad");
  LineChart chart{.title = "c"};
  chart.series.push_back({.label = "s", .x = {0, 1, 2}, .y = {0, 1}});
  EXPECT_THROW(page.AddLineChart(chart), std::invalid_argument);
  EXPECT_THROW(page.AddLineChart({.title = "r", .y_axis = {.min = 2.0, .max = 1.0}}),
               std::invalid_argument);
  EXPECT_THROW(page.AddMapChart({.title = "m", .x = {0}, .y = {0, 1}, .value = {0}}),
               std::invalid_argument);
  EXPECT_THROW(page.AddTable({.header = {"a", "b"}, .rows = {{"1"}}}), std::invalid_argument);
  EXPECT_THROW(HtmlReport("x", {.max_points_per_series = 4}), std::invalid_argument);
  EXPECT_EQ(page.chart_count(), 0);  // nothing half-added
}

TEST(HtmlReportTest, WritesAtomically) {
  const test::TempDir dir;
  HtmlReport page("Replay");
  page.AddLineChart(CornerChart(50));
  const fs::path path = dir.path() / "report.html";
  test::WriteTextFile(path, "old");
  page.Write(path);
  EXPECT_EQ(test::ReadTextFile(path), page.Render());

  // A missing folder: InputError naming it, nothing created.
  try {
    page.Write(dir.path() / "no_such" / "report.html");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "no_such"));
  }
  EXPECT_FALSE(fs::exists(dir.path() / "no_such"));

  // The rename fails (a folder is in the way): the folder is untouched, no temporary is left.
  const fs::path blocked = dir.path() / "blocked.html";
  test::WriteTextFile(blocked / "keep.txt", "x");
  EXPECT_THROW(page.Write(blocked), InputError);
  EXPECT_TRUE(fs::is_directory(blocked));
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  }
  EXPECT_EQ(test::ReadTextFile(path), page.Render());
}

}  // namespace
}  // namespace hotlap::report
