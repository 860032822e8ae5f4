#include "hotlap/ocp/optimal_run_json.h"

#include <algorithm>

#include "hotlap/common/json_output.h"
#include "hotlap/common/units.h"
#include "hotlap/ocp/optimal_run_text.h"

namespace hotlap::ocp {

namespace {

// The lap's mesh: its nodes, shortest and longest interval, the error estimate, and an adaptive
// mesh's solves.
nlohmann::json MeshJson(const OptimalLapRun& run) {
  const std::vector<double>& d = run.solution.distance;
  double shortest = 0.0, longest = 0.0;
  for (size_t k = 1; k < d.size(); ++k) {
    const double h = d[k] - d[k - 1];
    shortest = k == 1 ? h : std::min(shortest, h);
    longest = std::max(longest, h);
  }
  nlohmann::json rounds = nlohmann::json::array();
  for (const MeshRound& m : run.mesh_rounds) {
    rounds.push_back({{"nodes", m.nodes},
                      {"ipopt_iterations", m.iterations},
                      {"solve_time_s", RoundSignificant(m.solve_seconds)},
                      {"lap_time_s", RoundSignificant(m.lap_time_s)},
                      {"estimated_error_s", RoundSignificant(m.estimated_error_s)},
                      {"estimated_abs_error_s", RoundSignificant(m.abs_error_s)},
                      {"status", m.converged ? "converged" : "failed"}});
  }
  const bool estimated = !run.mesh_error.interval_s.empty();
  return {
      {"adaptive", !run.mesh_rounds.empty()},
      {"nodes", run.solution.layout.nodes},
      {"min_step_m", RoundSignificant(shortest)},
      {"max_step_m", RoundSignificant(longest)},
      {"estimated_error_s", estimated
                                ? nlohmann::json(RoundSignificant(run.mesh_error.lap_time_error_s))
                                : nlohmann::json()},
      {"estimated_abs_error_s",
       estimated ? nlohmann::json(RoundSignificant(run.mesh_error.abs_error_s)) : nlohmann::json()},
      {"rounds", rounds}};
}

nlohmann::json FailedStartsJson(const std::vector<OptimalLapRun::FailedStart>& failed) {
  nlohmann::json out = nlohmann::json::array();
  for (const OptimalLapRun::FailedStart& f : failed) {
    out.push_back({{"from", f.from}, {"ipopt_iterations", f.iterations}, {"message", f.message}});
  }
  return out;
}

}  // namespace

nlohmann::json SolvedLapJson(const SolvedLap& s, const std::string& thermal_start) {
  const SolveResult& r = s.run.solution.solve;
  const OptimalLapFigures& f = s.figures;
  nlohmann::json corners;
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    nlohmann::json& j = corners[std::string(CornerName(c))];
    j = {{"peak_disc_temp_C", RoundSignificant(f.peak_disc_temp_C[i])},
         {"peak_tread_temp_C", RoundSignificant(f.peak_tread_temp_C[i])},
         {"wear_mm", RoundSignificant(f.wear_mm[i])}};
    const CornerTrace& t = s.run.solution.corners[i];
    if (!t.gas_temp.empty()) {
      j["peak_gas_temp_C"] = RoundSignificant(
          KelvinToCelsius(*std::max_element(t.gas_temp.begin(), t.gas_temp.end())));
      j["peak_pressure_kPa"] =
          RoundSignificant(1e-3 * *std::max_element(t.pressure.begin(), t.pressure.end()));
    }
    // The exact models' audit over the lap (sim::RunReplay over the solution's channels).
    if (!s.run.exact.audits.empty()) j["energy_audit"] = sim::AuditJson(s.run.exact.audits[0][i]);
  }
  nlohmann::json start = {{"mode", thermal_start}, {"qss_laps", s.run.start_laps}};
  if (thermal_start == "racing") {
    start["carcass_rise_K"] = RoundSignificant(s.run.start_carcass_rise_K);
  }
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    // The state at the start line (periodic: the solution's own first node).
    const CornerTrace& t = s.run.solution.corners[i];
    const bool own = !t.tread_temp.empty();
    start["corners"][std::string(CornerName(c))] = {
        {"tread_temp_C", RoundSignificant(KelvinToCelsius(own ? t.tread_temp.front()
                                                              : s.run.start.tyres[i].tread_temp))},
        {"carcass_temp_C", RoundSignificant(KelvinToCelsius(
                               own ? t.carcass_temp.front() : s.run.start.tyres[i].carcass_temp))},
        {"disc_temp_C", RoundSignificant(KelvinToCelsius(own ? t.disc_temp.front()
                                                             : s.run.start.brakes[i].disc_temp))},
        {"calliper_temp_C",
         RoundSignificant(KelvinToCelsius(own ? t.calliper_temp.front()
                                              : s.run.start.brakes[i].calliper_temp))}};
  }
  nlohmann::json turns = nlohmann::json::array();
  for (const TurnApproach& t : s.approaches) {
    nlohmann::json j = {{"turn", t.turn},
                        {"entry_m", RoundSignificant(t.entry_m)},
                        {"min_speed_mps", RoundSignificant(t.min_speed_mps)},
                        {"min_speed_at_m", RoundSignificant(t.min_speed_at_m)}};
    j["lift_m"] = t.lift_m ? nlohmann::json(RoundSignificant(*t.lift_m)) : nlohmann::json();
    j["brake_m"] = t.brake_m ? nlohmann::json(RoundSignificant(*t.brake_m)) : nlohmann::json();
    turns.push_back(j);
  }
  return {
      {"lap_time_s", RoundSignificant(f.lap_time_s)},
      {"qss_lap_time_s", RoundSignificant(s.run.qss_lap_time)},
      {"qss_on_optimal_line_lap_time_s", RoundSignificant(s.run.qss_on_line_lap_time)},
      {"solve_time_s", RoundSignificant(r.solve_seconds)},
      {"ipopt_iterations", r.iterations},
      {"regularized_iterations", r.regularized_iterations},
      {"coarse_solve",
       s.run.coarse.iterations > 0
           ? nlohmann::json{{"ipopt_iterations", s.run.coarse.iterations},
                            {"regularized_iterations", s.run.coarse.regularized_iterations},
                            {"solve_time_s", RoundSignificant(s.run.coarse.solve_seconds)},
                            {"lap_time_s", RoundSignificant(s.run.coarse_lap_time)},
                            {"status", s.run.coarse.ok() ? "converged" : "failed"}}
           : nlohmann::json()},
      {"status", r.ok() ? "converged" : "failed"},
      {"message", r.message},
      {"failed_starts", FailedStartsJson(s.run.failed_starts)},
      {"started_from", s.run.started_from},
      {"warm_start_from",
       s.warm_start_from.empty() ? nlohmann::json() : nlohmann::json(s.warm_start_from)},
      {"warm_start_distance", s.warm_start_from.empty()
                                  ? nlohmann::json()
                                  : nlohmann::json(RoundSignificant(s.warm_start_distance))},
      {"constraint_violation", RoundSignificant(r.primal_infeasibility)},
      {"front_disc_limit_C",
       s.front_disc_limit ? nlohmann::json(RoundSignificant(KelvinToCelsius(*s.front_disc_limit)))
                          : nlohmann::json()},
      {"max_front_disc_temp_C", RoundSignificant(f.max_front_disc_temp_C)},
      {"top_speed_mps", RoundSignificant(f.top_speed_mps)},
      {"min_speed_mps", RoundSignificant(f.min_speed_mps)},
      {"corners", corners},
      {"turns", turns},
      {"thermal_start", start},
      {"brake_energy_J", RoundSignificant(f.brake_energy_J)},
      {"brake_energy_under_drive_J", RoundSignificant(f.brake_energy_under_drive_J)},
      {"max_pedal_rate_per_s", RoundSignificant(f.max_pedal_rate_per_s)},
      {"max_steer_rate_radps", RoundSignificant(f.max_steer_rate_radps)},
      {"smoothing_effect_tread_K", RoundSignificant(s.run.max_tread_difference_K)},
      {"smoothing_effect_disc_K", RoundSignificant(s.run.max_disc_difference_K)},
      {"frozen_wear_grip_difference", RoundSignificant(s.run.solution.frozen_wear_grip_difference)},
      {"mesh", MeshJson(s.run)},
      {"variables", s.run.solution.variables},
      {"constraints", s.run.solution.constraints},
      {"sensitivities",
       s.sensitivities.empty() ? nlohmann::json() : SensitivitiesJson(s.sensitivities)}};
}

