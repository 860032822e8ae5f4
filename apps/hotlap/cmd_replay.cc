// `hotlap replay`: run the four tyre and four brake thermal models over a telemetry log.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/telemetry.h"
#include "hotlap/common/units.h"
#include "hotlap/report/html_report.h"
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"

namespace hotlap::app {

namespace {

struct ReplayArgs {
  std::string telemetry;
  std::string out;
  std::string car = "gen7";
  std::string json;
  std::string report;
  bool heat_flows = false;
  double max_step_s = 0.02;
  std::optional<double> tread_C, carcass_C, disc_C, calliper_C, ambient_C, track_C;
};

std::optional<double> ToKelvin(const std::optional<double>& celsius) {
  if (!celsius) return std::nullopt;
  return CelsiusToKelvin(*celsius);
}

nlohmann::json StatsJson(const sim::HistoryStats& s, bool kelvin) {
  const double shift = kelvin ? kZeroCelsius : 0.0;
  return {{"peak", RoundSignificant(s.peak - shift)},
          {"mean", RoundSignificant(s.mean - shift)},
          {"final", RoundSignificant(s.final - shift)}};
}

/// `--report`: the summary table and every history against time, one self-contained HTML file
/// (docs/reports.md).
void WriteReplayReport(const ReplayArgs& a, const vehicle::Car& car,
                       const std::vector<std::pair<std::string, std::string>>& log_metadata,
                       const sim::ReplayResult& result,
                       const std::vector<std::vector<std::string>>& summary_rows) {
  report::HtmlReport page("hotlap replay: " +
                          std::filesystem::path(a.telemetry).filename().string());
  page.AddMetadata("telemetry", a.telemetry);
  page.AddMetadata("car", car.name + " (" + car.path.string() + ")");
  page.AddMetadata("samples", std::to_string(result.time.size()));
  page.AddMetadata("duration", fmt::format("{:.2f} s", result.time.back() - result.time.front()));
  for (const auto& [key, value] : log_metadata) page.AddMetadata("log " + key, value);
  page.AddMetadata("channels", a.out);

  page.AddHeading("Summary");
  page.AddTable({.title = "Per corner: peak / time-weighted mean / final",
                 .header = {"corner", "tread \u00b0C", "carcass \u00b0C", "disc \u00b0C",
                            "calliper \u00b0C", "wear mm", "min grip", "brake energy kJ"},
                 .rows = summary_rows});

  // One chart per quantity, the four corners in their fixed colours, all on one linked time axis.
  const auto chart = [&](const char* title, const char* label, const char* unit,
                         std::vector<double> sim::CornerHistory::*channel, double scale,
                         double shift) {
    report::LineChart c{.title = title,
                        .x_axis = {.label = "time", .unit = "s"},
                        .y_axis = {.label = label, .unit = unit},
                        .x_link = "time"};
    for (Corner corner : kAllCorners) {
      std::vector<double> y = result.corners[CornerIndex(corner)].*channel;
      for (double& v : y) v = v * scale + shift;
      c.series.push_back({.label = std::string(CornerName(corner)),
                          .x = result.time,
                          .y = std::move(y),
                          .corner = corner});
    }
    page.AddLineChart(c);
  };
  page.AddHeading("Tyres");
  chart("Tread temperature", "tread", "\u00b0C", &sim::CornerHistory::tread_temp, 1.0,
        -kZeroCelsius);
  chart("Carcass temperature", "carcass", "\u00b0C", &sim::CornerHistory::carcass_temp, 1.0,
        -kZeroCelsius);
  chart("Wear", "wear", "mm", &sim::CornerHistory::wear, 1.0, 0.0);
  chart("Grip factor", "grip factor", "", &sim::CornerHistory::grip_factor, 1.0, 0.0);
  page.AddHeading("Brakes");
  chart("Disc temperature", "disc", "\u00b0C", &sim::CornerHistory::disc_temp, 1.0, -kZeroCelsius);
  chart("Calliper temperature", "calliper", "\u00b0C", &sim::CornerHistory::calliper_temp, 1.0,
        -kZeroCelsius);
  chart("Braking power", "braking power", "kW", &sim::CornerHistory::brake_power, 1e-3, 0.0);
  page.Write(a.report);
}

int RunReplay(const ReplayArgs& a) {
  CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.report.empty()) CheckOutputFolder(a.report, "--report");
  const auto started = std::chrono::steady_clock::now();

