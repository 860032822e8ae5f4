#include "hotlap/sim/fe_abs_json.h"

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

}  // namespace hotlap::sim
