// `hotlap replay`: run the four tyre and four brake thermal models over a telemetry log.

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/runs/replay_run.h"
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
  runs::ReplayRunOptions run;
};

int RunReplay(const ReplayArgs& a) {
  CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.report.empty()) CheckOutputFolder(a.report, "--report");
  const auto started = std::chrono::steady_clock::now();
  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  const Telemetry log = Telemetry::Read(a.telemetry, "time", {a.channel_map, a.lap});
  for (const std::string& w : log.warnings()) fmt::print(stderr, "hotlap: warning: {}\n", w);
  const runs::ReplayRun run = runs::RunReplay(car, log, a.run, runs::NameStyle::kCommandLine);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // Outputs: the channels CSV, then the JSON summary; both written atomically.
  runs::WriteReplayChannels(a.out, run, log, car);
  fmt::print("{}", runs::ReplayRunText(run, log, car));
  fmt::print("wrote {} ({} columns) in {:.3f} s\n", a.out, run.columns.names.size(), elapsed);
  if (!a.json.empty()) {
    nlohmann::json json = sim::ReplayJson(run.result, run.summaries, a.telemetry, car, a.out);
    json["telemetry_warnings"] = log.warnings();
    WriteJsonFile(a.json, json);
    fmt::print("wrote {}\n", a.json);
  }
  if (!a.report.empty()) {
    sim::WriteReplayReport(a.report, a.telemetry, a.out, car, log.metadata(), run.result,
                           run.summaries);
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
  sub->add_flag("--heat-flows", args->run.heat_flows, "Also write q1..q7 of every tyre, W");
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/json-output.md)");
  sub->add_option("--report", args->report,
                  "Write an HTML report: summary and interactive charts (docs/reports.md)");
  sub->add_option("--max-step-s", args->run.max_step_s, "Longest RK4 sub-step, s")
      ->capture_default_str()
      ->check(kPositive);
  sub->add_option("--tread-temp-C", args->run.tread_C, "Initial tread temperature if not logged");
  sub->add_option("--carcass-temp-C", args->run.carcass_C,
                  "Initial carcass temperature if not logged");
  sub->add_option("--disc-temp-C", args->run.disc_C, "Initial disc temperature if not logged");
  sub->add_option("--calliper-temp-C", args->run.calliper_C,
                  "Initial calliper temperature if not logged");
  sub->add_option("--ambient-temp-C", args->run.ambient_C, "Air temperature if not logged");
  sub->add_option("--track-temp-C", args->run.track_C, "Track temperature if not logged");
  return [args] { return RunReplay(*args); };
}

}  // namespace hotlap::app
