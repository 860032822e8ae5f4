// `hotlap observe`: the live thermal and wear observer over a log or a stream (docs/observer.md).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/log_table.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/observe/car_observer.h"
#include "hotlap/observe/live_server.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/observe/stream_io.h"

namespace hotlap::app {

namespace {

struct ObserveArgs {
  std::string telemetry, out, json, config, noise_from_fit;
  std::string car = "gen7";
  std::vector<std::string> set;  // --set KEY=VALUE
  std::string channel_map;       // --channel-map
  std::optional<int> lap;        // --lap
  bool p5_scale = false;
  std::optional<double> tread_C, carcass_C, disc_C, calliper_C;
  std::optional<double> sensor_lag_s;  // --sensor-lag-s
  std::optional<int> serve_port;       // --serve PORT
  double serve_linger_s = 0.0;         // --serve-linger-s
  double ambient_C = 25.0, track_C = 40.0;
};

std::optional<double> ToKelvin(const std::optional<double>& celsius) {
  if (!celsius) return std::nullopt;
  return CelsiusToKelvin(*celsius);
}

nlohmann::json Num(double x) {
  return std::isfinite(x) ? nlohmann::json(RoundSignificant(x, 6)) : nlohmann::json(nullptr);
}

int RunObserve(const ObserveArgs& a) {
  if (a.out != "-") CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  const auto started = std::chrono::steady_clock::now();
  // With the estimates on standard output, everything else goes to standard error.
  std::FILE* text = a.out == "-" ? stderr : stdout;

  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  observe::ObserverConfig config = observe::LoadObserverConfig(
      a.config.empty() ? observe::DefaultObserverConfigPath() : std::filesystem::path(a.config));
  if (a.p5_scale) config.p5_scale.estimate = true;
  if (!a.noise_from_fit.empty()) observe::ApplyFitResidualNoise(a.noise_from_fit, config);
  observe::ObserverStart start;
  start.tread_temp = ToKelvin(a.tread_C);
  start.carcass_temp = ToKelvin(a.carcass_C);
  start.disc_temp = ToKelvin(a.disc_C);
  start.calliper_temp = ToKelvin(a.calliper_C);

  const bool stream = a.telemetry == "-";
  if (stream && (a.lap || !a.channel_map.empty())) {
    throw InputError(
        "--lap and --channel-map need a log file: a stream on standard input is read a line at a "
        "time as hotlap CSV");
  }
  const observe::StreamDefaults defaults{CelsiusToKelvin(a.ambient_C), CelsiusToKelvin(a.track_C)};
  // A hotlap CSV file or stream is read a line at a time; a MoTeC log, or one lap of any log,
  // is read whole first, as replay and fit read it (docs/telemetry-formats.md). Only a regular
  // file is sniffed for its format: a named pipe is read a line at a time, from its first line.
  const bool whole_log = !stream && (a.lap || !a.channel_map.empty() ||
                                     (std::filesystem::is_regular_file(a.telemetry) &&
                                      LogFormatOf(a.telemetry) != LogFormat::kHotlapCsv));
  std::ifstream file;
  std::istream* in = &std::cin;
  if (!stream && !whole_log) {
    file.open(a.telemetry);
    if (!file) throw InputError(fmt::format("cannot read '{}'", a.telemetry));
    in = &file;
  }
  std::optional<observe::TelemetryLineReader> line_reader;
  std::optional<observe::TelemetryLogReader> log_reader;
  if (whole_log) {
    log_reader.emplace(a.telemetry, TelemetryReadOptions{a.channel_map, a.lap}, defaults);
  } else {
    line_reader.emplace(*in, stream ? "stdin" : a.telemetry, defaults);
  }
  const auto next = [&] { return log_reader ? log_reader->Next() : line_reader->Next(); };
  const auto line = [&] { return log_reader ? log_reader->line() : line_reader->line(); };
  const std::vector<std::string>& reader_warnings =
      log_reader ? log_reader->warnings() : line_reader->warnings();
  const auto warning_count = [&] {
    return log_reader ? log_reader->warning_count() : line_reader->warning_count();
  };
  // The first sample is read before the output is opened, so a log refused at its header or
  // first line leaves no file behind; from then on the estimates are written as they come.
  std::optional<observe::ObserverSample> sample = next();
  if (!sample) {
    throw InputError(fmt::format("{}: no data lines after the header",
                                 a.telemetry == "-" ? "stdin" : a.telemetry));
  }
  const double first_time = sample->time;
  // The sensors' lag: the option, else the log's own `# sensor_lag_s:` line (hotlap synth writes
  // it), else the noise file's (zero without a sensor_lag section).
  std::string lag_from = config.path.string();
  if (a.sensor_lag_s) {
    config.sensor_lag = {*a.sensor_lag_s, *a.sensor_lag_s, *a.sensor_lag_s};
    lag_from = "--sensor-lag-s";
  } else {
    const auto& metadata = log_reader ? log_reader->metadata() : line_reader->metadata();
    for (const auto& [key, value] : metadata) {
      if (key != "sensor_lag_s") continue;
      const std::optional<double> tau = ParseYamlNumber(value);
      if (!tau || !(*tau >= 0.0 && *tau <= 60.0)) {
        throw InputError(fmt::format("{}: '# sensor_lag_s: {}' is not a time constant in [0, 60] s",
                                     a.telemetry == "-" ? "stdin" : a.telemetry, value));
      }
      config.sensor_lag = {*tau, *tau, *tau};
      lag_from = "the log's sensor_lag_s";
    }
  }
  observe::CarObserver observer(car, config, start);
  observe::LineCsvWriter writer(a.out);
  writer.WriteHeader(observe::EstimateColumns(config.p5_scale.estimate));
  // The live page: estimates handed to the server's thread as they are written.
  std::unique_ptr<observe::LiveServer> server;
  if (a.serve_port) {
    server = std::make_unique<observe::LiveServer>(
        *a.serve_port, observe::EstimateColumns(config.p5_scale.estimate));
    fmt::print(stderr, "hotlap observe: live page at http://127.0.0.1:{}/\n", server->port());
    std::fflush(stderr);
  }

  std::vector<observe::DisagreementWarning> warnings;
  for (; sample; sample = next()) {
    std::vector<observe::DisagreementWarning> raised;
    try {
      raised = observer.Step(*sample);
    } catch (const InputError& e) {
      throw InputError(
          fmt::format("{}:{}: {}", a.telemetry == "-" ? "stdin" : a.telemetry, line(), e.what()));
    }
    const std::vector<double> row = observe::EstimateRow(observer);
    writer.WriteRow(row);
    if (server) server->Add(row);
    for (observe::DisagreementWarning& w : raised) {
      fmt::print(stderr, "hotlap: warning: {}\n", w.message);
      warnings.push_back(std::move(w));
    }
  }
  writer.Close();
  if (server) server->Finish();
  for (const std::string& w : reader_warnings) fmt::print(stderr, "hotlap: warning: {}\n", w);
  if (warning_count() > static_cast<long>(reader_warnings.size())) {
    fmt::print(stderr, "hotlap: warning: {} more such telemetry warnings\n",
               warning_count() - static_cast<long>(reader_warnings.size()));
  }
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const double duration = observer.time() - first_time;

  fmt::print(text, "hotlap observe: {} ({} samples, {:.2f} s of log) with car '{}', noise {}\n",
             a.telemetry, observer.samples(), duration, car.name, config.source);
  fmt::print(text, "sensor lag: tread {:g} s, disc {:g} s, calliper {:g} s (from {})\n",
             config.sensor_lag.tread_temp, config.sensor_lag.disc_temp,
             config.sensor_lag.calliper_temp, lag_from);
  fmt::print(text, "{:<6} {:>16} {:>16} {:>20} {:>16} {:>16}\n", "corner", "tread degC",
             "carcass degC", "wear mm", "disc degC", "calliper degC");
  nlohmann::json corners = nlohmann::json::object();
  bool all_consistent = true;
  for (Corner c : kAllCorners) {
    const observe::CornerEstimate e = observer.Estimate(c);
    fmt::print(
        text, "{:<6} {:>16} {:>16} {:>20} {:>16} {:>16}\n", CornerName(c),
        fmt::format("{:.2f} +- {:.2f}", KelvinToCelsius(e.tread_temp), e.tread_temp_sd),
        fmt::format("{:.2f} +- {:.2f}", KelvinToCelsius(e.carcass_temp), e.carcass_temp_sd),
        fmt::format("{:.5f} +- {:.5f}", e.wear, e.wear_sd),
        fmt::format("{:.1f} +- {:.1f}", KelvinToCelsius(e.disc_temp), e.disc_temp_sd),
        fmt::format("{:.1f} +- {:.1f}", KelvinToCelsius(e.calliper_temp), e.calliper_temp_sd));
    nlohmann::json j = {{"tread_temp_C", Num(KelvinToCelsius(e.tread_temp))},
                        {"tread_temp_sd_C", Num(e.tread_temp_sd)},
                        {"carcass_temp_C", Num(KelvinToCelsius(e.carcass_temp))},
                        {"carcass_temp_sd_C", Num(e.carcass_temp_sd)},
                        {"wear_mm", Num(e.wear)},
                        {"wear_sd_mm", Num(e.wear_sd)},
                        {"disc_temp_C", Num(KelvinToCelsius(e.disc_temp))},
                        {"disc_temp_sd_C", Num(e.disc_temp_sd)},
                        {"calliper_temp_C", Num(KelvinToCelsius(e.calliper_temp))},
                        {"calliper_temp_sd_C", Num(e.calliper_temp_sd)}};
    if (config.p5_scale.estimate) {
      j["p5_scale"] = Num(e.p5_scale);
      j["p5_scale_sd"] = Num(e.p5_scale_sd);
    }
    nlohmann::json sensors = nlohmann::json::object();
    for (observe::Sensor s : observe::kAllSensors) {
      const observe::SensorMonitor& m = observer.monitor(c, s);
      if (m.readings == 0) continue;
      const auto [lo, hi] = m.Bounds95();
      all_consistent = all_consistent && m.Consistent();
      sensors[std::string(observe::SensorQuantity(s))] = {
          {"readings", m.readings},
          {"used", m.used},
          {"rejected", m.rejected},
          {"missing", m.missing},
          {"mean_nis", Num(m.MeanNis())},
          {"nis_bounds95", {Num(lo), Num(hi)}},
          {"consistent", m.Consistent()},
          {"disagreements", m.disagreements},
          {"disagree_time_s", Num(m.disagree_time_s)}};
    }
    j["sensors"] = sensors;
    corners[std::string(CornerName(c))] = j;
  }
  fmt::print(text, "{:<6} {:<14} {:>8} {:>8} {:>8} {:>8} {:>9} {:>19} {}\n", "corner", "sensor",
             "readings", "used", "rejected", "missing", "mean NIS", "95% bounds", "");
  for (Corner c : kAllCorners) {
    for (observe::Sensor s : observe::kAllSensors) {
      const observe::SensorMonitor& m = observer.monitor(c, s);
      if (m.readings == 0) continue;
      const auto [lo, hi] = m.Bounds95();
      fmt::print(text, "{:<6} {:<14} {:>8} {:>8} {:>8} {:>8} {:>9.3f} {:>19} {}\n", CornerName(c),
                 observe::SensorQuantity(s), m.readings, m.used, m.rejected, m.missing, m.MeanNis(),
                 fmt::format("[{:.3f}, {:.3f}]", lo, hi),
                 m.Consistent()           ? "consistent"
                 : m.GateRejectsTooMany() ? "INCONSISTENT (too many rejected)"
                                          : "INCONSISTENT");
    }
  }
  fmt::print(text, "{} disagreement warning(s); wrote {} in {:.3f} s ({:.0f} times real time)\n",
             warnings.size(), a.out == "-" ? "standard output" : a.out, elapsed,
             elapsed > 0.0 ? duration / elapsed : 0.0);
  if (!a.json.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const observe::DisagreementWarning& w : warnings) {
      list.push_back({{"corner", std::string(CornerName(w.corner))},
                      {"sensor", std::string(observe::SensorQuantity(w.sensor))},
                      {"since_s", Num(w.since_s)},
                      {"time_s", Num(w.time_s)},
                      {"nis_average", Num(w.nis_average)},
                      {"message", w.message}});
    }
    WriteJsonFile(a.json, {{"command", "observe"},
                           {"telemetry", a.telemetry},
                           {"car", car.name},
                           {"overrides", vehicle::OverridesJson(car.overrides)},
                           {"noise", config.source},
                           {"p5_scale_estimated", config.p5_scale.estimate},
                           {"sensor_lag_s",
                            {{"tread_temp", config.sensor_lag.tread_temp},
                             {"disc_temp", config.sensor_lag.disc_temp},
                             {"calliper_temp", config.sensor_lag.calliper_temp}}},
                           {"sensor_lag_from", lag_from},
                           {"out", a.out},
                           {"samples", observer.samples()},
                           {"duration_s", Num(duration)},
                           {"wall_time_s", Num(elapsed)},
                           {"consistent", all_consistent},
                           {"corners", corners},
                           {"disagreements", list},
                           {"lap", a.lap ? nlohmann::json(*a.lap) : nlohmann::json(nullptr)},
                           {"telemetry_warnings", reader_warnings}});
    fmt::print(text, "wrote {}\n", a.json);
  }
  if (server && a.serve_linger_s > 0.0) {
    fmt::print(stderr, "hotlap observe: serving http://127.0.0.1:{}/ for another {:g} s\n",
               server->port(), a.serve_linger_s);
    std::fflush(stderr);
    server->ServeFor(a.serve_linger_s);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterObserveCommand(CLI::App& app) {
  auto a = std::make_shared<ObserveArgs>();
  CLI::App* sub = app.add_subcommand(
      "observe",
      "Estimate carcass, wear and brake temperatures live from a log or a stream (Kalman filter)");
  sub->add_option("--telemetry", a->telemetry,
                  "Input log (CSV, docs/telemetry-csv.md), or - for a stream on standard input "
                  "(header first, then one sample a line)")
      ->required();
  sub->add_option("--out", a->out,
                  "Estimates CSV, one line per input line, written and flushed as it goes; - for "
                  "standard output")
      ->required();
  sub->add_option("--car", a->car, "Built-in car name or path to a car.yaml")
      ->capture_default_str();
  AddSetOption(sub, a->set);
  AddTelemetryReadOptions(sub, a->channel_map, a->lap);
  sub->add_option("--config", a->config,
                  "Noise model (YAML, model: observer_noise); default data/observer/default.yaml");
  sub->add_option("--noise-from-fit", a->noise_from_fit,
                  "Sensor noise from a fit's residuals (hotlap fit ... --json FIT.json)");
  sub->add_flag("--p5-scale", a->p5_scale,
                "Also estimate a slowly drifting factor on p5 (tread-carcass conductance)");
  sub->add_option("--sensor-lag-s", a->sensor_lag_s,
                  "First-order time constant of every temperature sensor (default: the log's "
                  "'# sensor_lag_s:' line, as hotlap synth writes, else the noise file's "
                  "sensor_lag section, else 0)")
      ->check(CLI::Range(0.0, 60.0));
  sub->add_option("--serve", a->serve_port,
                  "Serve a live page of the estimates and their bands at http://127.0.0.1:PORT/ "
                  "while observing (0: any free port, printed on standard error)")
      ->check(CLI::Range(0, 65535));
  sub->add_option("--serve-linger-s", a->serve_linger_s,
                  "With --serve: keep serving the page this long after the input ends")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 86400.0));
  sub->add_option("--json", a->json, "Write the summary as JSON (docs/json-output.md)");
  sub->add_option("--tread-temp-C", a->tread_C, "Initial tread temperature if not logged");
  sub->add_option("--carcass-temp-C", a->carcass_C, "Initial carcass temperature");
  sub->add_option("--disc-temp-C", a->disc_C, "Initial disc temperature if not logged");
  sub->add_option("--calliper-temp-C", a->calliper_C, "Initial calliper temperature if not logged");
  sub->add_option("--ambient-temp-C", a->ambient_C, "Air temperature if not logged")
      ->capture_default_str();
  sub->add_option("--track-temp-C", a->track_C, "Track temperature if not logged")
      ->capture_default_str();
  return [a] { return RunObserve(*a); };
}

}  // namespace hotlap::app