nlohmann::json SensitivitiesJson(const std::vector<LapSensitivity>& sensitivities) {
  nlohmann::json list = nlohmann::json::array();
  for (const LapSensitivity& s : sensitivities) {
    list.push_back({{"key", s.parameter.key},
                    {"label", s.parameter.label},
                    {"unit", s.parameter.unit},
                    {"value", RoundSignificant(s.value)},
                    {"step", RoundSignificant(s.step)},
                    {"d_lap_time_s_per_unit", RoundSignificant(s.d_lap_time_per_unit)},
                    {"typical_step", RoundSignificant(s.parameter.typical_step)},
                    {"typical_step_text", s.parameter.step_text},
                    {"typical_step_effect_ms", RoundSignificant(1e3 * s.typical_effect_s())}});
  }
  return list;
}

nlohmann::json LimitCostSensitivitiesJson(const SolvedLap& free, const SolvedLap& limited) {
  const std::vector<LimitCostSensitivity> both = LimitCostSensitivities(free, limited);
  if (both.empty()) return nullptr;
  nlohmann::json list = nlohmann::json::array();
  for (const LimitCostSensitivity& s : both) {
    list.push_back({{"key", s.free->parameter.key},
                    {"label", s.free->parameter.label},
                    {"unit", s.free->parameter.unit},
                    {"d_delta_s_per_unit", RoundSignificant(s.d_cost_per_unit())},
                    {"typical_step_text", s.free->parameter.step_text},
                    {"typical_step_effect_ms", RoundSignificant(1e3 * s.typical_cost_effect_s())}});
  }
  return list;
}

