#include "hotlap/fe/fe_config.h"

#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::fe {

namespace {

constexpr double kMm = 1e-3;
constexpr double kInch = 0.0254;

QuasiStaticStep ReadQuasiStatic(YamlReader& y) {
  QuasiStaticStep s;
  s.ramp_s = y.Number("ramp_s", Range::Positive("s"));
  s.hold_s = y.Number("hold_s", Range::NonNegative("s"));
  s.damping_per_s = y.Number("damping_per_s", Range::NonNegative("1/s"));
  return s;
}

int Count(YamlReader& y, const char* key, double lo, double hi) {
  const double v = y.Number(key, Range::Closed(lo, hi, ""));
  if (v != static_cast<int>(v)) y.Fail(key, fmt::format("{:g} must be a whole number", v));
  return static_cast<int>(v);
}

// The tyre's size.
void ReadTyreSize(YamlReader& y, FeConfig& c) {
  YamlReader t = y.Map("tyre");
  c.size.section_width_m = kMm * t.Number("section_width_mm", Range::Closed(100, 400, "mm"));
  c.size.aspect_ratio = t.Number("aspect_ratio", Range::Closed(0.2, 1.0, ""));
  c.size.rim_diameter_m = kInch * t.Number("rim_diameter_in", Range::Closed(10, 24, "in"));
  t.Finish();
}

// The section's profile (the mesh's shape).
void ReadProfile(YamlReader& y, FeConfig& c) {
  YamlReader p = y.Map("profile");
  TyreMeshOptions& m = c.mesh;
  m.rim_width_m = kMm * p.Number("rim_width_mm", Range::Positive("mm"));
  m.flange_height_m = kMm * p.Number("flange_height_mm", Range::NonNegative("mm"));
  m.tread_half_width_m = kMm * p.Number("tread_half_width_mm", Range::Positive("mm"));
  m.crown_thickness_m = kMm * p.Number("crown_thickness_mm", Range::Positive("mm"));
  m.sidewall_thickness_m = kMm * p.Number("sidewall_thickness_mm", Range::Positive("mm"));
  m.bead_thickness_m = kMm * p.Number("bead_thickness_mm", Range::Positive("mm"));
  m.widest_point_fraction = p.Number("widest_point_fraction", Range::Closed(0.2, 0.8, ""));
  m.profile_exponent = p.Number("profile_exponent", Range::Closed(1.5, 8.0, ""));
  if (m.tread_half_width_m >= 0.5 * c.size.section_width_m) {
    p.Fail("tread_half_width_mm",
           fmt::format("{:g} must be below half the section width", m.tread_half_width_m / kMm));
  }
  p.Finish();
}

// The mesh's divisions.
void ReadMeshDivisions(YamlReader& y, FeConfig& c) {
  YamlReader g = y.Map("mesh");
  TyreMeshOptions& m = c.mesh;
  m.meridional_elements_half = Count(g, "meridional_elements_half", 4, 200);
  m.thickness_elements = Count(g, "thickness_elements", 3, 20);
  m.tread_layers = Count(g, "tread_layers", 1, 18);
  m.circumferential_elements_contact = Count(g, "circumferential_elements_contact", 1, 2000);
  m.circumferential_elements_rest = Count(g, "circumferential_elements_rest", 3, 2000);
  m.contact_sector_half_angle_deg =
      g.Number("contact_sector_half_angle_deg", Range::OpenClosed(0, 90, "deg"));
  m.bead_volume_fraction = g.Number("bead_volume_fraction", Range::Closed(0.0, 0.4, ""));
  m.belt_plies = Count(g, "belt_plies", 1, 2);
  g.Finish();
}

// Each region's rubber (Yeoh), with the bulk modulus `bulk_to_shear` times the shear.
void ReadRubber(YamlReader& y, FeConfig& c, double bulk_to_shear) {
  YamlReader r = y.Map("rubber");
  for (const char* region : {"tread", "sidewall", "rim_strip", "belt", "ply", "filler"}) {
    YamlReader m = r.Map(region);
    const double c10 = m.Number("c10_Pa", Range::Positive("Pa"));
    const double c20 = m.Number("c20_Pa", Range::Any("Pa"));
    const double c30 = m.Number("c30_Pa", Range::Any("Pa"));
    const double rho = m.Number("density_kg_per_m3", Range::Closed(100, 20000, "kg/m^3"));
    m.Finish();
    c.rubber.push_back(MakeYeohMaterial(c10, c20, c30, rho, bulk_to_shear));
  }
  r.Finish();
}

// The cords' rebar.
void ReadCords(YamlReader& y, FeConfig& c) {
  YamlReader r = y.Map("cords");
  for (const char* cord : {"bead", "ply", "belt", "chafer"}) {
    YamlReader m = r.Map(cord);
    RebarMaterial b;
    b.name = cord;
    b.youngs_modulus_Pa = m.Number("youngs_modulus_Pa", Range::Positive("Pa"));
    b.density_kg_per_m3 = m.Number("density_kg_per_m3", Range::Closed(100, 20000, "kg/m^3"));
    b.response = m.Choice("response", {"tension_only", "linear"}) == "linear"
                     ? FibreResponse::kLinear
                     : FibreResponse::kTensionOnly;
    if (std::string(cord) != "bead") {  // 002 Table 3 has no bead row: circumferential wire
      b.area_m2 = m.Number("area_m2", Range::Positive("m^2"));
      b.spacing_m = m.Number("spacing_m", Range::Positive("m"));
      b.angle_deg = m.Number("angle_deg", Range::Closed(-90, 90, "deg"));
    }
    m.Finish();
    c.cords.push_back(b);
  }
  r.Finish();
}

// The explicit solver's options.
void ReadSolver(YamlReader& y, FeConfig& c) {
  YamlReader s = y.Map("solver");
  SolverOptions& o = c.solver;
  o.time_step_safety = s.Number("time_step_safety", Range::OpenClosed(0.0, 1.0, ""));
  o.bulk_viscosity_linear = s.Number("bulk_viscosity_linear", Range::Closed(0.0, 1.0, ""));
  o.bulk_viscosity_quadratic = s.Number("bulk_viscosity_quadratic", Range::Closed(0.0, 5.0, ""));
  o.hourglass_stiffness = s.Number("hourglass_stiffness", Range::Closed(0.0, 1.0, ""));
  o.hourglass_viscous = s.Number("hourglass_viscous", Range::Closed(0.0, 1.0, ""));
  o.mass_scaling_min_step_s = s.Number("mass_scaling_min_step_s", Range::Closed(0.0, 1e-3, "s"));
  s.Finish();
}

// The road contact: penalty factors (within the stable bound) and friction.
void ReadRoad(YamlReader& y, FeConfig& c) {
  YamlReader r = y.Map("road");
  c.road.penalty_factor = r.Number("penalty_factor", {0.0, 1.0, false, false, ""});
  c.road.tangential_penalty_factor =
      r.Number("tangential_penalty_factor", {0.0, 1.0, false, false, ""});
  // Stable with any mesh up to 4 (1 - s^2), s the step's safety factor (road_contact.h).
  const double bound = MaxStablePenaltyFactor(c.solver.time_step_safety);
  for (const auto& [key, value] :
       {std::pair{"penalty_factor", c.road.penalty_factor},
        {"tangential_penalty_factor", c.road.tangential_penalty_factor}}) {
    if (value > bound) {
      r.Fail(key, fmt::format("{:g} must be at most 4 (1 - solver.time_step_safety^2) = {:g}: "
                              "a stiffer contact spring can make the explicit step unstable",
                              value, bound));
    }
  }
  c.road.friction.static_coefficient = r.Number("static_friction", Range::Closed(0, 3, ""));
  c.road.friction.kinetic_coefficient = r.Number("kinetic_friction", Range::Closed(0, 3, ""));
  c.road.friction.decay_s_per_m = r.Number("decay_s_per_m", Range::NonNegative("s/m"));
  r.Finish();
}

// The rim's mass and inertia.
void ReadRim(YamlReader& y, FeConfig& c) {
  YamlReader r = y.Map("rim");
  c.rim_mass_kg = r.Number("mass_kg", Range::NonNegative("kg"));
  c.rim_inertia_kgm2 = r.Number("inertia_kg_m2", Range::NonNegative("kg m^2"));
  r.Finish();
}

// The inflation step.
void ReadInflate(YamlReader& y, FeConfig& c) {
  YamlReader s = y.Map("inflate");
  c.inflation_pressure_Pa = 1e3 * s.Number("pressure_kPa", Range::Closed(0, 1000, "kPa"));
  c.inflate = ReadQuasiStatic(s);
  s.Finish();
}

// The footprint step.
void ReadFootprint(YamlReader& y, FeConfig& c) {
  YamlReader s = y.Map("footprint");
  c.vertical_load_N = s.Number("vertical_load_N", Range::Closed(0, 1e5, "N"));
  c.footprint = ReadQuasiStatic(s);
  s.Finish();
}

// The rolling run.
void ReadRoll(YamlReader& y, FeConfig& c) {
  YamlReader s = y.Map("roll");
  c.roll_speed_mps = s.Number("speed_mps", Range::Closed(0, 100, "m/s"));
  c.roll_duration_s = s.Number("duration_s", Range::Positive("s"));
  s.Finish();
}

// The ABS run.
void ReadAbs(YamlReader& y, FeConfig& c) {
  YamlReader s = y.Map("abs");
  c.abs_config = s.FilePath("config_file");
  // Optional: the lumped quarter car's own tuning, run and drawn beside the FE stop too.
  if (s.Has("lumped_config_file")) c.abs_lumped_config = s.FilePath("lumped_config_file");
  c.abs_duration_s = s.Number("duration_s", Range::Positive("s"));
  s.Finish();
}

// The histories and frames written.
void ReadOutput(YamlReader& y, FeConfig& c) {
  YamlReader s = y.Map("output");
  c.history_interval_s = s.Number("history_interval_s", Range::Positive("s"));
  c.vtu_frames = Count(s, "vtu_frames", 1, 1000);
  s.Finish();
}
}  // namespace

FeConfig LoadFeConfig(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  FeConfig c;
  c.file = path;
  c.name = y.String("name");
  y.Choice("model", {"fe_tyre_explicit"});
  ReadTyreSize(y, c);
  ReadProfile(y, c);
  ReadMeshDivisions(y, c);
  const double bulk_to_shear = y.Number("bulk_to_shear_ratio", Range::Closed(1.0, 1e4, ""));
  ReadRubber(y, c, bulk_to_shear);
  ReadCords(y, c);
  ReadSolver(y, c);
  ReadRoad(y, c);
  ReadRim(y, c);
  ReadInflate(y, c);
  ReadFootprint(y, c);
  ReadRoll(y, c);
  ReadAbs(y, c);
  ReadOutput(y, c);
  if (c.mesh.tread_layers > c.mesh.thickness_elements - 2) {
    throw InputError(
        fmt::format("{}: field 'mesh.tread_layers': {} must be at most "
                    "thickness_elements - 2 ({})",
                    path.string(), c.mesh.tread_layers, c.mesh.thickness_elements - 2));
  }
  y.Finish();
  return c;
}

}  // namespace hotlap::fe
