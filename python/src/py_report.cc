// hotlap._write_report: the library's self-contained HTML report (Chart.js inside, as every
// `--report` page) from Python, for pages the package makes itself (the sweep's report.html).

#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "hotlap/report/html_report.h"
#include "py_convert.h"

namespace hotlap::python {

namespace {

// charts: [{"title", "x_label", "x_unit", "y_label", "y_unit",
//           "series": [{"label", "x": array, "y": array}]}]
// tables: [{"title", "header": [str], "rows": [[str]]}]; texts and headings go before them.
void WriteReport(const std::string& path, const std::string& title,
                 const std::vector<std::pair<std::string, std::string>>& metadata,
                 const std::vector<std::string>& texts, const py::list& tables,
                 const py::list& charts) {
  report::HtmlReport page(title);
  for (const auto& [key, value] : metadata) page.AddMetadata(key, value);
  for (const std::string& text : texts) page.AddText(text);
  for (const py::handle& t : tables) {
    const py::dict d = t.cast<py::dict>();
    page.AddTable({.title = d["title"].cast<std::string>(),
                   .header = d["header"].cast<std::vector<std::string>>(),
                   .rows = d["rows"].cast<std::vector<std::vector<std::string>>>()});
  }
  for (const py::handle& c : charts) {
    const py::dict d = c.cast<py::dict>();
    report::LineChart chart{.title = d["title"].cast<std::string>(),
                            .x_axis = {.label = d["x_label"].cast<std::string>(),
                                       .unit = d["x_unit"].cast<std::string>()},
                            .y_axis = {.label = d["y_label"].cast<std::string>(),
                                       .unit = d["y_unit"].cast<std::string>()}};
    for (const py::handle& s : d["series"].cast<py::list>()) {
      const py::dict sd = s.cast<py::dict>();
      chart.series.push_back({.label = sd["label"].cast<std::string>(),
                              .x = ToVector(sd["x"], "series x"),
                              .y = ToVector(sd["y"], "series y")});
    }
    page.AddLineChart(chart);
  }
  page.Write(path);
}

}  // namespace

void BindReport(py::module_& m) {
  m.def("_write_report", &WriteReport, py::arg("path"), py::arg("title"), py::arg("metadata"),
        py::arg("texts"), py::arg("tables"), py::arg("charts"),
        "Writes a self-contained HTML report (the library's page, Chart.js inside) atomically.");
}

}  // namespace hotlap::python
