// `hotlap abs`: one wheel braked by the ABS controller (the FE/ABS paper's case by default), its
// channels as CSV, an HTML report, a JSON summary, and with --scenarios the comparisons.

#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cmd_abs_report.h"
#include "commands.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/sim/abs_config.h"
#include "hotlap/sim/abs_metrics.h"
#include "hotlap/sim/abs_run.h"
#include "hotlap/sim/abs_scenarios.h"

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
  std::string out;
  std::string json;
};

/// The JSON keys of one run's figures (docs/abs.md).
nlohmann::json MetricsJson(const sim::AbsMetrics& m) {
  const sim::AbsEnergy& e = m.energy;
  return {
      {"stopped", m.stopped},
      {"stopping_distance_m", JsonOrNull(m.stopping_distance_m)},
      {"stop_time_s", JsonOrNull(m.stop_time_s)},
      {"distance_m", RoundSignificant(m.distance_m)},
      {"end_time_s", RoundSignificant(m.end_time_s)},
      {"final_speed_mps", RoundSignificant(m.final_speed_mps)},
      {"mean_deceleration_mps2", RoundSignificant(m.mean_deceleration_mps2)},
      {"cycles", m.cycles},
      {"cycles_per_s", RoundSignificant(m.cycles_per_s)},
      {"first_cycle_start_s", JsonOrNull(m.first_cycle_start_s)},
      {"second_cycle_start_s", JsonOrNull(m.second_cycle_start_s)},
      {"abs_exit_s", JsonOrNull(m.abs_exit_s)},
      {"max_lambda_after_first_cycle", JsonOrNull(m.max_lambda_after_first_cycle)},
      {"fraction_time_lambda_below_0_135", JsonOrNull(m.fraction_time_lambda_below_0_135)},
      {"max_lambda", RoundSignificant(m.max_lambda)},
      {"wheel_locked", m.wheel_locked},
      {"peak_disc_temp_C", RoundSignificant(KelvinToCelsius(m.peak_disc_temp_K))},
      {"peak_calliper_temp_C", RoundSignificant(KelvinToCelsius(m.peak_calliper_temp_K))},
      {"final_disc_temp_C", RoundSignificant(KelvinToCelsius(m.final_disc_temp_K))},
      {"energy",
       {{"kinetic_lost_J", RoundSignificant(e.kinetic_lost_J)},
        {"drum_work_J", RoundSignificant(e.drum_work_J)},
        {"brake_J", RoundSignificant(e.brake_J)},
        {"tyre_slip_J", RoundSignificant(e.tyre_slip_J)},
        {"rolling_resistance_J", RoundSignificant(e.rolling_resistance_J)},
        {"closure_error", RoundSignificant(e.closure_error, 3)}}},
  };
}

/// The channels CSV (docs/abs.md lists the columns).
void WriteAbsCsv(const fs::path& path, const sim::AbsConfig& config, const sim::AbsEvent& event,
                 const sim::AbsRunResult& run) {
  const sim::AbsHistory& h = run.history;
  const auto scaled = [](const std::vector<double>& v, double k, double shift = 0.0) {
    std::vector<double> out(v.size());
    for (size_t i = 0; i < v.size(); ++i) out[i] = v[i] * k + shift;
    return out;
  };
  std::vector<double> state(h.size()), locked(h.size());
  for (size_t i = 0; i < h.size(); ++i) {
    state[i] = h.state[i] < 0 ? std::numeric_limits<double>::quiet_NaN() : h.state[i];
    locked[i] = h.locked[i];
  }
  const std::vector<std::string> names = {
      "time_s",         "distance_m",      "driver_pressure_MPa", "pressure_target_MPa",
      "pressure_MPa",   "brake_torque_Nm", "speed_mps",           "wheel_speed_mps",
      "omega_radps",    "lambda",          "slip_ratio",          "fx_N",
      "road_friction",  "abs_state",       "wheel_locked",        "disc_temp_C",
      "calliper_temp_C"};
  const std::vector<std::vector<double>> values = {h.time,
                                                   h.distance,
                                                   scaled(h.driver_pressure, 1e-6),
                                                   scaled(h.pressure_target, 1e-6),
                                                   scaled(h.pressure, 1e-6),
                                                   h.brake_torque,
                                                   h.speed,
                                                   scaled(h.wheel_speed, config.plant.wheel.radius),
                                                   h.wheel_speed,
                                                   h.lambda,
                                                   h.transient_slip,
                                                   h.fx,
                                                   h.friction,
                                                   state,
                                                   locked,
                                                   scaled(h.disc_temp, 1.0, -kZeroCelsius),
                                                   scaled(h.calliper_temp, 1.0, -kZeroCelsius)};
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"source", fmt::format("hotlap {} abs", HOTLAP_VERSION)},
      {"config", config.path.string()},
      {"surface", event.surface},
      {"abs", event.control == sim::AbsControl::kAbs ? "on" : "off"},
      {"abs_state",
       "0 initialise, 1 hold, 2 increase, 3 fast_increase, 4 decrease, "
       "5 step_increase, 6 step_decrease, 7 exit; empty without ABS"}};
  WriteCsv(path, metadata, names, values);
}

std::string Figure(const std::optional<double>& x, const char* format) {
  return x ? fmt::format(fmt::runtime(format), *x) : std::string("-");
}

