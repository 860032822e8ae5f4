#include "hotlap/ident/fit_run_report.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/report/html_report.h"

namespace hotlap::ident {

namespace {

// The run's settings and the log's metadata lines.
void AddRunMetadata(report::HtmlReport& page, const FitRun& run) {
  page.AddMetadata("telemetry", run.telemetry);
  page.AddMetadata("car", run.car_name + " (" + run.car_path + ")");
  page.AddMetadata("fitted car", run.out);
  page.AddMetadata("samples", std::to_string(run.time.size()));
  page.AddMetadata("options", run.options.dump());
  for (const auto& [key, value] : run.log_metadata) page.AddMetadata("log " + key, value);
}

void AddFittedParameters(report::HtmlReport& page, const FitRun& run) {
  // The paper's tables: per corner the values and the RMS errors.
  page.AddHeading("Fitted parameters");
  report::Table summary{.title = "Per corner: fitted values and RMS errors (as 000 Tables 4, 6)"};
  for (const CornerFitOutcome& c : run.result.corners) {
    const auto params = ModelParameters(c);
    if (summary.header.empty() && !params.empty()) {
      summary.header.push_back("corner");
      for (const auto& [p, e] : params) {
        summary.header.push_back(p->label + (p->unit.empty() ? "" : " " + p->unit));
      }
      for (const auto& [key, v] : c.rms) summary.header.push_back(key);
    }
    if (params.size() + c.rms.size() + 1 != summary.header.size()) continue;
    std::vector<std::string> row = {std::string(CornerName(c.corner))};
    for (const auto& [p, e] : params) row.push_back(ShortNumber(e->value + p->display_offset));
    for (const auto& [key, v] : c.rms) row.push_back(ShortNumber(v));
    summary.rows.push_back(row);
  }
  if (!summary.header.empty()) page.AddTable(summary);
}

// One fit's parameters: value, standard error, intervals, verdict, start (and the truth where
// it is known), then the held values.
report::Table ParameterTable(const CornerFitOutcome& c, const ReportedFit& r) {
  report::Table t{.title = fmt::format("{}: {}", CornerName(c.corner), r.title),
                  .header = {"parameter", "unit", "value", "std error", "95% interval",
                             "joint 95% interval", "well determined", "start"}};
  if (!c.truth.empty()) {
    t.header.insert(t.header.end(), {"truth", "truth in 95%", "truth in joint"});
  }
  for (size_t i = 0; i < r.fit.parameters.size(); ++i) {
    const FitParameter& p = r.fit.parameters[i];
    const ParameterEstimate& e = r.fit.estimates[i];
    std::vector<std::string> row = {p.label,
                                    p.unit,
                                    ShortNumber(e.value + p.display_offset),
                                    ShortNumber(e.std_error),
                                    IntervalText(p, e),
                                    JointIntervalText(p, e),
                                    VerdictText(e),
                                    ShortNumber(e.start + p.display_offset)};
    if (!c.truth.empty()) {
      const auto it = c.truth.find(p.key);
      const bool known = it != c.truth.end();
      const double t0 = known ? it->second - p.display_offset : 0.0;
      row.push_back(known ? ShortNumber(it->second) : "");
      row.push_back(known ? (t0 >= e.ci_low && t0 <= e.ci_high ? "yes" : "NO") : "");
      row.push_back(known ? (t0 >= e.joint_low && t0 <= e.joint_high ? "yes" : "NO") : "");
    }
    t.rows.push_back(row);
  }
  for (const auto& [k, v] : r.held) {
    std::vector<std::string> row = {k, "", ShortNumber(v), "held", "", "", "", ""};
    if (!c.truth.empty()) row.insert(row.end(), {"", "", ""});
    t.rows.push_back(row);
  }
  return t;
}

// The correlation matrix of one fit's estimates.
report::Table CorrelationTable(const CornerFitOutcome& c, const ReportedFit& r) {
  report::Table corr{
      .title = fmt::format("{}: {}: correlation of the estimates", CornerName(c.corner), r.title),
      .header = {""}};
  for (const FitParameter& p : r.fit.parameters) corr.header.push_back(p.label);
  for (Eigen::Index i = 0; i < r.fit.correlation.rows(); ++i) {
    std::vector<std::string> row = {r.fit.parameters[i].label};
    for (Eigen::Index k = 0; k < r.fit.correlation.cols(); ++k) {
      const double v = r.fit.correlation(i, k);
      row.push_back(std::isfinite(v) ? fmt::format("{:.2f}", v) : "\u2013");
    }
    corr.rows.push_back(row);
  }
  return corr;
}

void AddUncertainty(report::HtmlReport& page, const FitRun& run) {
  page.AddHeading("Uncertainty");
  page.AddText(
      "95% intervals are value \u00b1 1.96 standard errors (clipped to the bounds); a parameter is "
      "well determined when that half-width is within the fit's max_relative_ci of its value, it "
      "is not at a bound and the data do not leave it undetermined. Each 95% interval alone misses "
      "its truth one time in twenty; the joint intervals hold every parameter of this report at "
      "once with 95% probability (Bonferroni: each is a 1 - 0.05/m interval, m = " +
      std::to_string(run.result.joint_family_size) +
      " parameters). Both are widened where the cost rises more slowly than its quadratic "
      "(docs/fitting.md).");
  for (const CornerFitOutcome& c : run.result.corners) {
    for (const ReportedFit& r : c.fits) {
      page.AddTable(ParameterTable(c, r));
      page.AddTable(CorrelationTable(c, r));
    }
  }
}

void AddWarnings(report::HtmlReport& page, const FitRun& run) {
  page.AddHeading("Warnings");
  bool any = false;
  for (const CornerFitOutcome& c : run.result.corners) {
    for (const std::string& w : CornerWarnings(c)) {
      page.AddText(std::string(CornerName(c.corner)) + ": " + w);
      any = true;
    }
  }
  if (!any) page.AddText("None.");
}

// Measured against modelled, one chart per channel and corner on a shared time axis; the same
// as CSV columns (model, measured, residual) into `names` and `columns`.
void AddChannels(report::HtmlReport& page, const FitRun& run, std::vector<std::string>& names,
                 std::vector<std::vector<double>>& columns) {
  if (!run.result.corners.empty()) {
    page.AddHeading("Measured and modelled");
    // A corner with TPMS channels has two more (inflation pressure, gas temperature).
    size_t most = 0;
    for (const CornerFitOutcome& c : run.result.corners) most = std::max(most, c.channels.size());
    for (size_t q = 0; q < most; ++q) {
      for (const CornerFitOutcome& c : run.result.corners) {
        if (q >= c.channels.size()) continue;
        const ChannelPair& ch = c.channels[q];
        report::LineChart chart{.title = fmt::format("{} {}", CornerName(c.corner), ch.title),
                                .x_axis = {.label = "time", .unit = "s"},
                                .y_axis = {.label = ch.quantity, .unit = ch.unit},
                                .x_link = "time"};
        chart.series.push_back({.label = "measured",
                                .x = run.time,
                                .y = ch.measured,
                                .corner = c.corner,
                                .style = report::LineStyle::kDotted});
        chart.series.push_back(
            {.label = "model", .x = run.time, .y = ch.model, .colour = "#222222"});
        page.AddLineChart(chart);
        const std::string base =
            fmt::format("{}_{}_{}", ch.quantity, CornerName(c.corner), ch.column_unit);
        std::vector<double> residual(ch.model.size());
        for (size_t k = 0; k < residual.size(); ++k) residual[k] = ch.model[k] - ch.measured[k];
        names.insert(names.end(), {base, "measured_" + base, "residual_" + base});
        columns.insert(columns.end(), {ch.model, ch.measured, residual});
      }
    }
  }
}

}  // namespace

std::vector<std::filesystem::path> WriteFitReport(const FitRun& run,
                                                  const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directory(dir, ec);
  if (!std::filesystem::is_directory(dir)) {
    throw InputError(fmt::format("report folder '{}': cannot create it", dir.string()));
  }
  report::HtmlReport page("hotlap " + run.command + ": " +
                          std::filesystem::path(run.telemetry).filename().string());
  AddRunMetadata(page, run);
  AddFittedParameters(page, run);
  AddUncertainty(page, run);
  AddWarnings(page, run);
  std::vector<std::string> names = {"time_s"};
  std::vector<std::vector<double>> columns = {run.time};
  AddChannels(page, run, names, columns);
  const std::filesystem::path html = dir / "index.html", csv = dir / "channels.csv";
  page.Write(html);
  auto metadata = run.log_metadata;
  metadata.emplace_back("source", "hotlap " + run.command + " (measured, modelled, residual)");
  metadata.emplace_back("telemetry", run.telemetry);
  WriteCsv(csv, metadata, names, columns);
  return {html, csv};
}

}  // namespace hotlap::ident
