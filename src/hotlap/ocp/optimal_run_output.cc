#include "hotlap/ocp/optimal_run_output.h"

#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/optimal_lap_charts.h"
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
  page.AddMetadata("mesh", fmt::format("{:g} m, trapezoidal collocation, Ipopt", step_m));
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
