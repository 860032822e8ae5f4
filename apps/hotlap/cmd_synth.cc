// `hotlap synth`: a synthetic "measured" log from the lap simulation with chosen true parameters,
// sensor lag and noise (docs/fitting.md).

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/common/units.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/sim/road.h"
#include "hotlap/sim/synth.h"
#include "hotlap/sim/synth_json.h"
#include "hotlap/sim/synth_params.h"
#include "hotlap/track/track_io.h"

namespace hotlap::app {

namespace {

struct SynthArgs {
  std::string car = "gen7", params, track = "darlington", out, json;
  std::string process_noise;     // --process-noise NOISE.yaml|default
  std::vector<std::string> set;  // --set KEY=VALUE
  int laps = 1;
  double rate_hz = 50.0, noise_C = 0.5, lag_s = 0.2, wear_noise_mm = 1e-4, radius_noise_mm = 0.1;
  double ambient_C = 25.0, track_C = 40.0, step_m = 1.0;
  uint64_t seed = 1;
};

int RunSynth(const SynthArgs& a) {
  CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  vehicle::Car car = vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  std::string params_name = "the car's";
  if (!a.params.empty()) {
    const sim::ParameterOverrides overrides = sim::LoadParameterOverrides(a.params);
    sim::ApplyParameterOverrides(overrides, car);
    params_name = overrides.name;
  }
  const track::Track track = track::LoadTrack(a.track);
  const std::vector<sim::RoadPoint> road = sim::SampleRoad(track, a.step_m);

  sim::SynthOptions o;
  o.laps = a.laps;
  o.rate_hz = a.rate_hz;
  o.temp_noise_K = a.noise_C;
  o.sensor_lag_s = a.lag_s;
  o.wear_noise_mm = a.wear_noise_mm;
  o.radius_noise_m = 1e-3 * a.radius_noise_mm;
  o.seed = a.seed;
  o.ambient_temp = CelsiusToKelvin(a.ambient_C);
  o.track_temp = CelsiusToKelvin(a.track_C);
  std::string process_noise_file;
  if (!a.process_noise.empty()) {
    // The observer's noise file: its process_noise section is the random walk the truth gets.
    process_noise_file = a.process_noise == "default"
                             ? observe::DefaultObserverConfigPath().string()
                             : a.process_noise;
    const observe::ProcessNoise q = observe::LoadObserverConfig(process_noise_file).process;
    o.process_noise =
        sim::SynthProcessNoise{q.tread_temp, q.carcass_temp, q.wear, q.disc_temp, q.calliper_temp};
  }
  const sim::SynthLog log = sim::SynthesizeLog(car, road, o);
  sim::WriteSynthLog(a.out, log,
                     {{"track", track.name()},
                      {"params", a.params.empty() ? std::string("(car file)") : a.params}});

  const std::vector<double>& time = log.inputs.time;
  fmt::print("hotlap synth: car '{}' with {} parameters, {} lap(s) of {} ({:.3f} s per lap)\n",
             car.name, params_name, a.laps, track.name(), log.lap_time_s);
  fmt::print("{} samples at {:g} Hz; sensors: lag {:g} s, noise {:g} degC; seed {}\n", time.size(),
             a.rate_hz, a.lag_s, a.noise_C, a.seed);
  if (o.process_noise) {
    const sim::SynthProcessNoise& q = *o.process_noise;
    fmt::print(
        "truth with process noise from {}: random walk of tread {:.3g}, carcass {:.3g}, disc "
        "{:.3g}, calliper {:.3g} degC per sqrt(s), wear {:.3g} mm per sqrt(s)\n",
        process_noise_file, std::sqrt(q.tread_temp_K2_per_s), std::sqrt(q.carcass_temp_K2_per_s),
        std::sqrt(q.disc_temp_K2_per_s), std::sqrt(q.calliper_temp_K2_per_s),
        std::sqrt(q.wear_mm2_per_s));
  }
  const std::array<sim::SynthCornerSummary, 4> corners = sim::SummarizeSynthCorners(log);
  for (Corner c : kAllCorners) {
    const sim::SynthCornerSummary& s = corners[CornerIndex(c)];
    fmt::print("{}: peak tread {:.1f} degC, peak disc {:.1f} degC, wear {:.5f} mm\n", CornerName(c),
               KelvinToCelsius(s.peak_tread_temp_K), KelvinToCelsius(s.peak_disc_temp_K),
               s.wear_mm);
  }
  fmt::print("wrote {}\n", a.out);
  if (!a.json.empty()) {
    const nlohmann::json summary =
        sim::SynthJson(log, o, car, {track.name(), a.params, a.out, process_noise_file});
    WriteJsonFile(a.json, summary);
    fmt::print("wrote {}\n", a.json);
  }
  return 0;
}

}  // namespace

CommandRunner RegisterSynthCommand(CLI::App& app) {
  auto a = std::make_shared<SynthArgs>();
  CLI::App* sub = app.add_subcommand(
      "synth", "Make a synthetic measured log: lap simulation, true parameters, sensor lag, noise");
  sub->add_option("--car", a->car, "Built-in car name or path to a car.yaml")
      ->capture_default_str();
  AddSetOption(sub, a->set);
  sub->add_option("--params", a->params,
                  "Parameter file with the true values (model: parameter_overrides)");
  sub->add_option("--track", a->track, "Built-in track name or track file")->capture_default_str();
  sub->add_option("--laps", a->laps, "Laps to simulate")->capture_default_str()->check(kPositive);
  sub->add_option("--rate-hz", a->rate_hz, "Logging rate")->capture_default_str()->check(kPositive);
  sub->add_option("--noise-C", a->noise_C, "Standard deviation of every temperature sensor, degC")
      ->capture_default_str()
      ->check(kNonNegative);
  sub->add_option("--lag-s", a->lag_s, "First-order time constant of every temperature sensor")
      ->capture_default_str()
      ->check(kNonNegative);
  sub->add_option("--wear-noise-mm", a->wear_noise_mm, "Standard deviation of the wear channel")
      ->capture_default_str()
      ->check(kNonNegative);
  sub->add_option("--radius-noise-mm", a->radius_noise_mm,
                  "Standard deviation of the rolling radius")
      ->capture_default_str()
      ->check(kNonNegative);
  sub->add_option("--process-noise", a->process_noise,
                  "Make the truth stochastic: the model plus the random-walk process noise of an "
                  "observer noise file (its process_noise section; 'default' for "
                  "data/observer/default.yaml), as hotlap observe assumes");
  sub->add_option("--seed", a->seed, "Seed of the noise (sensor and process noise)")
      ->capture_default_str();
  sub->add_option("--ambient-temp-C", a->ambient_C, "Air temperature")->capture_default_str();
  sub->add_option("--track-temp-C", a->track_C, "Track surface temperature")->capture_default_str();
  sub->add_option("--step-m", a->step_m, "Spacing of the road points the lap is solved on")
      ->capture_default_str();
  sub->add_option("--out", a->out, "Output log (CSV, docs/telemetry-csv.md)")->required();
  sub->add_option("--json", a->json, "Write the summary as JSON (docs/json-output.md)");
  return [a] { return RunSynth(*a); };
}

}  // namespace hotlap::app
