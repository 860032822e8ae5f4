// `hotlap synth`: a synthetic "measured" log from the lap simulation with chosen true parameters,
// sensor lag and noise (docs/fitting.md).

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/output_folder.h"
#include "hotlap/runs/synth_run.h"
#include "hotlap/track/track_io.h"

namespace hotlap::app {

namespace {

struct SynthArgs {
  std::string car = "gen7", track = "darlington", out, json;
  std::vector<std::string> set;  // --set KEY=VALUE
  runs::SynthRunOptions run;
};

int RunSynth(const SynthArgs& a) {
  CheckOutputFolder(a.out, "--out");
  if (!a.json.empty()) CheckOutputFolder(a.json, "--json");
  vehicle::Car car = vehicle::LoadCar(ResolveCarFile(a.car), vehicle::ParseCarOverrides(a.set));
  const track::Track track = track::LoadTrack(a.track);
  const runs::SynthRun run = runs::RunSynth(car, track, a.run);
  runs::WriteSynthRunLog(a.out, run, track, a.run);
  fmt::print("{}", runs::SynthRunText(run, car, track));
  fmt::print("wrote {}\n", a.out);
  if (!a.json.empty())
    WriteJsonFileAndSay(a.json, runs::SynthRunJson(run, car, track, a.run, a.out));
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
  sub->add_option("--params", a->run.params,
                  "Parameter file with the true values (model: parameter_overrides)");
  sub->add_option("--track", a->track, "Built-in track name or track file")->capture_default_str();
  // An option with its default shown and its range checked.
  const auto checked = [sub](const char* name, auto& value, const char* help, const auto& range) {
    sub->add_option(name, value, help)->capture_default_str()->check(range);
  };
  checked("--laps", a->run.laps, "Laps to simulate", kPositive);
  checked("--rate-hz", a->run.rate_hz, "Logging rate", kPositive);
  checked("--noise-C", a->run.noise_C, "Standard deviation of every temperature sensor, degC",
          kNonNegative);
  checked("--lag-s", a->run.lag_s, "First-order time constant of every temperature sensor",
          kNonNegative);
  checked("--wear-noise-mm", a->run.wear_noise_mm, "Standard deviation of the wear channel",
          kNonNegative);
  checked("--radius-noise-mm", a->run.radius_noise_mm, "Standard deviation of the rolling radius",
          kNonNegative);
  sub->add_option("--truth", a->run.truth,
                  "The truth's models: 'paper' (the paper's two masses and lumped disc, what the "
                  "fits identify and the observer tracks) or 'car' (the car's own gas-and-rim "
                  "tyres and bulk discs, with TPMS channels)")
      ->capture_default_str();
  sub->add_flag("--tpms,!--no-tpms", a->run.tpms.enabled,
                "With --truth car, write the TPMS channels pressure_<c>_kPa and gas_temp_<c>_C")
      ->capture_default_str();
  checked("--tpms-noise-kPa", a->run.tpms.pressure_noise_kPa,
          "Standard deviation of the TPMS pressure", kNonNegative);
  checked("--tpms-temp-noise-C", a->run.tpms.temp_noise_K,
          "Standard deviation of the TPMS gas temperature", kNonNegative);
  checked("--tpms-lag-s", a->run.tpms.lag_s, "First-order time constant of the TPMS sensors",
          kNonNegative);
  sub->add_option("--process-noise", a->run.process_noise,
                  "Make the truth stochastic: the model plus the random-walk process noise of an "
                  "observer noise file (its process_noise section; 'default' for "
                  "data/observer/default.yaml), as hotlap observe assumes");
  sub->add_option("--seed", a->run.seed, "Seed of the noise (sensor and process noise)")
      ->capture_default_str();
  sub->add_option("--ambient-temp-C", a->run.ambient_C, "Air temperature")->capture_default_str();
  sub->add_option("--track-temp-C", a->run.track_C, "Track surface temperature")
      ->capture_default_str();
  sub->add_option("--step-m", a->run.step_m, "Spacing of the road points the lap is solved on")
      ->capture_default_str();
  sub->add_option("--out", a->out, "Output log (CSV, docs/telemetry-csv.md)")->required();
  sub->add_option("--json", a->json, "Write the summary as JSON (docs/json-output.md)");
  return [a] { return RunSynth(*a); };
}

}  // namespace hotlap::app
