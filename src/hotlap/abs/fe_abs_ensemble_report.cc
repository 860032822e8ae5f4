#include "hotlap/abs/fe_abs_ensemble_report.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/report/html_report.h"

namespace hotlap::sim {

namespace {

// The band of one channel: the members' mean, solid, between their smallest and largest value,
// dotted, all in one colour.
void AddBand(report::LineChart& chart, const std::string& label, const std::vector<double>& t,
             const EnsembleBand& b, const std::string& colour) {
  chart.series.push_back({.label = label + " (mean)", .x = t, .y = b.mean, .colour = colour});
  chart.series.push_back({.label = label + " (smallest)",
                          .x = t,
                          .y = b.min,
                          .colour = colour,
                          .style = report::LineStyle::kDotted});
  chart.series.push_back({.label = label + " (largest)",
                          .x = t,
                          .y = b.max,
                          .colour = colour,
                          .style = report::LineStyle::kDotted});
}

std::string Figure(double v) { return fmt::format("{:.4g}", v); }

}  // namespace

std::vector<std::string> FeAbsEnsembleText(const FeAbsEnsembleResult& e) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("abs ensemble: {} members, perturbation {}", e.members.size(),
                              FePerturbationName(e.perturbation)));
  for (size_t k = 0; k < e.keys.size(); ++k) {
    const EnsembleStat& s = e.stats[k];
    lines.push_back(fmt::format("  {}: {} +- {} ({} .. {}, n = {}){}", e.keys[k], Figure(s.mean),
                                Figure(s.standard_error), Figure(s.min), Figure(s.max), s.n,
                                e.units[k].empty() ? "" : " " + e.units[k]));
  }
  return lines;
}

void WriteFeAbsEnsembleCsv(const std::filesystem::path& path, const FeAbsEnsembleResult& e) {
  std::vector<std::string> columns = {"member", "control_cycles"};
  for (const std::string& k : e.keys) columns.push_back(k);
  std::vector<std::vector<double>> v(columns.size());
  for (size_t m = 0; m < e.members.size(); ++m) {
    v[0].push_back(static_cast<double>(e.first_member + m));
    v[1].push_back(e.members[m].cycles);
    const std::vector<FeAbsFigureValue> f = ListFeAbsFigures(e.members[m]);
    for (size_t k = 0; k < f.size(); ++k) {
      v[2 + k].push_back(f[k].value.value_or(std::numeric_limits<double>::quiet_NaN()));
    }
  }
  WriteCsv(path, {{"perturbation", FePerturbationName(e.perturbation)}}, columns, v);
}

void WriteFeAbsEnsembleReport(const std::filesystem::path& path, const FeAbsEnsembleResult& e,
                              const std::vector<LumpedAbsColumn>& lumped,
                              const std::vector<std::pair<std::string, std::string>>& metadata) {
  if (e.time_s.empty()) throw std::invalid_argument("WriteFeAbsEnsembleReport: no history");
  report::HtmlReport page("hotlap fe abs --ensemble: finite-element tyre braking, ensemble");
  for (const auto& [key, value] : metadata) page.AddMetadata(key, value);
  page.AddText(fmt::format(
      "{} braking stops that differ only by the perturbation '{}' (far below any physical "
      "uncertainty). One history of this threshold-controlled stick-slip event depends on "
      "round-off after a few control cycles; the statistics below do not (docs/fe-tyre.md).",
      e.members.size(), FePerturbationName(e.perturbation)));
  const auto opt = [](const std::optional<double>& v) { return v ? Figure(*v) : std::string("-"); };
  // Each lumped run's value of the ensemble's figures, in the order of `e.keys` (slip_p99 and
  // slip_mean have no lumped counterpart in AbsMetrics).
  const auto lumped_values = [](const AbsMetrics& m) {
    return std::vector<std::optional<double>>{m.fraction_time_lambda_below_0_135,
                                              std::nullopt,
                                              std::nullopt,
                                              m.max_lambda_after_first_cycle,
                                              m.cycles_per_s,
                                              m.first_cycle_start_s,
                                              m.distance_m,
                                              m.mean_deceleration_mps2};
  };
  report::Table table{
      .title = "Ensemble figures (window: after the first control cycle)",
      .header = {"figure", "unit", "mean", "standard error", "smallest", "largest", "members"}};
  std::vector<std::vector<std::optional<double>>> columns;
  for (const LumpedAbsColumn& c : lumped) {
    table.header.push_back(c.label);
    columns.push_back(lumped_values(c.metrics));
  }
  for (size_t k = 0; k < e.keys.size(); ++k) {
    const EnsembleStat& s = e.stats[k];
    std::vector<std::string> row = {
        e.keys[k],     e.units[k],    Figure(s.mean),     Figure(s.standard_error),
        Figure(s.min), Figure(s.max), std::to_string(s.n)};
    for (const auto& values : columns) row.push_back(k < values.size() ? opt(values[k]) : "-");
    table.rows.push_back(row);
  }
  page.AddTable(table);

  page.AddHeading("Histories: the members' mean and their smallest and largest value");
  const std::vector<double>& t = e.time_s;
  report::LineChart torque = report::TimeChart("Brake torque (cf. 002 Fig. 8)", "torque", "N m");
  AddBand(torque, "torque", t, e.torque_Nm, "#4e79a7");
  page.AddLineChart(torque);
  report::LineChart speeds =
      report::TimeChart("Forward and circumferential speeds (cf. 002 Fig. 9)", "speed", "m/s");
  AddBand(speeds, "Vx", t, e.vx_mps, "#4e79a7");
  AddBand(speeds, "omega R_l", t, e.omega_r_mps, "#f28e2b");
  page.AddLineChart(speeds);
  report::LineChart slip = report::TimeChart("Slip ratio (cf. 002 Fig. 10)", "slip", "");
  AddBand(slip, "slip", t, e.slip, "#4e79a7");
  slip.series.push_back({.label = "0.135 (002 Fig. 10)",
                         .x = {t.front(), t.back()},
                         .y = {kPaperSlipLimit, kPaperSlipLimit},
                         .colour = "#e15759",
                         .style = report::LineStyle::kDashed});
  page.AddLineChart(slip);
  page.Write(path);
}

}  // namespace hotlap::sim
