#include "hotlap/runs/observe_run.h"

#include <chrono>
#include <filesystem>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/observe/sample_source.h"
#include "hotlap/observe/stream_io.h"
#include "hotlap/runs/celsius_option.h"

namespace hotlap::runs {

namespace {

observe::ObservedModels ModelsOf(const std::string& models) {
  if (models == "paper") return observe::ObservedModels::kPaper;
  if (models == "car") return observe::ObservedModels::kCar;
  throw InputError(fmt::format("models '{}': 'paper' or 'car'", models));
}

// Steps the observer through every sample from `first` on, writing each estimate row.
void ObserveAll(observe::CarObserver& observer, observe::SampleSource& source,
                std::optional<observe::ObserverSample> sample, observe::LineCsvWriter& writer,
                const ObserveHooks& hooks, std::vector<observe::DisagreementWarning>& warnings) {
  for (; sample; sample = source.Next()) {
    std::vector<observe::DisagreementWarning> raised;
    try {
      raised = observer.Step(*sample);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}:{}: {}", source.name(), source.line(), e.what()));
    }
    const std::vector<double> row = observe::EstimateRow(observer);
    writer.WriteRow(row);
    if (hooks.row) hooks.row(row);
    for (observe::DisagreementWarning& w : raised) {
      if (hooks.warning) hooks.warning(w);
      warnings.push_back(std::move(w));
    }
  }
}

}  // namespace

observe::ObserverConfig LoadObserveConfig(const ObserveRunOptions& o) {
  observe::ObserverConfig config = observe::LoadObserverConfig(
      o.config.empty() ? observe::DefaultObserverConfigPath() : std::filesystem::path(o.config));
  if (o.p5_scale) config.p5_scale.estimate = true;
  if (!o.noise_from_fit.empty()) observe::ApplyFitResidualNoise(o.noise_from_fit, config);
  return config;
}

std::string ResolveSensorLag(const std::optional<double>& option,
                             const std::vector<std::pair<std::string, std::string>>& metadata,
                             const std::string& source, observe::ObserverConfig& config) {
  if (option) {
    config.sensor_lag = {*option, *option, *option};
    return "--sensor-lag-s";
  }
  std::string from = config.path.string();
  for (const auto& [key, value] : metadata) {
    if (key != "sensor_lag_s") continue;
    const std::optional<double> tau = ParseYamlNumber(value);
    if (!tau || !(*tau >= 0.0 && *tau <= 60.0)) {
      throw InputError(fmt::format("{}: '# sensor_lag_s: {}' is not a time constant in [0, 60] s",
                                   source, value));
    }
    config.sensor_lag = {*tau, *tau, *tau};
    from = "the log's sensor_lag_s";
  }
  return from;
}

std::string ResolveTpmsLag(const std::vector<std::pair<std::string, std::string>>& metadata,
                           const std::string& source, observe::ObserverConfig& config) {
  if (!config.car_models) return "";
  std::string from = config.path.string();
  for (const auto& [key, value] : metadata) {
    if (key != "tpms") continue;
    // hotlap synth's line: "pressure noise 2 kPa, gas temperature noise 0.5 C, lag 2 s".
    const size_t at = value.rfind("lag ");
    const size_t end = value.size() >= 2 && value.ends_with(" s") ? value.size() - 2 : 0;
    const std::optional<double> tau = at == std::string::npos || end <= at + 4
                                          ? std::nullopt
                                          : ParseYamlNumber(value.substr(at + 4, end - at - 4));
    if (!tau || !(*tau > 0.0 && *tau <= 60.0)) {
      throw InputError(fmt::format(
          "{}: '# tpms: {}' does not end in 'lag <s> s' with a time constant in (0, 60] s", source,
          value));
    }
    config.car_models->tpms_lag_s = *tau;
    from = "the log's tpms line";
  }
  return from;
}

ObserveRun RunObserve(const vehicle::Car& car, const ObserveRunOptions& o,
                      const ObserveHooks& hooks) {
  const auto started = std::chrono::steady_clock::now();
  observe::ObserverConfig config = LoadObserveConfig(o);
  const observe::ObserverStart start{.tread_temp = KelvinOf(o.tread_C),
                                     .carcass_temp = KelvinOf(o.carcass_C),
                                     .disc_temp = KelvinOf(o.disc_C),
                                     .calliper_temp = KelvinOf(o.calliper_C)};
  observe::SampleSource source(o.telemetry, TelemetryReadOptions{o.channel_map, o.lap},
                               {CelsiusToKelvin(o.ambient_C), CelsiusToKelvin(o.track_C)});
  // The first sample is read before the output is opened, so a log refused at its header or
  // first line leaves no file behind; from then on the estimates are written as they come.
  std::optional<observe::ObserverSample> first = source.Next();
  if (!first) throw InputError(fmt::format("{}: no data lines after the header", source.name()));
  const double first_time = first->time;
  ObserveRun run;
  run.summary.sensor_lag_from =
      ResolveSensorLag(o.sensor_lag_s, source.metadata(), source.name(), config);
  run.summary.tpms_lag_from = ResolveTpmsLag(source.metadata(), source.name(), config);
  run.observer = std::make_unique<observe::CarObserver>(car, config, start, ModelsOf(o.models));
  observe::LineCsvWriter writer(o.out);
  const std::vector<std::string> columns = observe::EstimateColumns(*run.observer);
  writer.WriteHeader(columns);
  if (hooks.started) hooks.started(columns);
  ObserveAll(*run.observer, source, std::move(first), writer, hooks, run.summary.warnings);
  writer.Close();

  observe::ObserveSummary& s = run.summary;
  s.telemetry = o.telemetry;
  s.out = o.out;
  s.lap = o.lap;
  s.duration_s = run.observer->time() - first_time;
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  s.telemetry_warnings = source.warnings();
  run.telemetry_warning_count = source.warning_count();
  return run;
}

}  // namespace hotlap::runs
