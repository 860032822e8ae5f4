#include "hotlap/tyre/tyre_eval_json.h"

#include "hotlap/common/json_output.h"

namespace hotlap::tyre {

nlohmann::json TyreForcesJson(const TyreForces<double>& f) {
  return {{"fx_N", RoundSignificant(f.fx)},
          {"fy_N", RoundSignificant(f.fy)},
          {"mz_Nm", RoundSignificant(f.mz)},
          {"mx_Nm", RoundSignificant(f.mx)},
          {"my_Nm", RoundSignificant(f.my)}};
}

nlohmann::json TyreEvalJson(std::string_view model_kind, const std::string& params, double grip,
                            const std::vector<double>& values) {
  nlohmann::json in;
  const auto& inputs = OperatingPointInputs();
  for (size_t i = 0; i < inputs.size() && i < values.size(); ++i) in[inputs[i].column] = values[i];
  return {{"command", "tyre eval"},
          {"model", model_kind},
          {"params", params},
          {"grip_factor", RoundSignificant(grip)},
          {"inputs", in}};
}

void AddTyreGridJson(nlohmann::json& summary, const TyreGrid& grid, const std::string& out) {
  summary["out"] = out;
  summary["points"] = grid.points;
  summary["peak_abs_fx_N"] = RoundSignificant(grid.peak_abs_fx);
  summary["peak_abs_fy_N"] = RoundSignificant(grid.peak_abs_fy);
  summary["peak_abs_mz_Nm"] = RoundSignificant(grid.peak_abs_mz);
}

}  // namespace hotlap::tyre
