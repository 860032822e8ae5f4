#include "hotlap/observe/observe_json.h"

#include <cmath>
#include <string>

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"

namespace hotlap::observe {

namespace {

nlohmann::json Num(double x) {
  return std::isfinite(x) ? nlohmann::json(RoundSignificant(x, 6)) : nlohmann::json(nullptr);
}

nlohmann::json CornerJson(const CarObserver& observer, Corner c) {
  const CornerEstimate e = observer.Estimate(c);
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
  if (observer.config().p5_scale.estimate) {
    j["p5_scale"] = Num(e.p5_scale);
    j["p5_scale_sd"] = Num(e.p5_scale_sd);
  }
  if (e.has_gas) {
    j["rim_temp_C"] = Num(KelvinToCelsius(e.rim_temp));
    j["rim_temp_sd_C"] = Num(e.rim_temp_sd);
    j["disc_bulk_temp_C"] = Num(KelvinToCelsius(e.disc_bulk_temp));
    j["disc_bulk_temp_sd_C"] = Num(e.disc_bulk_temp_sd);
    j["gas_temp_C"] = Num(KelvinToCelsius(e.gas_temp));
    j["gas_temp_sd_C"] = Num(e.gas_temp_sd);
    j["pressure_kPa"] = Num(1e-3 * e.pressure);
    j["pressure_sd_kPa"] = Num(1e-3 * e.pressure_sd);
  }
  j["sensors"] = SensorsJson(observer, c);
  return j;
}

nlohmann::json WarningsJson(const std::vector<DisagreementWarning>& warnings) {
  nlohmann::json list = nlohmann::json::array();
  for (const DisagreementWarning& w : warnings) {
    list.push_back({{"corner", std::string(CornerName(w.corner))},
                    {"sensor", std::string(SensorQuantity(w.sensor))},
                    {"since_s", Num(w.since_s)},
                    {"time_s", Num(w.time_s)},
                    {"nis_average", Num(w.nis_average)},
                    {"message", w.message}});
  }
  return list;
}

}  // namespace

nlohmann::json SensorsJson(const CarObserver& observer, Corner c) {
  nlohmann::json sensors = nlohmann::json::object();
  for (Sensor s : kAllSensors) {
    const SensorMonitor& m = observer.monitor(c, s);
    if (m.readings == 0) continue;
    const auto [lo, hi] = m.Bounds95();
    sensors[std::string(SensorQuantity(s))] = {{"readings", m.readings},
                                               {"used", m.used},
                                               {"rejected", m.rejected},
                                               {"missing", m.missing},
                                               {"mean_nis", Num(m.MeanNis())},
                                               {"nis_bounds95", {Num(lo), Num(hi)}},
                                               {"consistent", m.Consistent()},
                                               {"disagreements", m.disagreements},
                                               {"disagree_time_s", Num(m.disagree_time_s)}};
  }
  return sensors;
}

bool AllConsistent(const CarObserver& observer) {
  for (Corner c : kAllCorners) {
    for (Sensor s : kAllSensors) {
      const SensorMonitor& m = observer.monitor(c, s);
      if (m.readings > 0 && !m.Consistent()) return false;
    }
  }
  return true;
}

nlohmann::json ObserveJson(const CarObserver& observer, const vehicle::Car& car,
                           const ObserveSummary& s) {
  const ObserverConfig& config = observer.config();
  nlohmann::json corners = nlohmann::json::object();
  for (Corner c : kAllCorners) corners[std::string(CornerName(c))] = CornerJson(observer, c);
  return {{"command", "observe"},
          {"telemetry", s.telemetry},
          {"car", car.name},
          {"overrides", vehicle::OverridesJson(car.overrides)},
          {"noise", config.source},
          {"models", observer.models() == ObservedModels::kCar ? "car" : "paper"},
          {"p5_scale_estimated", config.p5_scale.estimate},
          {"sensor_lag_s",
           {{"tread_temp", config.sensor_lag.tread_temp},
            {"disc_temp", config.sensor_lag.disc_temp},
            {"calliper_temp", config.sensor_lag.calliper_temp}}},
          {"sensor_lag_from", s.sensor_lag_from},
          {"tpms_lag_s",
           config.car_models ? Num(config.car_models->tpms_lag_s) : nlohmann::json(nullptr)},
          {"tpms_lag_from", s.tpms_lag_from},
          {"out", s.out},
          {"samples", observer.samples()},
          {"duration_s", Num(s.duration_s)},
          {"wall_time_s", Num(s.wall_time_s)},
          {"consistent", AllConsistent(observer)},
          {"corners", corners},
          {"disagreements", WarningsJson(s.warnings)},
          {"lap", s.lap ? nlohmann::json(*s.lap) : nlohmann::json(nullptr)},
          {"telemetry_warnings", s.telemetry_warnings}};
}

}  // namespace hotlap::observe
