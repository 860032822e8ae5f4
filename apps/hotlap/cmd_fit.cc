// `hotlap fit tyre|contact-length|brake`: thermal, wear, contact-length and brake parameters
// fitted to a telemetry log, with their uncertainty, written as a car (docs/fitting.md). The
// fitting is the library's (ident/car_log_fit.h); this parses, calls it, prints and writes.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/ident/fit_run.h"
#include "hotlap/ident/fit_run_json.h"
#include "hotlap/ident/fit_run_report.h"
#include "hotlap/logs/telemetry.h"
#include "hotlap/runs/fit_run.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;
using ident::CarFitKind;

struct FitArgs {
  std::string channel_map;  // --channel-map
  std::optional<int> lap;   // --lap
  std::string telemetry, car = "gen7", report, json;
  std::string wear_per_lap;  // tyre only: fl=0.02,rr=0.033
  /// The run's options; the numeric ones parsed straight into the library's (their defaults are
  /// its).
  runs::FitRunOptions run;
};

// InputError before any work if an output cannot be written where it was asked for.
void CheckOutputs(const FitArgs& a) {
  CheckOutputFolder(a.run.out, "--out");
  if (const std::string ext = fs::path(a.run.out).extension().string();
      ext != ".yaml" && ext != ".yml") {
    throw InputError(fmt::format("--out '{}': the fitted car is a .yaml file", a.run.out));
  }
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  if (!a.report.empty()) {
    // A folder, created if it is not there; its parent must exist.
    const fs::path dir = fs::path(a.report).lexically_normal();
    const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
    if (!fs::is_directory(parent) || (fs::exists(dir) && !fs::is_directory(dir))) {
      throw InputError(fmt::format(
          "--report '{}': must be a folder (created if missing) inside an existing one", a.report));
    }
  }
}

int RunFit(FitArgs& a, CarFitKind kind) {
  CheckOutputs(a);
  a.run.kind = kind;
  a.run.wear_per_lap_mm = ident::ParseCornerValues(a.wear_per_lap, "--wear-per-lap-mm");
  const vehicle::Car car = vehicle::LoadCar(ResolveCarFile(a.car));
  const Telemetry log = Telemetry::Read(a.telemetry, "time", {a.channel_map, a.lap});
  for (const std::string& w : log.warnings()) fmt::print(stderr, "hotlap: warning: {}\n", w);
  const ident::FitRun run = runs::RunFit(car, log, a.run,
                                         {fmt::format("hotlap {}", HOTLAP_VERSION),
                                          fs::absolute(a.telemetry).lexically_normal().string()},
                                         runs::NameStyle::kCommandLine);
  // The paper-style table and the uncertainties; the warnings to standard error.
  fmt::print("{}", ident::FitRunText(run));
  for (const std::string& w : ident::FitRunWarnings(run)) {
    std::fprintf(stderr, "hotlap: warning: %s\n", w.c_str());
  }
  fmt::print("wrote {} (and the folder {})\n", a.run.out,
             (fs::path(a.run.out).parent_path() / fs::path(a.run.out).stem()).string());
  if (!a.json.empty()) {
    nlohmann::json json = ident::FitRunJson(run);
    json["telemetry_warnings"] = log.warnings();
    WriteJsonFile(a.json, json);
    fmt::print("wrote {}\n", a.json);
  }
  if (!a.report.empty()) {
    for (const fs::path& p : ident::WriteFitReport(run, a.report))
      fmt::print("wrote {}\n", p.string());
  }
  return 0;
}

