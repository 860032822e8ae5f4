#include "fe_output.h"

#include <cstdio>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/csv.h"
#include "hotlap/common/json_output.h"

namespace hotlap::app {

namespace fs = std::filesystem;

void WriteFeHistoryCsv(const fs::path& path, const std::string& step, const fe::FeConfig& config,
                       const std::vector<fe::HistoryRow>& history, double loaded_radius) {
  const std::vector<std::string> columns = {
      "time_s",      "rim_x_m",         "rim_z_m",         "rim_vx_mps",     "spin_rad_per_s",
      "omega_R_mps", "brake_torque_Nm", "road_fx_N",       "road_fz_N",      "slip",
      "kinetic_J",   "internal_J",      "hourglass_J",     "bulk_viscous_J", "damping_J",
      "friction_J",  "contact_J",       "external_work_J", "balance_error_J"};
  std::vector<std::vector<double>> v(columns.size());
  for (const fe::HistoryRow& r : history) {
    const fe::Energies& e = r.energies;
    const double row[] = {r.time_s,          r.rim_x_m,
                          r.rim_z_m,         r.rim_vx_mps,
                          r.spin_rad_per_s,  r.spin_rad_per_s * loaded_radius,
                          r.brake_torque_Nm, r.road_fx_N,
                          r.road_fz_N,       r.slip,
                          e.kinetic,         e.internal,
                          e.Hourglass(),     e.bulk_viscous,
                          e.damping,         e.friction,
                          e.contact_stored,  e.external_work,
                          e.BalanceError()};
    for (size_t k = 0; k < columns.size(); ++k) v[k].push_back(row[k]);
  }
  WriteCsv(path, {{"config", config.file.string()}, {"step", step}}, columns, v);
}

void WriteFootprintPressure(const fs::path& out, const fe::FeConfig& config,
                            const fe::FootprintResult& fp) {
  std::vector<std::vector<double>> map(4);
  for (const fe::ContactPoint& p : fp.contact) {
    map[0].push_back(p.x_m);
    map[1].push_back(p.y_m);
    map[2].push_back(p.force_N);
    map[3].push_back(p.pressure_Pa);
  }
  WriteCsv(out / "footprint_pressure.csv", {{"config", config.file.string()}},
           {"x_m", "y_m", "force_N", "pressure_Pa"}, map);
  WriteFileAtomically(out / "footprint_pressure.svg", [&](std::ostream& svg) {
    const double scale = 2000.0;  // px per metre
    const double w = 0.35 * scale, h = 0.35 * scale;
    fmt::print(svg,
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\">\n"
               "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
               "<text x=\"10\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">"
               "contact pressure, peak {2:.0f} kPa (x forward to the right, y up)</text>\n",
               w, h, 1e-3 * fp.peak_pressure_Pa);
    for (const fe::ContactPoint& p : fp.contact) {
      const double s = fp.peak_pressure_Pa > 0 ? p.pressure_Pa / fp.peak_pressure_Pa : 0.0;
      const int red = static_cast<int>(255 * s), blue = static_cast<int>(255 * (1 - s));
      fmt::print(svg, "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"6\" fill=\"rgb({},0,{})\"/>\n",
                 0.5 * w + scale * p.x_m, 0.5 * h - scale * p.y_m, red, blue);
    }
    svg << "</svg>\n";
  });
}

nlohmann::json FeEnergiesJson(const fe::Energies& e) {
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

namespace {

// The stable step counts each cord's stiffness up to kCordStrainAllowance (explicit_model.h).
double CordStrain(const char* step, double strain) {
  if (strain > fe::kCordStrainAllowance) {
    std::fprintf(stderr,
                 "fe %s: warning: a cord reached a strain of %.1f%%, above the %.0f%% the stable "
                 "step allows for (the safety factor covers some more; a smaller "
                 "solver.time_step_safety covers more still)\n",
                 step, 100.0 * strain, 100.0 * fe::kCordStrainAllowance);
  }
  return RoundSignificant(strain, 4);
}

}  // namespace

nlohmann::json InflateJson(const fe::InflateResult& inf, const fe::Energies& energies) {
  return {{"pressure_kPa", RoundSignificant(1e-3 * inf.pressure_Pa, 6)},
          {"outer_radius_before_mm", RoundSignificant(1e3 * inf.outer_radius_before_m, 6)},
          {"outer_radius_after_mm", RoundSignificant(1e3 * inf.outer_radius_after_m, 6)},
          {"section_width_before_mm", RoundSignificant(1e3 * inf.section_width_before_m, 6)},
          {"section_width_after_mm", RoundSignificant(1e3 * inf.section_width_after_m, 6)},
          {"roundness_error_mm", RoundSignificant(1e3 * inf.max_roundness_error_m, 3)},
          {"max_cord_strain", CordStrain("inflate", inf.max_cord_strain)},
          {"energies", FeEnergiesJson(energies)}};
}

nlohmann::json FootprintJson(const fe::FootprintResult& fp, const fe::Energies& energies) {
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
      {"max_cord_strain", CordStrain("footprint", fp.max_cord_strain)},
      {"energies", FeEnergiesJson(energies)}};
}

nlohmann::json RollJson(const fe::RollResult& rr, const fe::Energies& energies) {
  return {{"speed_mps", RoundSignificant(rr.speed_mps, 6)},
          {"spin_rad_per_s", RoundSignificant(rr.spin_rad_per_s, 6)},
          {"effective_radius_mm", RoundSignificant(1e3 * rr.effective_radius_m, 6)},
          {"loaded_radius_mm", RoundSignificant(1e3 * rr.loaded_radius_m, 6)},
          {"road_fx_N", RoundSignificant(rr.road_fx_N, 6)},
          {"road_fz_N", RoundSignificant(rr.road_fz_N, 6)},
          {"paper_spin_rad_per_s", 28.268},
          {"paper_effective_radius_mm", 394.2},
          {"max_cord_strain", CordStrain("roll", rr.max_cord_strain)},
          {"energies", FeEnergiesJson(energies)}};
}

nlohmann::json AbsStopJson(const sim::FeAbsStopResult& r, double duration_s,
                           const fe::Energies& energies) {
  const fe::BrakeResult& br = r.brake;
  const sim::CycleWindow& cycles = r.cycles;
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
      {"max_cord_strain", CordStrain("abs", br.max_cord_strain)},
      {"energies", FeEnergiesJson(energies)}};
}

}  // namespace hotlap::app
