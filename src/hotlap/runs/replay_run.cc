#include "hotlap/runs/replay_run.h"

#include <iterator>

#include <fmt/format.h>

#include "hotlap/common/csv.h"
#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/runs/celsius_option.h"

namespace hotlap::runs {

ReplayRun RunReplay(const vehicle::Car& car, const Telemetry& log, const ReplayRunOptions& o,
                    NameStyle style) {
  if (!(o.max_step_s > 0.0)) {
    throw InputError(
        fmt::format("{} {} must be > 0", OptionName(style, "max_step_s"), o.max_step_s));
  }
  sim::InitialTemperatureOverrides overrides;
  overrides.tread_temp = KelvinOf(o.tread_C);
  overrides.carcass_temp = KelvinOf(o.carcass_C);
  overrides.disc_temp = KelvinOf(o.disc_C);
  overrides.calliper_temp = KelvinOf(o.calliper_C);
  overrides.ambient_temp = KelvinOf(o.ambient_C);
  overrides.track_temp = KelvinOf(o.track_C);
  const sim::ReplayInputs inputs = sim::ReplayInputsFromTelemetry(log, overrides);
  const sim::ReplayInitialState initial = sim::InitialStateFor(log, car, overrides);
  sim::ReplayOptions options;
  options.max_step_s = o.max_step_s;
  options.record_heat_flows = o.heat_flows;
  ReplayRun run;
  run.result = sim::RunReplay(car, inputs, initial, options);
  run.summaries = sim::SummarizeReplay(run.result);
  run.columns = sim::ReplayResultColumns(run.result, o.heat_flows);
  return run;
}

void WriteReplayChannels(const std::filesystem::path& path, const ReplayRun& run,
                         const Telemetry& log, const vehicle::Car& car) {
  auto metadata = log.metadata();
  metadata.emplace_back("source", fmt::format("hotlap {} replay", HOTLAP_VERSION));
  metadata.emplace_back("telemetry", log.path().string());
  metadata.emplace_back("car", car.path.string());
  if (!car.overrides.empty()) {
    metadata.emplace_back("overrides", vehicle::OverridesText(car.overrides));
  }
  WriteCsv(path, metadata, run.columns.names, run.columns.values);
}

std::string ReplayRunText(const ReplayRun& run, const Telemetry& log, const vehicle::Car& car) {
  const sim::ReplayResult& result = run.result;
  const double duration = result.time.back() - result.time.front();
  std::string out = fmt::format("hotlap replay: {} ({} samples, {:.2f} s of log) with car '{}'\n",
                                log.path().string(), result.time.size(), duration, car.name);
  auto it = std::back_inserter(out);
  for (const auto& [key, value] : log.metadata()) {
    if (key == "unmapped channels")
      fmt::format_to(it, "MoTeC channels not mapped (kept): {}\n", value);
  }
  fmt::format_to(it, "{:<6} {:>23} {:>23} {:>23} {:>23} {:>8} {:>6}\n", "corner",
                 "tread degC pk/mean/end", "carcass degC", "disc degC", "calliper degC", "wear mm",
                 "grip");
  for (Corner c : kAllCorners) {
    const sim::CornerReplaySummary& s = run.summaries[CornerIndex(c)];
    fmt::format_to(it, "{:<6} {:>23} {:>23} {:>23} {:>23} {:>8.4f} {:>6.3f}\n", CornerName(c),
                   sim::TemperatureStatsText(s.tread), sim::TemperatureStatsText(s.carcass),
                   sim::TemperatureStatsText(s.disc), sim::TemperatureStatsText(s.calliper),
                   s.final_wear_mm, s.min_grip_factor);
  }
  out += sim::ReplayHeatText(result, run.summaries);
  return out;
}

}  // namespace hotlap::runs
