#include "hotlap/observe/observer_config.h"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "hotlap/common/corner.h"
#include "hotlap/common/data_path.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::observe {

ObserverConfig LoadObserverConfig(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  ObserverConfig c;
  c.path = path;
  c.source = path.string();
  c.name = y.String("name");
  y.Choice("model", {"observer_noise"});

  YamlReader p = y.Map("process_noise");
  c.process.tread_temp = p.Number("tread_temp_K2_per_s", Range::NonNegative("K^2/s"));
  c.process.carcass_temp = p.Number("carcass_temp_K2_per_s", Range::NonNegative("K^2/s"));
  c.process.wear = p.Number("wear_mm2_per_s", Range::NonNegative("mm^2/s"));
  c.process.disc_temp = p.Number("disc_temp_K2_per_s", Range::NonNegative("K^2/s"));
  c.process.calliper_temp = p.Number("calliper_temp_K2_per_s", Range::NonNegative("K^2/s"));
  p.Finish();

  YamlReader s = y.Map("sensor_noise");
  SensorNoise sensor;
  sensor.tread_temp = s.Number("tread_temp_sd_C", Range::Positive("C"));
  sensor.disc_temp = s.Number("disc_temp_sd_C", Range::Positive("C"));
  sensor.calliper_temp = s.Number("calliper_temp_sd_C", Range::Positive("C"));
  s.Finish();
  c.sensors.fill(sensor);

  YamlReader i = y.Map("initial_sd");
  c.initial_sd.tread_temp = i.Number("tread_temp_C", Range::Positive("C"));
  c.initial_sd.carcass_temp = i.Number("carcass_temp_C", Range::Positive("C"));
  c.initial_sd.wear = i.Number("wear_mm", Range::Positive("mm"));
  c.initial_sd.disc_temp = i.Number("disc_temp_C", Range::Positive("C"));
  c.initial_sd.calliper_temp = i.Number("calliper_temp_C", Range::Positive("C"));
  i.Finish();

  if (y.Has("sensor_lag")) {
    YamlReader l = y.Map("sensor_lag");
    c.sensor_lag.tread_temp = l.Number("tread_temp_tau_s", Range::Closed(0.0, 60.0, "s"));
    c.sensor_lag.disc_temp = l.Number("disc_temp_tau_s", Range::Closed(0.0, 60.0, "s"));
    c.sensor_lag.calliper_temp = l.Number("calliper_temp_tau_s", Range::Closed(0.0, 60.0, "s"));
    l.Finish();
  }

  YamlReader k = y.Map("p5_scale");
  c.p5_scale.estimate = k.Choice("estimate", {"true", "false"}) == "true";
  c.p5_scale.initial_sd = k.Number("initial_sd", Range::Closed(1e-6, 1.0, "1"));
  c.p5_scale.random_walk_per_sqrt_s =
      k.Number("random_walk_per_sqrt_s", Range::Closed(0.0, 1.0, "1/sqrt(s)"));
  k.Finish();

  if (y.Has("car_models")) {
    YamlReader m = y.Map("car_models");
    CarModelsNoise n;
    n.rim_temp = m.Number("rim_temp_K2_per_s", Range::NonNegative("K^2/s"));
    n.disc_bulk_temp = m.Number("disc_bulk_temp_K2_per_s", Range::NonNegative("K^2/s"));
    n.rim_temp_sd = m.Number("rim_temp_sd_C", Range::Positive("C"));
    n.disc_bulk_temp_sd = m.Number("disc_bulk_temp_sd_C", Range::Positive("C"));
    n.pressure_sd = 1e3 * m.Number("tpms_pressure_sd_kPa", Range::Positive("kPa"));
    n.gas_temp_sd = m.Number("tpms_gas_temp_sd_C", Range::Positive("C"));
    n.tpms_lag_s = m.Number("tpms_tau_s", Range::Closed(1e-3, 60.0, "s"));
    m.Finish();
    c.car_models = n;
  }

  YamlReader g = y.Map("gate");
  c.gate_sigma = g.Number("innovation_sigma", Range::Closed(1.0, 1e3, "sigma"));
  g.Finish();

  YamlReader m = y.Map("monitor");
  c.window_s = m.Number("window_s", Range::Positive("s"));
  c.disagree_nis = m.Number("disagree_nis", Range::Positive("1"));
  c.disagree_after_s = m.Number("disagree_after_s", Range::NonNegative("s"));
  m.Finish();

  c.max_step_s = y.Number("max_step_s", Range::OpenClosed(0.0, 1.0, "s"));
  y.Finish();
  return c;
}

std::filesystem::path DefaultObserverConfigPath() {
  return DataDir() / "observer" / "default.yaml";
}

int ApplyFitResidualNoise(const std::filesystem::path& fit_json, ObserverConfig& config) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(ReadWholeFile(fit_json));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a JSON file: {}", fit_json.string(), e.what()));
  }
  if (!j.is_object() || !j.contains("corners") || !j["corners"].is_object()) {
    throw InputError(fmt::format(
        "{}: not a fit summary (no 'corners' object; write one with hotlap fit ... --json)",
        fit_json.string()));
  }
  int taken = 0;
  for (Corner c : kAllCorners) {
    const std::string name(CornerName(c));
    if (!j["corners"].contains(name)) continue;
    const nlohmann::json& corner = j["corners"][name];
    SensorNoise& s = config.sensors[CornerIndex(c)];
    const auto take = [&](const char* key, double& sd) {
      if (!corner.contains(key) || !corner[key].is_number()) return;
      const double v = corner[key].get<double>();
      if (!(std::isfinite(v) && v > 0.0)) {
        throw InputError(fmt::format("{}: corners.{}.{} is {}, expected a positive RMS in C",
                                     fit_json.string(), name, key, corner[key].dump()));
      }
      sd = v;
      ++taken;
    };
    take("rms_tread_C", s.tread_temp);
    take("rms_disc_C", s.disc_temp);
    take("rms_calliper_C", s.calliper_temp);
  }
  if (taken > 0) {
    config.source += fmt::format(" (sensor noise from {})", fit_json.string());
  }
  return taken;
}

}  // namespace hotlap::observe