void AddCommonOptions(CLI::App* sub, FitArgs& a) {
  ident::FitOptions& solver = a.run.numeric.fit.solver;
  sub->add_option("--telemetry", a.telemetry,
                  "Logged channels (CSV, MoTeC i2 CSV or MoTeC .ld, docs/telemetry-formats.md)")
      ->required();
  AddTelemetryReadOptions(sub, a.channel_map, a.lap);
  AddShownOption(sub, "--car", a.car,
                 "Built-in car name or path to a car.yaml (the starting values)");
  AddShownOption(sub, "--corners", a.run.corners, "Corners to fit: all, or a list such as fl,rr");
  sub->add_option("--out", a.run.out, "The fitted car (.yaml; its parts go in a folder beside it)")
      ->required();
  sub->add_option("--report", a.report, "Folder for the HTML report and the channels CSV");
  sub->add_option("--json", a.json, "Write the results as JSON (docs/json-output.md)");
  sub->add_option("--truth", a.run.truth,
                  "Parameter file with the true values (hotlap synth --params), for the report");
  AddShownOption(sub, "--loss", a.run.loss, "Robust loss: huber, cauchy or none");
  AddShownOption(sub, "--loss-scale", solver.loss_scale, "Where the loss starts, in noise levels")
      ->check(kPositive);
  AddShownOption(sub, "--max-relative-ci", solver.max_relative_ci,
                 "Well determined: 95% half-width at most this fraction of the value")
      ->check(kPositive);
  AddShownOption(sub, "--starts", a.run.numeric.fit.random_starts,
                 "Seeded random starting points besides the guesses")
      ->check(kNonNegative);
  AddShownOption(sub, "--seed", a.run.numeric.fit.seed, "Seed of the random starts");
  AddShownOption(sub, "--threads", a.run.threads, "Corners fitted at once (0: one per core)")
      ->check(kNonNegative);
}

void AddThermalOptions(CLI::App* sub, FitArgs& a) {
  AddShownOption(sub, "--sensor-lag-s", a.run.numeric.fit.sensor_lag_s,
                 "First-order lag of the temperature sensors, modelled in the fit")
      ->check(kNonNegative);
  AddShownOption(sub, "--initial-state", a.run.initial_state,
                 "fitted (initial temperatures fitted too) or measured (first samples)");
  AddShownOption(sub, "--max-step-s", a.run.numeric.fit.max_step_s, "Longest RK4 sub-step, s")
      ->check(kPositive);
  sub->add_option("--ambient-temp-C", a.run.ambient_C, "Air temperature if not logged");
  sub->add_option("--track-temp-C", a.run.track_C, "Track temperature if not logged");
}

}  // namespace

CommandRunner RegisterFitCommand(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* fit = app.add_subcommand(
      "fit", "Fit thermal, wear, contact-length or brake parameters to a log, with uncertainty");
  fit->require_subcommand(1);
  CLI::App* tyre = fit->add_subcommand(
      "tyre",
      "Fit p1..p5 to tread and carcass temperatures, then wp1, wp2 to the wear, then the gas "
      "path's conductances to TPMS pressure and gas temperature where logged");
  AddCommonOptions(tyre, *args);
  AddThermalOptions(tyre, *args);
  tyre->add_option("--wear-per-lap-mm", args->wear_per_lap,
                   "Measured wear per lap, e.g. fl=0.02,rr=0.033 (else a wear channel is used)");
  tyre->add_option("--wear-sd-mm", args->run.numeric.wear_sd_mm,
                   "Standard deviation of a --wear-per-lap-mm value, mm per lap")
      ->capture_default_str()
      ->check(kPositive);
  tyre->add_option("--tpms-lag-s", args->run.numeric.fit.tpms_lag_s,
                   "First-order lag of the TPMS pressure and gas temperature, modelled in the "
                   "gas stage")
      ->capture_default_str()
      ->check(kNonNegative);
  tyre->add_option("--laps", args->run.numeric.laps,
                   "Laps in the log, for --wear-per-lap-mm (default: the log's '# laps:', else 1)")
      ->check(kPositive);
  CLI::App* contact = fit->add_subcommand(
      "contact-length", "Fit p_cp1, p_cp2 of the contact length to measured rolling radii");
  AddCommonOptions(contact, *args);
  CLI::App* brake = fit->add_subcommand(
      "brake", "Fit gamma, xi and the convection entries to disc and calliper temperatures");
  AddCommonOptions(brake, *args);
  AddThermalOptions(brake, *args);
  return [args, tyre, contact] {
    const CarFitKind kind = tyre->parsed()      ? CarFitKind::kTyre
                            : contact->parsed() ? CarFitKind::kContactLength
                                                : CarFitKind::kBrake;
    return RunFit(*args, kind);
  };
}

}  // namespace hotlap::app