nlohmann::json OptimalRunsJson(const OptimalRuns& runs, const OptimalRunOptions& options,
                               const std::string& track_name, const vehicle::Car& car,
                               double wall_time_s,
                               const std::optional<double>& mesh_check_delta_s) {
  const std::vector<SolvedLap>& laps = runs.laps;
  nlohmann::json j;
  if (laps.size() == 2) {
    j = {{"command", "lap --method ocp"},
         {"unconstrained", SolvedLapJson(laps[0], options.thermal_start)},
         {"constrained", SolvedLapJson(laps[1], options.thermal_start)},
         {"delta_s", RoundSignificant(laps[1].figures.lap_time_s - laps[0].figures.lap_time_s)},
         {"limit_cost_sensitivities", LimitCostSensitivitiesJson(laps[0], laps[1])}};
    // The headline keys of the unconstrained run at the top level too.
    for (const char* k : {"lap_time_s", "solve_time_s", "ipopt_iterations", "status",
                          "max_front_disc_temp_C", "top_speed_mps"}) {
      j[k] = j["unconstrained"][k];
    }
    j["limited_in_second_process"] = runs.limited_in_second_process;
  } else {
    j = SolvedLapJson(laps[0], options.thermal_start);
    j["command"] = "optimise";
  }
  j["track"] = track_name;
  j["car"] = car.name;
  j["overrides"] = vehicle::OverridesJson(car.overrides);
  j["mesh_step_m"] = options.tolerance_s > 0.0 ? nlohmann::json() : nlohmann::json(options.step_m);
  j["mesh_tolerance_s"] =
      options.tolerance_s > 0.0 ? nlohmann::json(options.tolerance_s) : nlohmann::json();
  j["collocation"] = options.collocation;
  j["coarse_mesh_step_m"] = options.coarse_step_m;
  j["coarse_collocation"] = options.coarse_collocation;
  j["wear_in_programme"] = options.wear_in_programme;
  j["paper_models"] = options.paper_models;
  j["controls"] = options.independent_drive_and_brake ? "independent" : "pedal";
  j["wall_time_s"] = RoundSignificant(wall_time_s);
  if (mesh_check_delta_s) j["mesh_check_delta_s"] = RoundSignificant(*mesh_check_delta_s);
  return j;
}

}  // namespace hotlap::ocp
