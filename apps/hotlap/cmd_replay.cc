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
#include "hotlap/sim/replay.h"
#include "hotlap/sim/replay_io.h"
#include "hotlap/sim/replay_report.h"

namespace hotlap::app {

namespace {

struct ReplayArgs {
  std::string telemetry;
  std::string channel_map;  // --channel-map
  std::optional<int> lap;   // --lap
  std::string out;
  std::string car = "gen7";
  std::vector<std::string> set;  // --set KEY=VALUE
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

int RunReplay(const ReplayArgs& a) {
  CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.report.empty()) CheckOutputFolder(a.report, "--report");
  const auto started = std::chrono::steady_clock::now();

  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  const Telemetry log = Telemetry::Read(a.telemetry, "time", {a.channel_map, a.lap});
  for (const std::string& w : log.warnings()) fmt::print(stderr, "hotlap: warning: {}\n", w);
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
  if (!a.set.empty()) metadata.emplace_back("overrides", vehicle::OverridesText(car.overrides));
  WriteCsv(a.out, metadata, columns.names, columns.values);

  const double duration = result.time.back() - result.time.front();
  fmt::print("hotlap replay: {} ({} samples, {:.2f} s of log) with car '{}'\n", a.telemetry,
             result.time.size(), duration, car.name);
  for (const auto& [key, value] : log.metadata()) {
    if (key == "unmapped channels") fmt::print("MoTeC channels not mapped (kept): {}\n", value);
  }
  fmt::print("{:<6} {:>23} {:>23} {:>23} {:>23} {:>8} {:>6}\n", "corner", "tread degC pk/mean/end",
             "carcass degC", "disc degC", "calliper degC", "wear mm", "grip");
  const std::array<sim::CornerReplaySummary, 4> summaries = sim::SummarizeReplay(result);
  for (Corner c : kAllCorners) {
    const sim::CornerReplaySummary& s = summaries[CornerIndex(c)];
    fmt::print("{:<6} {:>23} {:>23} {:>23} {:>23} {:>8.4f} {:>6.3f}\n", CornerName(c),
               sim::TemperatureStatsText(s.tread), sim::TemperatureStatsText(s.carcass),
               sim::TemperatureStatsText(s.disc), sim::TemperatureStatsText(s.calliper),
               s.final_wear_mm, s.min_grip_factor);
  }
  fmt::print("{}", sim::ReplayHeatText(result, summaries));
  fmt::print("wrote {} ({} columns) in {:.3f} s\n", a.out, columns.names.size(), elapsed);
  if (!a.json.empty()) {
    nlohmann::json json = sim::ReplayJson(result, summaries, a.telemetry, car, a.out);
    json["telemetry_warnings"] = log.warnings();
    WriteJsonFile(a.json, json);
    fmt::print("wrote {}\n", a.json);
  }
  if (!a.report.empty()) {
    sim::WriteReplayReport(a.report, a.telemetry, a.out, car, log.metadata(), result, summaries);
    fmt::print("wrote {}\n", a.report);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterReplayCommand(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* sub = app.add_subcommand(
      "replay", "Run the tyre and brake thermal and wear models over a telemetry log");
  sub->add_option("--telemetry", args->telemetry,
                  "Input log (CSV, MoTeC i2 CSV or MoTeC .ld, docs/telemetry-formats.md)")
      ->required();
  AddTelemetryReadOptions(sub, args->channel_map, args->lap);
  sub->add_option("--out", args->out, "Output channels CSV")->required();
  sub->add_option("--car", args->car, "Built-in car name or path to a car.yaml")
      ->capture_default_str();
  AddSetOption(sub, args->set);
  sub->add_flag("--heat-flows", args->heat_flows, "Also write q1..q7 of every tyre, W");
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/json-output.md)");
  sub->add_option("--report", args->report,
                  "Write an HTML report: summary and interactive charts (docs/reports.md)");
  sub->add_option("--max-step-s", args->max_step_s, "Longest RK4 sub-step, s")
      ->capture_default_str()
      ->check(kPositive);
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
