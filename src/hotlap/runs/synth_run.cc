#include "hotlap/runs/synth_run.h"

#include <array>
#include <cmath>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/observe/observer_config.h"
#include "hotlap/sim/road.h"
#include "hotlap/sim/synth_json.h"
#include "hotlap/sim/synth_params.h"

namespace hotlap::runs {

namespace {

sim::SynthOptions SynthOptionsOf(const SynthRunOptions& a) {
  sim::SynthOptions o;
  o.laps = a.laps;
  o.rate_hz = a.rate_hz;
  o.temp_noise_K = a.noise_C;
  o.sensor_lag_s = a.lag_s;
  o.wear_noise_mm = a.wear_noise_mm;
  o.radius_noise_m = 1e-3 * a.radius_noise_mm;
  o.tpms = a.tpms;
  if (a.truth != "paper" && a.truth != "car") {
    throw InputError(fmt::format("--truth '{}': 'paper' or 'car'", a.truth));
  }
  o.paper_models = a.truth == "paper";
  o.seed = a.seed;
  o.ambient_temp = CelsiusToKelvin(a.ambient_C);
  o.track_temp = CelsiusToKelvin(a.track_C);
  return o;
}

}  // namespace

SynthRun RunSynth(vehicle::Car& car, const track::Track& track, const SynthRunOptions& a) {
  SynthRun run;
  if (!a.params.empty()) {
    const sim::ParameterOverrides overrides = sim::LoadParameterOverrides(a.params);
    sim::ApplyParameterOverrides(overrides, car);
    run.params_name = overrides.name;
  }
  const std::vector<sim::RoadPoint> road = sim::SampleRoad(track, a.step_m);
  run.options = SynthOptionsOf(a);
  if (!a.process_noise.empty()) {
    // The observer's noise file: its process_noise section is the random walk the truth gets.
    run.process_noise_file = a.process_noise == "default"
                                 ? observe::DefaultObserverConfigPath().string()
                                 : a.process_noise;
    const observe::ProcessNoise q = observe::LoadObserverConfig(run.process_noise_file).process;
    run.options.process_noise =
        sim::SynthProcessNoise{q.tread_temp, q.carcass_temp, q.wear, q.disc_temp, q.calliper_temp};
  }
  run.log = sim::SynthesizeLog(car, road, run.options);
  return run;
}

void WriteSynthRunLog(const std::filesystem::path& out, const SynthRun& run,
                      const track::Track& track, const SynthRunOptions& options) {
  const std::string& params = options.params;
  sim::WriteSynthLog(
      out, run.log,
      {{"track", track.name()}, {"params", params.empty() ? std::string("(car file)") : params}});
}

nlohmann::json SynthRunJson(const SynthRun& run, const vehicle::Car& car, const track::Track& track,
                            const SynthRunOptions& options, const std::string& out) {
  return sim::SynthJson(run.log, run.options, car,
                        {track.name(), options.params, out, run.process_noise_file});
}

std::string SynthRunText(const SynthRun& run, const vehicle::Car& car, const track::Track& track) {
  const sim::SynthOptions& o = run.options;
  std::string out =
      fmt::format("hotlap synth: car '{}' with {} parameters, {} lap(s) of {} ({:.3f} s per lap)\n",
                  car.name, run.params_name, o.laps, track.name(), run.log.lap_time_s);
  auto it = std::back_inserter(out);
  fmt::format_to(it, "{} samples at {:g} Hz; sensors: lag {:g} s, noise {:g} degC; seed {}\n",
                 run.log.inputs.time.size(), o.rate_hz, o.sensor_lag_s, o.temp_noise_K, o.seed);
  if (o.process_noise) {
    const sim::SynthProcessNoise& q = *o.process_noise;
    fmt::format_to(
        it,
        "truth with process noise from {}: random walk of tread {:.3g}, carcass {:.3g}, disc "
        "{:.3g}, calliper {:.3g} degC per sqrt(s), wear {:.3g} mm per sqrt(s)\n",
        run.process_noise_file, std::sqrt(q.tread_temp_K2_per_s),
        std::sqrt(q.carcass_temp_K2_per_s), std::sqrt(q.disc_temp_K2_per_s),
        std::sqrt(q.calliper_temp_K2_per_s), std::sqrt(q.wear_mm2_per_s));
  }
  const std::array<sim::SynthCornerSummary, 4> corners = sim::SummarizeSynthCorners(run.log);
  for (Corner c : kAllCorners) {
    const sim::SynthCornerSummary& s = corners[CornerIndex(c)];
    fmt::format_to(it, "{}: peak tread {:.1f} degC, peak disc {:.1f} degC, wear {:.5f} mm\n",
                   CornerName(c), KelvinToCelsius(s.peak_tread_temp_K),
                   KelvinToCelsius(s.peak_disc_temp_K), s.wear_mm);
  }
  return out;
}

}  // namespace hotlap::runs