  const vehicle::Car car = vehicle::LoadCar(ResolveCarFile(a.car));
  const Telemetry log = Telemetry::Read(a.telemetry);
  sim::InitialTemperatureOverrides overrides;
  overrides.tread_temp = ToKelvin(a.tread_C);
  overrides.carcass_temp = ToKelvin(a.carcass_C);
  overrides.disc_temp = ToKelvin(a.disc_C);
  overrides.calliper_temp = ToKelvin(a.calliper_C);
  overrides.ambient_temp = ToKelvin(a.ambient_C);
  overrides.track_temp = ToKelvin(a.track_C);
  const sim::ReplayInputs inputs = sim::ReplayInputsFromTelemetry(log, overrides);
  const sim::ReplayInitialState initial = sim::InitialStateFor(log, car, overrides);
  sim::ReplayOptions options;
  options.max_step_s = a.max_step_s;
  options.record_heat_flows = a.heat_flows;
  const sim::ReplayResult result = sim::RunReplay(car, inputs, initial, options);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  // Outputs: the channels CSV, then the JSON summary; both written atomically.
  const sim::ColumnSet columns = sim::ReplayResultColumns(result, a.heat_flows);
  auto metadata = log.metadata();
  metadata.emplace_back("source", fmt::format("hotlap {} replay", HOTLAP_VERSION));
  metadata.emplace_back("telemetry", a.telemetry);
  metadata.emplace_back("car", car.path.string());
  WriteCsv(a.out, metadata, columns.names, columns.values);

  const double duration = result.time.back() - result.time.front();
  fmt::print("hotlap replay: {} ({} samples, {:.2f} s of log) with car '{}'\n", a.telemetry,
             result.time.size(), duration, car.name);
  fmt::print("{:<6} {:>23} {:>23} {:>23} {:>23} {:>8} {:>6}\n", "corner", "tread degC pk/mean/end",
             "carcass degC", "disc degC", "calliper degC", "wear mm", "grip");
  nlohmann::json corners;
  std::vector<std::vector<std::string>> summary_rows;  // the printed table, for --report
  const std::array<sim::CornerReplaySummary, 4> summaries = sim::SummarizeReplay(result);
  for (Corner c : kAllCorners) {
    const sim::CornerReplaySummary& cs = summaries[CornerIndex(c)];
    const auto& [tread, carcass, disc, calliper, wear, min_grip, brake_energy] = cs;
    const auto triple = [](const sim::HistoryStats& s) {
      return fmt::format("{:.1f}/{:.1f}/{:.1f}", KelvinToCelsius(s.peak), KelvinToCelsius(s.mean),
                         KelvinToCelsius(s.final));
    };
    fmt::print("{:<6} {:>23} {:>23} {:>23} {:>23} {:>8.4f} {:>6.3f}\n", CornerName(c),
               triple(tread), triple(carcass), triple(disc), triple(calliper), wear, min_grip);
    summary_rows.push_back({std::string(CornerName(c)), triple(tread), triple(carcass),
                            triple(disc), triple(calliper), fmt::format("{:.4f}", wear),
                            fmt::format("{:.3f}", min_grip),
                            fmt::format("{:.1f}", brake_energy / 1e3)});
    corners[std::string(CornerName(c))] = {
        {"tread_temp_C", StatsJson(tread, true)},
        {"carcass_temp_C", StatsJson(carcass, true)},
        {"disc_temp_C", StatsJson(disc, true)},
        {"calliper_temp_C", StatsJson(calliper, true)},
        {"wear_mm", RoundSignificant(wear)},
        {"min_grip_factor", RoundSignificant(min_grip)},
        {"brake_energy_J", RoundSignificant(brake_energy)},
    };
  }
  fmt::print("wrote {} ({} columns) in {:.3f} s\n", a.out, columns.names.size(), elapsed);
  if (!a.json.empty()) {
    const nlohmann::json summary = {
        {"command", "replay"},
        {"telemetry", a.telemetry},
        {"car", car.name},
        {"out", a.out},
        {"samples", result.time.size()},
        {"duration_s", RoundSignificant(duration)},
        {"corners", corners},
    };
    WriteJsonFile(a.json, summary);
    fmt::print("wrote {}\n", a.json);
  }
  if (!a.report.empty()) {
    WriteReplayReport(a, car, log.metadata(), result, summary_rows);
    fmt::print("wrote {}\n", a.report);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterReplayCommand(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* sub = app.add_subcommand(
      "replay", "Run the tyre and brake thermal and wear models over a telemetry log");
  sub->add_option("--telemetry", args->telemetry, "Input log (CSV, docs/telemetry-csv.md)")
      ->required();
  sub->add_option("--out", args->out, "Output channels CSV")->required();
  sub->add_option("--car", args->car, "Built-in car name or path to a car.yaml")
      ->capture_default_str();
  sub->add_flag("--heat-flows", args->heat_flows, "Also write q1..q7 of every tyre, W");
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/json-output.md)");
  sub->add_option("--report", args->report,
                  "Write an HTML report: summary and interactive charts (docs/reports.md)");
  sub->add_option("--max-step-s", args->max_step_s, "Longest RK4 sub-step, s")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub->add_option("--tread-temp-C", args->tread_C, "Initial tread temperature if not logged");
  sub->add_option("--carcass-temp-C", args->carcass_C, "Initial carcass temperature if not logged");
  sub->add_option("--disc-temp-C", args->disc_C, "Initial disc temperature if not logged");
  sub->add_option("--calliper-temp-C", args->calliper_C,
                  "Initial calliper temperature if not logged");
  sub->add_option("--ambient-temp-C", args->ambient_C, "Air temperature if not logged");
  sub->add_option("--track-temp-C", args->track_C, "Track temperature if not logged");
  return [args] { return RunReplay(*args); };
}

}  // namespace hotlap::app
