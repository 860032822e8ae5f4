#include "hotlap/sim/synth_json.h"

#include <algorithm>

#include "hotlap/common/corner.h"
#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"

namespace hotlap::sim {

std::array<SynthCornerSummary, 4> SummarizeSynthCorners(const SynthLog& log) {
  std::array<SynthCornerSummary, 4> out;
  for (int i = 0; i < 4; ++i) {
    const CornerHistory& h = log.truth.corners[i];
    if (!h.tread_temp.empty()) {
      out[i].peak_tread_temp_K = *std::max_element(h.tread_temp.begin(), h.tread_temp.end());
    }
    if (!h.disc_temp.empty()) {
      out[i].peak_disc_temp_K = *std::max_element(h.disc_temp.begin(), h.disc_temp.end());
    }
    if (!h.wear.empty()) out[i].wear_mm = h.wear.back();
  }
  return out;
}

nlohmann::json SynthJson(const SynthLog& log, const SynthOptions& options, const vehicle::Car& car,
                         const SynthRunInfo& info) {
  nlohmann::json corners;
  const std::array<SynthCornerSummary, 4> summary = SummarizeSynthCorners(log);
  for (Corner c : kAllCorners) {
    const SynthCornerSummary& s = summary[CornerIndex(c)];
    corners[std::string(CornerName(c))] = {
        {"peak_tread_temp_C", RoundSignificant(KelvinToCelsius(s.peak_tread_temp_K))},
        {"peak_disc_temp_C", RoundSignificant(KelvinToCelsius(s.peak_disc_temp_K))},
        {"wear_mm", RoundSignificant(s.wear_mm)}};
  }
  const std::vector<double>& time = log.inputs.time;
  nlohmann::json j = {
      {"command", "synth"},
      {"car", car.name},
      {"overrides", vehicle::OverridesJson(car.overrides)},
      {"params", info.params},
      {"track", info.track},
      {"out", info.out},
      {"laps", options.laps},
      {"samples", time.size()},
      {"duration_s", time.empty() ? 0.0 : RoundSignificant(time.back() - time.front())},
      {"lap_time_s", RoundSignificant(log.lap_time_s)},
      {"rate_hz", options.rate_hz},
      {"noise_C", options.temp_noise_K},
      {"lag_s", options.sensor_lag_s},
      {"seed", options.seed},
      {"corners", corners}};
  if (options.process_noise) {
    const SynthProcessNoise& q = *options.process_noise;
    j["process_noise"] = {{"file", info.process_noise_file},
                          {"tread_temp_K2_per_s", q.tread_temp_K2_per_s},
                          {"carcass_temp_K2_per_s", q.carcass_temp_K2_per_s},
                          {"wear_mm2_per_s", q.wear_mm2_per_s},
                          {"disc_temp_K2_per_s", q.disc_temp_K2_per_s},
                          {"calliper_temp_K2_per_s", q.calliper_temp_K2_per_s}};
  }
  return j;
}

}  // namespace hotlap::sim
