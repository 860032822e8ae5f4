// `hotlap observe`: the live thermal and wear observer over a log or a stream (docs/observer.md).

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
#include "hotlap/observe/live_server.h"
#include "hotlap/observe/observe_json.h"
#include "hotlap/runs/observe_run.h"
#include "hotlap/runs/observe_text.h"

namespace hotlap::app {

namespace {

struct ObserveArgs {
  std::string json;
  std::string car = "gen7";
  std::vector<std::string> set;   // --set KEY=VALUE
  std::optional<int> serve_port;  // --serve PORT
  double serve_linger_s = 0.0;    // --serve-linger-s
  runs::ObserveRunOptions run;
};

int RunObserve(const ObserveArgs& a) {
  if (a.run.out != "-") CheckOutputFolder(a.run.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  // With the estimates on standard output, everything else goes to standard error.
  std::FILE* text = a.run.out == "-" ? stderr : stdout;
  const vehicle::Car car =
      vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  // The live page: estimates handed to the server's thread as they are written.
  std::unique_ptr<observe::LiveServer> server;
  runs::ObserveHooks hooks;
  hooks.started = [&](const std::vector<std::string>& columns) {
    if (!a.serve_port) return;
    server = std::make_unique<observe::LiveServer>(*a.serve_port, columns);
    fmt::print(stderr, "hotlap observe: live page at http://127.0.0.1:{}/\n", server->port());
    std::fflush(stderr);
  };
  hooks.row = [&](const std::vector<double>& row) {
    if (server) server->Add(row);
  };
  hooks.warning = [](const observe::DisagreementWarning& w) {
    fmt::print(stderr, "hotlap: warning: {}\n", w.message);
  };
  const runs::ObserveRun run = runs::RunObserve(car, a.run, hooks);
  if (server) server->Finish();
  const std::vector<std::string>& reader_warnings = run.summary.telemetry_warnings;
  for (const std::string& w : reader_warnings) fmt::print(stderr, "hotlap: warning: {}\n", w);
  if (run.telemetry_warning_count > static_cast<long>(reader_warnings.size())) {
    fmt::print(stderr, "hotlap: warning: {} more such telemetry warnings\n",
               run.telemetry_warning_count - static_cast<long>(reader_warnings.size()));
  }
  fmt::print(text, "{}", runs::ObserveRunText(run, car));
  if (!a.json.empty()) {
    WriteJsonFile(a.json, observe::ObserveJson(*run.observer, car, run.summary));
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
  sub->add_option("--telemetry", a->run.telemetry,
                  "Input log (CSV, docs/telemetry-csv.md), or - for a stream on standard input "
                  "(header first, then one sample a line)")
      ->required();
  sub->add_option("--out", a->run.out,
                  "Estimates CSV, one line per input line, written and flushed as it goes; - for "
                  "standard output")
      ->required();
  sub->add_option("--car", a->car, "Built-in car name or path to a car.yaml")
      ->capture_default_str();
  AddSetOption(sub, a->set);
  AddTelemetryReadOptions(sub, a->run.channel_map, a->run.lap);
  sub->add_option("--config", a->run.config,
                  "Noise model (YAML, model: observer_noise); default data/observer/default.yaml");
  sub->add_option("--noise-from-fit", a->run.noise_from_fit,
                  "Sensor noise from a fit's residuals (hotlap fit ... --json FIT.json)");
  sub->add_option("--models", a->run.models,
                  "paper (the paper's two-mass tyres and lumped discs, as the fits identify "
                  "them) or car (the car's own gas-and-rim tyres, their rims and TPMS readings, "
                  "and surface-and-bulk discs: gas temperature and hot pressure estimated)")
      ->capture_default_str()
      ->check(CLI::IsMember({"paper", "car"}));
  sub->add_flag("--p5-scale", a->run.p5_scale,
                "Also estimate a slowly drifting factor on p5 (tread-carcass conductance)");
  sub->add_option("--sensor-lag-s", a->run.sensor_lag_s,
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
  sub->add_option("--tread-temp-C", a->run.tread_C, "Initial tread temperature if not logged");
  sub->add_option("--carcass-temp-C", a->run.carcass_C, "Initial carcass temperature");
  sub->add_option("--disc-temp-C", a->run.disc_C, "Initial disc temperature if not logged");
  sub->add_option("--calliper-temp-C", a->run.calliper_C,
                  "Initial calliper temperature if not logged");
  sub->add_option("--ambient-temp-C", a->run.ambient_C, "Air temperature if not logged")
      ->capture_default_str();
  sub->add_option("--track-temp-C", a->run.track_C, "Track temperature if not logged")
      ->capture_default_str();
  return [a] { return RunObserve(*a); };
}

}  // namespace hotlap::app
