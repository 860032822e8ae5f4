// `hotlap abs`: one wheel braked by the ABS controller (the FE/ABS paper's case by default), its
// channels as CSV, an HTML report, a JSON summary, and with --scenarios the comparisons.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/abs/abs_config.h"
#include "hotlap/abs/abs_json.h"
#include "hotlap/abs/abs_metrics.h"
#include "hotlap/abs/abs_output.h"
#include "hotlap/abs/abs_report.h"
#include "hotlap/abs/abs_run.h"
#include "hotlap/abs/abs_scenarios.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;

struct AbsArgs {
  std::string config;
  std::optional<double> speed_mps, duration_s;
  std::optional<std::string> surface;
  bool no_abs = false;
  bool drum = false;
  bool scenarios = false;
  std::vector<std::string> set;  // KEY=VALUE overrides of the ABS file's numbers
  std::string out;
  std::string json;
};

int RunAbsCommand(const AbsArgs& a) {
  // Everything checked before any work: the output folder, the configuration, the options.
  // The folder is created with the outputs, so a refusal leaves nothing behind.
  const fs::path out(a.out);
  CheckOutputDirectory(out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  const sim::AbsConfig config =
      sim::LoadAbsConfig(a.config.empty() ? sim::DefaultAbsConfigPath() : fs::path(a.config),
                         sim::ParseAbsOverrides(a.set));
  sim::AbsEvent event = config.event;
  if (a.speed_mps) event.initial_speed_mps = *a.speed_mps;
  if (a.duration_s) event.duration_s = *a.duration_s;
  if (a.surface) event.surface = *a.surface;
  if (a.no_abs) event.control = sim::AbsControl::kDriverOnly;
  if (a.drum) event.vehicle = sim::AbsVehicleMode::kDrum;
  config.SurfaceNamed(event.surface);  // InputError listing the surfaces if unknown

  const sim::AbsRunResult run = sim::RunAbs(config, event);
  const sim::AbsMetrics m = sim::CalcAbsMetrics(config, run);
  std::optional<std::vector<sim::AbsComparisonRun>> comparison;
  std::optional<sim::AbsStopSeries> series;
  if (a.scenarios) {
    comparison = sim::RunAbsComparison(config, event);
    series = sim::RunAbsStopSeries(config, event);
  }

  CreateOutputDirectory(out, "--out");
  const fs::path csv = out / "abs.csv", html = out / "abs_report.html";
  sim::WriteAbsCsv(csv, config, event, run);
  const bool with_abs = event.control == sim::AbsControl::kAbs;
  const std::vector<std::pair<std::string, std::string>> summary = sim::AbsSummaryRows(m, with_abs);
  sim::AbsReportInputs report{.config = &config,
                              .event = &event,
                              .run = &run,
                              .metrics = &m,
                              .summary = summary,
                              .comparison = comparison ? &*comparison : nullptr,
                              .series = series ? &*series : nullptr,
                              .csv = csv.string()};
  sim::WriteAbsReport(report, html);

  fmt::print("hotlap abs: '{}' on '{}' from {:.3f} m/s{}\n", config.name, event.surface,
             event.initial_speed_mps, with_abs ? "" : ", without ABS");
  for (const auto& [k, v] : summary) fmt::print("  {:<48} {}\n", k, v);
  if (comparison) {
    for (const std::string& line : sim::AbsScenarioLines(*comparison, *series)) {
      fmt::print("  {}\n", line);
    }
  }
  fmt::print("wrote {} and {}\n", csv.string(), html.string());

  if (!a.json.empty()) {
    WriteJsonFile(
        a.json, sim::AbsRunJson(config, event, m, csv.string(), html.string(),
                                comparison ? &*comparison : nullptr, series ? &*series : nullptr));
    fmt::print("wrote {}\n", a.json);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterAbsCommand(CLI::App& app) {
  auto args = std::make_shared<AbsArgs>();
  CLI::App* sub = app.add_subcommand(
      "abs", "Brake one wheel with the ABS controller (the FE/ABS paper's case by default)");
  sub->add_option("--config", args->config,
                  "ABS configuration file (default: the shipped data/abs/paper.yaml)");
  sub->add_option("--set", args->set,
                  "Override a number of the ABS file: KEY=VALUE in the key's own unit, "
                  "repeatable (e.g. controller.reapply_fraction=0.85; docs/abs.md)");
  sub->add_option("--speed-mps", args->speed_mps, "Initial speed, m/s (default: the file's)")
      ->check(kPositive);
  sub->add_option("--duration-s", args->duration_s, "Longest time simulated, s")->check(kPositive);
  sub->add_option("--surface", args->surface, "A friction law or surface of the file");
  sub->add_flag("--no-abs", args->no_abs, "The driver's pressure alone (the wheel may lock)");
  sub->add_flag("--drum", args->drum, "Hold the vehicle speed (drum) instead of a quarter car");
  sub->add_flag("--scenarios", args->scenarios,
                "Also compare ABS and locked stops on every surface, and run a series of stops");
  sub->add_option("--out", args->out, "Output folder: abs.csv and abs_report.html")->required();
  sub->add_option("--json", args->json, "Write the summary as JSON (docs/abs.md)");
  return [args] { return RunAbsCommand(*args); };
}

}  // namespace hotlap::app
