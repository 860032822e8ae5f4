#include "hotlap/fe/fe_config_fields.h"

namespace hotlap::fe {

namespace {

constexpr double kMm = 1e-3;
constexpr double kInch = 0.0254;
constexpr double kKpa = 1e3;

using R = Range;

// A row for a number (in the file's unit times `to_si`) and one for a whole-number count.
#define FE_NUMBER(section, key, range, to_si, member)                           \
  FeConfigField {                                                               \
    section, key, range, to_si, [](FeConfig& c) -> double& { return c.member; } \
  }
#define FE_COUNT(section, key, lo, hi, member)         \
  FeConfigField {                                      \
    section, key, R::Closed(lo, hi, ""), 1.0, nullptr, \
        [](FeConfig& c) -> int& { return c.member; }   \
  }

}  // namespace

std::string FeConfigField::Path() const {
  return section.empty() ? std::string(key) : std::string(section) + "." + std::string(key);
}

double FeConfigField::Of(const FeConfig& c) const {
  FeConfig& m = const_cast<FeConfig&>(c);  // the accessors only read here
  return IsCount() ? static_cast<double>(count(m)) : number(m);
}

std::span<const FeConfigField> FeConfigFields() {
  static const FeConfigField kFields[] = {
      FE_NUMBER("tyre", "section_width_mm", R::Closed(100, 400, "mm"), kMm, size.section_width_m),
      FE_NUMBER("tyre", "aspect_ratio", R::Closed(0.2, 1.0, ""), 1.0, size.aspect_ratio),
      FE_NUMBER("tyre", "rim_diameter_in", R::Closed(10, 24, "in"), kInch, size.rim_diameter_m),
      FE_NUMBER("profile", "rim_width_mm", R::Positive("mm"), kMm, mesh.rim_width_m),
      FE_NUMBER("profile", "flange_height_mm", R::NonNegative("mm"), kMm, mesh.flange_height_m),
      FE_NUMBER("profile", "tread_half_width_mm", R::Positive("mm"), kMm, mesh.tread_half_width_m),
      FE_NUMBER("profile", "crown_thickness_mm", R::Positive("mm"), kMm, mesh.crown_thickness_m),
      FE_NUMBER("profile", "sidewall_thickness_mm", R::Positive("mm"), kMm,
                mesh.sidewall_thickness_m),
      FE_NUMBER("profile", "bead_thickness_mm", R::Positive("mm"), kMm, mesh.bead_thickness_m),
      FE_NUMBER("profile", "widest_point_fraction", R::Closed(0.2, 0.8, ""), 1.0,
                mesh.widest_point_fraction),
      FE_NUMBER("profile", "profile_exponent", R::Closed(1.5, 8.0, ""), 1.0, mesh.profile_exponent),
      FE_COUNT("mesh", "meridional_elements_half", 4, 200, mesh.meridional_elements_half),
      FE_COUNT("mesh", "thickness_elements", 3, 20, mesh.thickness_elements),
      FE_COUNT("mesh", "tread_layers", 1, 18, mesh.tread_layers),
      FE_COUNT("mesh", "circumferential_elements_contact", 1, 2000,
               mesh.circumferential_elements_contact),
      FE_COUNT("mesh", "circumferential_elements_rest", 3, 2000,
               mesh.circumferential_elements_rest),
      FE_NUMBER("mesh", "contact_sector_half_angle_deg", R::OpenClosed(0, 90, "deg"), 1.0,
                mesh.contact_sector_half_angle_deg),
      FE_NUMBER("mesh", "bead_volume_fraction", R::Closed(0.0, 0.4, ""), 1.0,
                mesh.bead_volume_fraction),
      FE_COUNT("mesh", "belt_plies", 1, 2, mesh.belt_plies),
      FE_NUMBER("", "bulk_to_shear_ratio", R::Closed(1.0, 1e4, ""), 1.0, bulk_to_shear_ratio),
      FE_NUMBER("solver", "time_step_safety", R::OpenClosed(0.0, 1.0, ""), 1.0,
                solver.time_step_safety),
      FE_NUMBER("solver", "bulk_viscosity_linear", R::Closed(0.0, 1.0, ""), 1.0,
                solver.bulk_viscosity_linear),
      FE_NUMBER("solver", "bulk_viscosity_quadratic", R::Closed(0.0, 5.0, ""), 1.0,
                solver.bulk_viscosity_quadratic),
      FE_NUMBER("solver", "hourglass_stiffness", R::Closed(0.0, 1.0, ""), 1.0,
                solver.hourglass_stiffness),
      FE_NUMBER("solver", "hourglass_viscous", R::Closed(0.0, 1.0, ""), 1.0,
                solver.hourglass_viscous),
      FE_NUMBER("solver", "mass_scaling_min_step_s", R::Closed(0.0, 1e-3, "s"), 1.0,
                solver.mass_scaling_min_step_s),
      // Open at both ends; the stable bound (4 (1 - s^2), s the step's safety) is checked after.
      FE_NUMBER("road", "penalty_factor", (R{0.0, 1.0, false, false, ""}), 1.0,
                road.penalty_factor),
      FE_NUMBER("road", "tangential_penalty_factor", (R{0.0, 1.0, false, false, ""}), 1.0,
                road.tangential_penalty_factor),
      FE_NUMBER("road", "static_friction", R::Closed(0, 3, ""), 1.0,
                road.friction.static_coefficient),
      FE_NUMBER("road", "kinetic_friction", R::Closed(0, 3, ""), 1.0,
                road.friction.kinetic_coefficient),
      FE_NUMBER("road", "decay_s_per_m", R::NonNegative("s/m"), 1.0, road.friction.decay_s_per_m),
      FE_NUMBER("rim", "mass_kg", R::NonNegative("kg"), 1.0, rim_mass_kg),
      FE_NUMBER("rim", "inertia_kg_m2", R::NonNegative("kg m^2"), 1.0, rim_inertia_kgm2),
      FE_NUMBER("inflate", "pressure_kPa", R::Closed(0, 1000, "kPa"), kKpa, inflation_pressure_Pa),
      FE_NUMBER("inflate", "ramp_s", R::Positive("s"), 1.0, inflate.ramp_s),
      FE_NUMBER("inflate", "hold_s", R::NonNegative("s"), 1.0, inflate.hold_s),
      FE_NUMBER("inflate", "damping_per_s", R::NonNegative("1/s"), 1.0, inflate.damping_per_s),
      FE_NUMBER("footprint", "vertical_load_N", R::Closed(0, 1e5, "N"), 1.0, vertical_load_N),
      FE_NUMBER("footprint", "ramp_s", R::Positive("s"), 1.0, footprint.ramp_s),
      FE_NUMBER("footprint", "hold_s", R::NonNegative("s"), 1.0, footprint.hold_s),
      FE_NUMBER("footprint", "damping_per_s", R::NonNegative("1/s"), 1.0, footprint.damping_per_s),
      FE_NUMBER("roll", "speed_mps", R::Closed(0, 100, "m/s"), 1.0, roll_speed_mps),
      FE_NUMBER("roll", "duration_s", R::Positive("s"), 1.0, roll_duration_s),
      FE_NUMBER("abs", "duration_s", R::Positive("s"), 1.0, abs_duration_s),
      FE_NUMBER("output", "history_interval_s", R::Positive("s"), 1.0, history_interval_s),
      FE_COUNT("output", "vtu_frames", 1, 1000, vtu_frames),
  };
  return kFields;
}

#undef FE_NUMBER
#undef FE_COUNT

std::vector<const FeConfigField*> FeConfigFieldsIn(std::string_view section) {
  std::vector<const FeConfigField*> out;
  for (const FeConfigField& f : FeConfigFields()) {
    if (f.section == section) out.push_back(&f);
  }
  return out;
}

std::span<const std::string_view> FeRubberRegions() {
  static constexpr std::string_view kRegions[] = {"tread", "sidewall", "rim_strip",
                                                  "belt",  "ply",      "filler"};
  return kRegions;
}

std::span<const FeRubberField> FeRubberFields() {
  static const FeRubberField kFields[] = {
      {"c10_Pa", &YeohMaterial::c10_Pa, R::Positive("Pa")},
      {"c20_Pa", &YeohMaterial::c20_Pa, R::Any("Pa")},
      {"c30_Pa", &YeohMaterial::c30_Pa, R::Any("Pa")},
      {"density_kg_per_m3", &YeohMaterial::density_kg_per_m3, R::Closed(100, 20000, "kg/m^3")},
  };
  return kFields;
}

std::span<const std::string_view> FeCordNames() {
  static constexpr std::string_view kCords[] = {"bead", "ply", "belt", "chafer"};
  return kCords;
}

std::span<const FeCordField> FeCordFields() {
  static const FeCordField kFields[] = {
      {"youngs_modulus_Pa", &RebarMaterial::youngs_modulus_Pa, R::Positive("Pa")},
      {"density_kg_per_m3", &RebarMaterial::density_kg_per_m3, R::Closed(100, 20000, "kg/m^3")},
      {"area_m2", &RebarMaterial::area_m2, R::Positive("m^2"), false},
      {"spacing_m", &RebarMaterial::spacing_m, R::Positive("m"), false},
      {"angle_deg", &RebarMaterial::angle_deg, R::Closed(-90, 90, "deg"), false},
  };
  return kFields;
}

std::span<const std::string_view> FeCordResponses() {
  static constexpr std::string_view kResponses[] = {"tension_only", "linear"};
  return kResponses;
}

}  // namespace hotlap::fe