int RunAbsCommand(const AbsArgs& a) {
  // Everything checked before any work: the output folder, the configuration, the options.
  const fs::path out(a.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (!fs::is_directory(out)) {
    throw InputError(fmt::format("--out: cannot create the folder '{}'", a.out));
  }
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  const sim::AbsConfig config =
      sim::LoadAbsConfig(a.config.empty() ? sim::DefaultAbsConfigPath() : fs::path(a.config));
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

  const fs::path csv = out / "abs.csv", html = out / "abs_report.html";
  WriteAbsCsv(csv, config, event, run);
  const bool with_abs = event.control == sim::AbsControl::kAbs;
  const std::vector<std::pair<std::string, std::string>> summary = {
      {"stopped", m.stopped ? fmt::format("yes, at {:.3f} s after {:.3f} m", *m.stop_time_s,
                                          *m.stopping_distance_m)
                            : fmt::format("no: {:.3f} m/s after {:.3f} m in {:.3f} s",
                                          m.final_speed_mps, m.distance_m, m.end_time_s)},
      {"control cycles", with_abs ? fmt::format("{} ({:.2f} per second)", m.cycles, m.cycles_per_s)
                                  : std::string("no ABS")},
      {"max lambda after the first cycle", Figure(m.max_lambda_after_first_cycle, "{:.4f}")},
      {"time with lambda < 0.135 after the first cycle",
       m.fraction_time_lambda_below_0_135
           ? fmt::format("{:.1f} %", 100.0 * *m.fraction_time_lambda_below_0_135)
           : std::string("-")},
      {"max lambda above the exit speed", fmt::format("{:.4f}", m.max_lambda)},
      {"wheel locked above the exit speed", m.wheel_locked ? "yes" : "no"},
      {"peak disc / calliper temperature",
       fmt::format("{:.1f} / {:.1f} \u00b0C", KelvinToCelsius(m.peak_disc_temp_K),
                   KelvinToCelsius(m.peak_calliper_temp_K))},
      {"energy: kinetic lost + drum work",
       fmt::format("{:.1f} J", m.energy.kinetic_lost_J + m.energy.drum_work_J)},
      {"energy: brake + tyre slip + rolling",
       fmt::format("{:.1f} + {:.1f} + {:.1f} J (closure error {:.2e})", m.energy.brake_J,
                   m.energy.tyre_slip_J, m.energy.rolling_resistance_J, m.energy.closure_error)},
  };
  AbsReportInputs report{.config = &config,
                         .event = &event,
                         .run = &run,
                         .metrics = &m,
                         .summary = summary,
                         .comparison = comparison ? &*comparison : nullptr,
                         .series = series ? &*series : nullptr,
                         .csv = csv.string()};
  WriteAbsReport(report, html);

  fmt::print("hotlap abs: '{}' on '{}' from {:.3f} m/s{}\n", config.name, event.surface,
             event.initial_speed_mps, with_abs ? "" : ", without ABS");
  for (const auto& [k, v] : summary) fmt::print("  {:<48} {}\n", k, v);
  if (comparison) {
    fmt::print("  scenarios (to standstill):   surface   ABS m   locked m   ratio\n");
    for (size_t i = 0; i + 1 < comparison->size(); i += 2) {
      const sim::AbsMetrics& abs = (*comparison)[i].metrics;
      const sim::AbsMetrics& locked = (*comparison)[i + 1].metrics;
      fmt::print("  {:>38} {:>7} {:>10} {:>7}\n", (*comparison)[i].surface,
                 Figure(abs.stopping_distance_m, "{:.2f}"),
                 Figure(locked.stopping_distance_m, "{:.2f}"),
                 abs.stopping_distance_m && locked.stopping_distance_m
                     ? fmt::format("{:.3f}", *abs.stopping_distance_m / *locked.stopping_distance_m)
                     : std::string("-"));
    }
    fmt::print("  stop series: peak disc temperature {:.1f} degC after {} stops\n",
               KelvinToCelsius(series->stops.back().peak_disc_temp_K), series->stops.size());
  }
  fmt::print("wrote {} and {}\n", csv.string(), html.string());

  if (!a.json.empty()) {
    nlohmann::json j = MetricsJson(m);
    j["command"] = "abs";
    j["config"] = config.path.string();
    j["surface"] = event.surface;
    j["abs"] = with_abs;
    j["vehicle"] = event.vehicle == sim::AbsVehicleMode::kFree ? "free" : "drum";
    j["initial_speed_mps"] = RoundSignificant(event.initial_speed_mps);
    j["duration_s"] = RoundSignificant(event.duration_s);
    j["outputs"] = {{"csv", csv.string()}, {"report", html.string()}};
    if (comparison) {
      nlohmann::json runs = nlohmann::json::array();
      for (size_t i = 0; i + 1 < comparison->size(); i += 2) {
        runs.push_back({{"surface", (*comparison)[i].surface},
                        {"abs", MetricsJson((*comparison)[i].metrics)},
                        {"locked", MetricsJson((*comparison)[i + 1].metrics)}});
      }
      nlohmann::json peaks = nlohmann::json::array();
      for (const sim::AbsMetrics& s : series->stops) {
        peaks.push_back(RoundSignificant(KelvinToCelsius(s.peak_disc_temp_K)));
      }
      j["scenarios"] = {{"comparison", runs},
                        {"stop_series",
                         {{"surface", config.scenarios.stop_series_surface},
                          {"stops", series->stops.size()},
                          {"interval_s", config.scenarios.stop_series_interval_s},
                          {"peak_disc_temp_C", peaks}}}};
    }
    WriteJsonFile(a.json, j);
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
  sub->add_option("--speed-mps", args->speed_mps, "Initial speed, m/s (default: the file's)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--duration-s", args->duration_s, "Longest time simulated, s")
      ->check(CLI::PositiveNumber);
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
