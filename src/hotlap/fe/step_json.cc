#include "hotlap/fe/step_json.h"

#include <fmt/format.h>

#include "hotlap/common/json_output.h"

namespace hotlap::fe {

nlohmann::json FeMeshJson(const TyreRun& run) {
  const ExplicitSolver& solver = run.solver();
  const MassScalingReport& ms = solver.mass_scaling();
  return {{"elements", run.tyre().mesh.elements.size()},
          {"nodes", run.tyre().mesh.nodes.size()},
          {"time_step_s", RoundSignificant(solver.time_step(), 6)},
          {"time_step_scale", solver.model().options.time_step_scale},
          {"contact_step_s", RoundSignificant(solver.model().contact_step_s, 6)},
          {"stable_step_unscaled_s", RoundSignificant(ms.stable_step_unscaled_s, 6)},
          {"physical_mass_kg", RoundSignificant(ms.physical_mass_kg, 6)},
          {"mass_scaling_added_kg", RoundSignificant(ms.added_mass_kg, 6)},
          {"mass_scaled_elements", ms.scaled_elements}};
}

nlohmann::json FeEnergiesJson(const Energies& e) {
  return {{"kinetic_J", RoundSignificant(e.kinetic, 6)},
          {"internal_J", RoundSignificant(e.internal, 6)},
          {"hourglass_J", RoundSignificant(e.Hourglass(), 6)},
          {"bulk_viscous_J", RoundSignificant(e.bulk_viscous, 6)},
          {"damping_J", RoundSignificant(e.damping, 6)},
          {"friction_J", RoundSignificant(e.friction, 6)},
          {"contact_J", RoundSignificant(e.contact_stored, 6)},
          {"external_work_J", RoundSignificant(e.external_work, 6)},
          {"balance_error_J", RoundSignificant(e.BalanceError(), 3)},
          {"hourglass_over_internal",
           RoundSignificant(e.internal > 0 ? e.Hourglass() / e.internal : 0.0, 3)}};
}

nlohmann::json InflateJson(const InflateResult& inf, const Energies& energies) {
  return {{"pressure_kPa", RoundSignificant(1e-3 * inf.pressure_Pa, 6)},
          {"outer_radius_before_mm", RoundSignificant(1e3 * inf.outer_radius_before_m, 6)},
          {"outer_radius_after_mm", RoundSignificant(1e3 * inf.outer_radius_after_m, 6)},
          {"section_width_before_mm", RoundSignificant(1e3 * inf.section_width_before_m, 6)},
          {"section_width_after_mm", RoundSignificant(1e3 * inf.section_width_after_m, 6)},
          {"roundness_error_mm", RoundSignificant(1e3 * inf.max_roundness_error_m, 3)},
          {"max_cord_strain", CordStrainJson(inf.max_cord_strain)},
          {"energies", FeEnergiesJson(energies)}};
}

nlohmann::json FootprintJson(const FootprintResult& fp, const Energies& energies) {
  return {
      {"vertical_load_N", RoundSignificant(fp.vertical_load_N, 6)},
      {"road_force_z_N", RoundSignificant(fp.road_force_z_N, 6)},
      {"loaded_radius_mm", RoundSignificant(1e3 * fp.loaded_radius_m, 6)},
      {"deflection_mm", RoundSignificant(1e3 * fp.deflection_m, 6)},
      {"vertical_stiffness_kN_per_m", RoundSignificant(1e-3 * fp.vertical_stiffness_N_per_m, 6)},
      {"contact_area_cm2", RoundSignificant(1e4 * fp.contact_area_m2, 6)},
      {"contact_length_mm", RoundSignificant(1e3 * fp.contact_length_m, 6)},
      {"contact_width_mm", RoundSignificant(1e3 * fp.contact_width_m, 6)},
      {"peak_pressure_kPa", RoundSignificant(1e-3 * fp.peak_pressure_Pa, 6)},
      {"mean_pressure_kPa", RoundSignificant(1e-3 * fp.mean_pressure_Pa, 6)},
      {"max_cord_strain", CordStrainJson(fp.max_cord_strain)},
      {"energies", FeEnergiesJson(energies)}};
}

nlohmann::json RollJson(const RollResult& rr, const Energies& energies) {
  return {{"speed_mps", RoundSignificant(rr.speed_mps, 6)},
          {"spin_rad_per_s", RoundSignificant(rr.spin_rad_per_s, 6)},
          {"effective_radius_mm", RoundSignificant(1e3 * rr.effective_radius_m, 6)},
          {"loaded_radius_mm", RoundSignificant(1e3 * rr.loaded_radius_m, 6)},
          {"road_fx_N", RoundSignificant(rr.road_fx_N, 6)},
          {"road_fz_N", RoundSignificant(rr.road_fz_N, 6)},
          {"paper_spin_rad_per_s", 28.268},
          {"paper_effective_radius_mm", 394.2},
          {"max_cord_strain", CordStrainJson(rr.max_cord_strain)},
          {"energies", FeEnergiesJson(energies)}};
}

double CordStrainJson(double strain) { return RoundSignificant(strain, 4); }

// The stable step counts each cord's stiffness up to kCordStrainAllowance (explicit_model.h).
std::string CordStrainWarning(const std::string& step, double strain) {
  if (!(strain > kCordStrainAllowance)) return "";
  return fmt::format(
      "fe {}: warning: a cord reached a strain of {:.1f}%, above the {:.0f}% the stable step "
      "allows for (the safety factor covers some more; a smaller solver.time_step_safety covers "
      "more still)",
      step, 100.0 * strain, 100.0 * kCordStrainAllowance);
}

}  // namespace hotlap::fe
