// `hotlap fit tyre|contact-length|brake`: thermal, wear, contact-length and brake parameters
// fitted to a telemetry log, with their uncertainty, written as a car (docs/fitting.md). The
// fitting is the library's (ident/car_log_fit.h); this parses, calls it, prints and writes.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/telemetry.h"
#include "hotlap/common/units.h"
#include "hotlap/ident/car_log_fit.h"
#include "hotlap/ident/fit_log.h"
#include "hotlap/ident/fit_run.h"
#include "hotlap/ident/fit_run_json.h"
#include "hotlap/ident/fit_run_report.h"
#include "hotlap/ident/fitted_car.h"
#include "hotlap/sim/synth_params.h"

namespace hotlap::app {

namespace {

namespace fs = std::filesystem;
using ident::CarFitKind;

struct FitArgs {
  std::string channel_map;  // --channel-map
  std::optional<int> lap;   // --lap
  std::string telemetry, car = "gen7", corners = "all", out, report, json, truth;
  std::string loss = "huber", initial_state = "fitted";
  std::string wear_per_lap;  // tyre only
  std::optional<double> ambient_C, track_C;
  int threads = 0;  // 0: one per core
  /// The numeric options, parsed straight into the library's (their defaults are its).
  ident::CarFitOptions options;
};

const char* CommandName(CarFitKind kind) {
  switch (kind) {
    case CarFitKind::kTyre:
      return "fit tyre";
    case CarFitKind::kContactLength:
      return "fit contact-length";
    case CarFitKind::kBrake:
      break;
  }
  return "fit brake";
}

// The paper-style table, the uncertainties and the warnings (warnings to stderr).
void PrintFitRun(const ident::FitRun& run) {
  using ident::ShortNumber;
  fmt::print("hotlap {}: {} ({} samples, {:.2f} s of log) with car '{}'\n", run.command,
             run.telemetry, run.time.size(),
             run.time.empty() ? 0.0 : run.time.back() - run.time.front(), run.car_name);
  for (const ident::CornerFitOutcome& c : run.result.corners) {
    fmt::print("{}:", CornerName(c.corner));
    for (const auto& [key, value] : c.rms) fmt::print("  {} {:.4g}", key, value);
    fmt::print("\n");
    for (const auto& [p, e] : ident::ModelParameters(c)) {
      fmt::print(
          "  {:<12} {:>11} {:<10} std error {:>9}  95% {:<24} joint {:<24} well determined: {}\n",
          p->label, ShortNumber(e->value + p->display_offset), p->unit, ShortNumber(e->std_error),
          ident::IntervalText(*p, *e), ident::JointIntervalText(*p, *e), ident::VerdictText(*e));
    }
    for (const ident::ReportedFit& r : c.fits) {
      for (const auto& [k, v] : r.held) fmt::print("  {:<12} {:>11} (held)\n", k, ShortNumber(v));
    }
    for (const std::string& w : ident::CornerWarnings(c)) {
      std::fprintf(stderr, "hotlap: warning: %s: %s\n", std::string(CornerName(c.corner)).c_str(),
                   w.c_str());
    }
  }
  fmt::print("fitted in {:.2f} s\n", run.elapsed_s);
}

// InputError before any work if an output cannot be written where it was asked for.
void CheckOutputs(const FitArgs& a) {
  CheckOutputFolder(a.out, "--out");
  if (const std::string ext = fs::path(a.out).extension().string();
      ext != ".yaml" && ext != ".yml") {
    throw InputError(fmt::format("--out '{}': the fitted car is a .yaml file", a.out));
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

int RunFit(const FitArgs& a, CarFitKind kind) {
  CheckOutputs(a);
  const auto started = std::chrono::steady_clock::now();

  const vehicle::Car car = vehicle::LoadCar(ResolveCarFile(a.car));
  const Telemetry log = Telemetry::Read(a.telemetry, "time", {a.channel_map, a.lap});
  for (const std::string& w : log.warnings()) fmt::print(stderr, "hotlap: warning: {}\n", w);
  ident::CarFitOptions options = a.options;
  options.kind = kind;
  options.corners = ident::ParseCornerList(a.corners, "--corners");
  if (!a.truth.empty()) {
    options.truth = car;
    sim::ApplyParameterOverrides(sim::LoadParameterOverrides(a.truth), *options.truth);
  }
  options.fit.solver.loss = ident::ParseLossKind(a.loss);
  options.fit.initial_state = ident::ParseInitialStateMode(a.initial_state);
  if (a.ambient_C) options.temperatures.ambient_temp = CelsiusToKelvin(*a.ambient_C);
  if (a.track_C) options.temperatures.track_temp = CelsiusToKelvin(*a.track_C);
  options.wear_per_lap_mm = ident::ParseCornerValues(a.wear_per_lap, "--wear-per-lap-mm");
  options.threads = a.threads > 0
                        ? a.threads
                        : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  options.source_date = ident::TodayIsoDate();
  options.source_log = fs::path(a.telemetry).filename().string();

  ident::FitRun run;
  run.command = CommandName(kind);
  run.telemetry = a.telemetry;
  run.car_name = car.name;
  run.car_path = car.path.string();
  run.out = a.out;
  run.time = log.Channel("time");
  run.log_metadata = log.metadata();
  run.options = {{"loss", a.loss},
                 {"loss_scale", options.fit.solver.loss_scale},
                 {"max_relative_ci", options.fit.solver.max_relative_ci},
                 {"sensor_lag_s", options.fit.sensor_lag_s},
                 {"initial_state", a.initial_state},
                 {"random_starts", options.fit.random_starts},
                 {"seed", options.fit.seed}};
  run.result = ident::FitCarToLog(car, log, options);

  run.result.edits.header = {
      fmt::format("Fitted by hotlap {} {} on {} to {}.", HOTLAP_VERSION, run.command,
                  options.source_date, fs::absolute(a.telemetry).lexically_normal().string()),
      "Fitted values carry their own source comments; all others are as in the file named "
      "below."};
  ident::WriteFittedCar(car, a.out, run.result.edits);
  run.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  PrintFitRun(run);
  fmt::print("wrote {} (and the folder {})\n", a.out,
             (fs::path(a.out).parent_path() / fs::path(a.out).stem()).string());
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
  ident::FitOptions& solver = a.options.fit.solver;
  sub->add_option("--telemetry", a.telemetry,
                  "Logged channels (CSV, MoTeC i2 CSV or MoTeC .ld, docs/telemetry-formats.md)")
      ->required();
  AddTelemetryReadOptions(sub, a.channel_map, a.lap);
  sub->add_option("--car", a.car, "Built-in car name or path to a car.yaml (the starting values)")
      ->capture_default_str();
  sub->add_option("--corners", a.corners, "Corners to fit: all, or a list such as fl,rr")
      ->capture_default_str();
  sub->add_option("--out", a.out, "The fitted car (.yaml; its parts go in a folder beside it)")
      ->required();
  sub->add_option("--report", a.report, "Folder for the HTML report and the channels CSV");
  sub->add_option("--json", a.json, "Write the results as JSON (docs/json-output.md)");
  sub->add_option("--truth", a.truth,
                  "Parameter file with the true values (hotlap synth --params), for the report");
  sub->add_option("--loss", a.loss, "Robust loss: huber, cauchy or none")->capture_default_str();
  sub->add_option("--loss-scale", solver.loss_scale, "Where the loss starts, in noise levels")
      ->capture_default_str()
      ->check(kPositive);
  sub->add_option("--max-relative-ci", solver.max_relative_ci,
                  "Well determined: 95% half-width at most this fraction of the value")
      ->capture_default_str()
      ->check(kPositive);
  sub->add_option("--starts", a.options.fit.random_starts,
                  "Seeded random starting points besides the guesses")
      ->capture_default_str()
      ->check(kNonNegative);
  sub->add_option("--seed", a.options.fit.seed, "Seed of the random starts")->capture_default_str();
  sub->add_option("--threads", a.threads, "Corners fitted at once (0: one per core)")
      ->capture_default_str()
      ->check(kNonNegative);
}

void AddThermalOptions(CLI::App* sub, FitArgs& a) {
  sub->add_option("--sensor-lag-s", a.options.fit.sensor_lag_s,
                  "First-order lag of the temperature sensors, modelled in the fit")
      ->capture_default_str()
      ->check(kNonNegative);
  sub->add_option("--initial-state", a.initial_state,
                  "fitted (initial temperatures fitted too) or measured (first samples)")
      ->capture_default_str();
  sub->add_option("--max-step-s", a.options.fit.max_step_s, "Longest RK4 sub-step, s")
      ->capture_default_str()
      ->check(kPositive);
  sub->add_option("--ambient-temp-C", a.ambient_C, "Air temperature if not logged");
  sub->add_option("--track-temp-C", a.track_C, "Track temperature if not logged");
}

}  // namespace

CommandRunner RegisterFitCommand(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* fit = app.add_subcommand(
      "fit", "Fit thermal, wear, contact-length or brake parameters to a log, with uncertainty");
  fit->require_subcommand(1);
  CLI::App* tyre = fit->add_subcommand(
      "tyre", "Fit p1..p5 to tread and carcass temperatures, then wp1, wp2 to the wear");
  AddCommonOptions(tyre, *args);
  AddThermalOptions(tyre, *args);
  tyre->add_option("--wear-per-lap-mm", args->wear_per_lap,
                   "Measured wear per lap, e.g. fl=0.02,rr=0.033 (else a wear channel is used)");
  tyre->add_option("--wear-sd-mm", args->options.wear_sd_mm,
                   "Standard deviation of a --wear-per-lap-mm value, mm per lap")
      ->capture_default_str()
      ->check(kPositive);
  tyre->add_option("--laps", args->options.laps,
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
