#include "hotlap/abs/abs_json.h"

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"

namespace hotlap::sim {

nlohmann::json AbsMetricsJson(const AbsMetrics& m) {
  const AbsEnergy& e = m.energy;
  return {
      {"stopped", m.stopped},
      {"stopping_distance_m", JsonOrNull(m.stopping_distance_m)},
      {"stop_time_s", JsonOrNull(m.stop_time_s)},
      {"distance_m", RoundSignificant(m.distance_m)},
      {"end_time_s", RoundSignificant(m.end_time_s)},
      {"final_speed_mps", RoundSignificant(m.final_speed_mps)},
      {"mean_deceleration_mps2", RoundSignificant(m.mean_deceleration_mps2)},
      {"cycles", m.cycles},
      {"cycles_per_s", RoundSignificant(m.cycles_per_s)},
      {"first_cycle_start_s", JsonOrNull(m.first_cycle_start_s)},
      {"second_cycle_start_s", JsonOrNull(m.second_cycle_start_s)},
      {"abs_exit_s", JsonOrNull(m.abs_exit_s)},
      {"max_lambda_after_first_cycle", JsonOrNull(m.max_lambda_after_first_cycle)},
      {"fraction_time_lambda_below_0_135", JsonOrNull(m.fraction_time_lambda_below_0_135)},
      {"max_lambda", RoundSignificant(m.max_lambda)},
      {"wheel_locked", m.wheel_locked},
      {"peak_disc_temp_C", RoundSignificant(KelvinToCelsius(m.peak_disc_temp_K))},
      {"peak_calliper_temp_C", RoundSignificant(KelvinToCelsius(m.peak_calliper_temp_K))},
      {"final_disc_temp_C", RoundSignificant(KelvinToCelsius(m.final_disc_temp_K))},
      {"energy",
       {{"kinetic_lost_J", RoundSignificant(e.kinetic_lost_J)},
        {"drum_work_J", RoundSignificant(e.drum_work_J)},
        {"brake_J", RoundSignificant(e.brake_J)},
        {"tyre_slip_J", RoundSignificant(e.tyre_slip_J)},
        {"rolling_resistance_J", RoundSignificant(e.rolling_resistance_J)},
        {"closure_error", RoundSignificant(e.closure_error, 3)}}},
  };
}

nlohmann::json AbsRunJson(const AbsConfig& config, const AbsEvent& event, const AbsMetrics& m,
                          const std::string& out_csv, const std::string& out_report,
                          const std::vector<AbsComparisonRun>* comparison,
                          const AbsStopSeries* series) {
  nlohmann::json j = AbsMetricsJson(m);
  j["command"] = "abs";
  j["config"] = config.path.string();
  j["overrides"] = AbsOverridesJson(config.overrides);
  j["surface"] = event.surface;
  j["abs"] = event.control == AbsControl::kAbs;
  j["vehicle"] = event.vehicle == AbsVehicleMode::kFree ? "free" : "drum";
  j["initial_speed_mps"] = RoundSignificant(event.initial_speed_mps);
  j["duration_s"] = RoundSignificant(event.duration_s);
  j["outputs"] = {{"csv", out_csv}, {"report", out_report}};
  if (comparison != nullptr && series != nullptr) {
    nlohmann::json runs = nlohmann::json::array();
    for (size_t i = 0; i + 1 < comparison->size(); i += 2) {
      runs.push_back({{"surface", (*comparison)[i].surface},
                      {"abs", AbsMetricsJson((*comparison)[i].metrics)},
                      {"locked", AbsMetricsJson((*comparison)[i + 1].metrics)}});
    }
    nlohmann::json peaks = nlohmann::json::array();
    for (const AbsMetrics& s : series->stops) {
      peaks.push_back(RoundSignificant(KelvinToCelsius(s.peak_disc_temp_K)));
    }
    j["scenarios"] = {{"comparison", runs},
                      {"stop_series",
                       {{"surface", config.scenarios.stop_series_surface},
                        {"stops", series->stops.size()},
                        {"interval_s", config.scenarios.stop_series_interval_s},
                        {"peak_disc_temp_C", peaks}}}};
  }
  return j;
}

}  // namespace hotlap::sim
