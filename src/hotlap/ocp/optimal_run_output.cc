#include "hotlap/ocp/optimal_run_output.h"

#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/optimal_lap_charts.h"
#include "hotlap/ocp/optimal_run_text.h"
#include "hotlap/report/html_report.h"

namespace hotlap::ocp {

namespace fs = std::filesystem;

void WriteSolvedLapCsv(const fs::path& path, const SolvedLap& s, const track::Track& track,
                       const vehicle::Car& car) {
  const sim::ColumnSet columns = OptimalLapColumns(s.run, track);
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"source", fmt::format("hotlap {} optimal lap", HOTLAP_VERSION)},
      {"track", track.name()},
      {"car", car.path.string()}};
  if (!car.overrides.empty()) {
    metadata.emplace_back("overrides", vehicle::OverridesText(car.overrides));
  }
  metadata.emplace_back(
      "front_disc_limit_C",
      s.front_disc_limit ? fmt::format("{:g}", KelvinToCelsius(*s.front_disc_limit)) : "none");
  metadata.emplace_back("status", s.run.solution.solve.message);
  WriteCsv(path, metadata, columns.names, columns.values);
}

namespace {

// The set-up sensitivities ranked by the first lap's typical-step effect: each lap's effect and,
// for the comparison, the limit's cost (LimitCostSensitivities). Nothing without sensitivities.
void AddSensitivityTable(report::HtmlReport& page, const std::vector<SolvedLap>& runs) {
  if (runs.empty() || runs[0].sensitivities.empty()) return;
  const bool comparison = runs.size() == 2 && !runs[1].sensitivities.empty();
  std::vector<std::string> header = {"step", "parameter", "at"};
  for (const SolvedLap& s : runs) header.push_back(s.label + ", ms");
  if (comparison) header.push_back("limit's cost, ms");
  std::vector<std::vector<std::string>> rows;
  for (const LapSensitivity* f : RankedSensitivities(runs[0])) {
    const SetupParameter& p = f->parameter;
    std::vector<std::string> row = {
        p.step_text, p.label, fmt::format("{:.4g}{}", f->value, p.unit == "1" ? "" : " " + p.unit),
        fmt::format("{:+.3f}", 1e3 * f->typical_effect_s())};
    if (runs.size() == 2) {
      const LapSensitivity* l = nullptr;
      for (const LapSensitivity& x : runs[1].sensitivities) {
        if (x.parameter.key == p.key) l = &x;
      }
      row.push_back(l ? fmt::format("{:+.3f}", 1e3 * l->typical_effect_s()) : "-");
      if (comparison) {
        row.push_back(
            l ? fmt::format("{:+.3f}", 1e3 * (l->typical_effect_s() - f->typical_effect_s()))
              : "-");
      }
    }
    rows.push_back(std::move(row));
  }
  page.AddHeading("Set-up sensitivities");
  page.AddText(
      "The lap time's first-order change for a typical step of each parameter a crew chief sets, "
      "from the solved lap's multipliers (no solve again), largest first.");
  page.AddTable({.title = "Set-up sensitivities", .header = header, .rows = rows});
}

}  // namespace

std::vector<fs::path> WriteOptimalRunFiles(const fs::path& out, const std::vector<SolvedLap>& runs,
                                           const vehicle::Car& car, const track::Track& track,
                                           double step_m) {
  fs::create_directories(out);
  std::vector<fs::path> written;
  if (runs.size() == 1) {
    written.push_back(out / "optimal.csv");
    WriteSolvedLapCsv(written.back(), runs[0], track, car);
  } else {
    written.push_back(out / "unconstrained.csv");
    WriteSolvedLapCsv(written.back(), runs[0], track, car);
    written.push_back(out / "constrained.csv");
    WriteSolvedLapCsv(written.back(), runs[1], track, car);
  }
  report::HtmlReport page(fmt::format("hotlap optimal lap: {} on {}", car.name, track.name()));
  page.AddMetadata("car", car.path.string());
  if (!car.overrides.empty()) page.AddMetadata("overrides", vehicle::OverridesText(car.overrides));
  page.AddMetadata("track", fmt::format("{} ({:.1f} m)", track.name(), track.length_m()));
  if (runs[0].run.mesh_rounds.empty()) {
    page.AddMetadata("mesh", fmt::format("{:g} m, trapezoidal collocation, Ipopt", step_m));
  } else {
    std::string nodes;
    for (const SolvedLap& s : runs) {
      nodes += fmt::format("{}{} nodes (estimated error {:+.3f} ms)", nodes.empty() ? "" : ", ",
                           s.run.solution.layout.nodes, 1e3 * s.run.mesh_error.lap_time_error_s);
    }
    page.AddMetadata("mesh", fmt::format("adaptive: {}; trapezoidal collocation, Ipopt", nodes));
  }
  page.AddMetadata("version", HOTLAP_VERSION);
  page.AddHeading("Summary");
  std::vector<std::vector<std::string>> rows;
  for (const SolvedLap& s : runs) {
    rows.push_back({s.label, fmt::format("{:.3f}", s.figures.lap_time_s),
                    fmt::format("{:.2f}", s.figures.top_speed_mps),
                    fmt::format("{:.1f}", s.figures.max_front_disc_temp_C),
                    s.run.solution.solve.message,
                    fmt::format("{} / {:.1f} s", s.run.solution.solve.iterations,
                                s.run.solution.solve.solve_seconds)});
  }
  page.AddTable(
      {.title = "Runs",
       .header = {"run", "lap s", "top m/s", "front disc pk \u00b0C", "Ipopt", "iterations / time"},
       .rows = rows});
  AddSensitivityTable(page, runs);
  std::vector<const OptimalLapRun*> ptrs;
  std::vector<std::string> labels;
  for (const SolvedLap& s : runs) {
    ptrs.push_back(&s.run);
    labels.push_back(s.label);
  }
  AddOptimalLapCharts(page, ptrs, labels, track);
  written.push_back(out / (runs.size() == 2 ? "compare.html" : "optimal.html"));
  page.Write(written.back());
  return written;
}

}  // namespace hotlap::ocp
