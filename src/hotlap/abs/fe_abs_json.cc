#include "hotlap/abs/fe_abs_json.h"

#include "hotlap/common/json_output.h"
#include "hotlap/fe/step_json.h"

namespace hotlap::sim {

nlohmann::json FeAbsStopJson(const FeAbsStopResult& r, double duration_s,
                             const fe::Energies& energies) {
  const fe::BrakeResult& br = r.brake;
  const CycleWindow& cycles = r.cycles;
  nlohmann::json cycle_starts = nlohmann::json::array();
  for (double t : r.cycle_starts_s) cycle_starts.push_back(RoundSignificant(t));
  return {
      {"duration_s", RoundSignificant(duration_s, 6)},
      {"initial_speed_mps", RoundSignificant(br.initial_speed_mps, 6)},
      {"final_speed_mps", RoundSignificant(br.final_speed_mps, 6)},
      {"distance_m", RoundSignificant(br.distance_m, 6)},
      {"max_slip", RoundSignificant(br.max_slip, 6)},
      {"max_brake_torque_Nm", RoundSignificant(br.max_brake_torque_Nm, 6)},
      {"control_cycles", cycles.cycles},
      {"cycle_starts_s", cycle_starts},
      {"cycles_per_s", RoundSignificant(cycles.cycles_per_s)},
      {"first_cycle_start_s", JsonOrNull(cycles.first_cycle_start_s)},
      {"second_cycle_start_s", JsonOrNull(cycles.second_cycle_start_s)},
      {"abs_exit_s", JsonOrNull(r.abs_exit_s)},
      {"max_lambda_after_first_cycle", JsonOrNull(cycles.max_lambda_after_first_cycle)},
      {"fraction_time_lambda_below_0_135", JsonOrNull(cycles.fraction_time_lambda_below_0_135, 4)},
      {"max_cord_strain", fe::CordStrainJson(br.max_cord_strain)},
      {"energies", fe::FeEnergiesJson(energies)}};
}

nlohmann::json LumpedAbsJson(const AbsMetrics& m) {
  return {{"control_cycles", m.cycles},
          {"first_cycle_start_s", JsonOrNull(m.first_cycle_start_s, 6)},
          {"second_cycle_start_s", JsonOrNull(m.second_cycle_start_s, 6)},
          {"max_lambda_after_first_cycle", JsonOrNull(m.max_lambda_after_first_cycle, 6)},
          {"fraction_time_lambda_below_0_135", JsonOrNull(m.fraction_time_lambda_below_0_135, 6)},
          {"final_speed_mps", RoundSignificant(m.final_speed_mps, 6)},
          {"distance_m", RoundSignificant(m.distance_m, 6)}};
}

nlohmann::json FeAbsEnsembleJson(const FeAbsEnsembleResult& e, double duration_s) {
  nlohmann::json figures = nlohmann::json::object();
  for (size_t k = 0; k < e.keys.size(); ++k) {
    const EnsembleStat& s = e.stats[k];
    figures[e.keys[k]] = {{"n", s.n},
                          {"mean", RoundSignificant(s.mean, 6)},
                          {"standard_error", RoundSignificant(s.standard_error, 4)},
                          {"sd", RoundSignificant(s.sd, 4)},
                          {"min", RoundSignificant(s.min, 6)},
                          {"max", RoundSignificant(s.max, 6)},
                          {"unit", e.units[k]}};
  }
  nlohmann::json members = nlohmann::json::array();
  for (size_t k = 0; k < e.members.size(); ++k) {
    const FeAbsFigures& f = e.members[k];
    nlohmann::json m = {{"member", e.first_member + static_cast<int>(k)},
                        {"control_cycles", f.cycles}};
    for (const FeAbsFigureValue& v : ListFeAbsFigures(f)) m[v.key] = JsonOrNull(v.value, 6);
    members.push_back(m);
  }
  return {{"members", static_cast<int>(e.members.size())},
          {"first_member", e.first_member},
          {"perturbation", FePerturbationName(e.perturbation)},
          {"duration_s", RoundSignificant(duration_s, 6)},
          {"figures", figures},
          {"member_figures", members}};
}

}  // namespace hotlap::sim
