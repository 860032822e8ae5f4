#include "hotlap/brake/brake_params_io.h"

#include <fmt/format.h>

#include "hotlap/common/yaml_reader.h"

namespace hotlap::brake {

namespace {

ConvectionPolynomial<double> ReadCholesky(YamlReader& parent, std::string_view key) {
  YamlReader c = parent.Map(key);
  // Diagonal entries are kept non-negative so that (L, P) is a unique pair; off-diagonal entries
  // may have either sign. Any such L gives a positive semi-definite P.
  const Range diagonal = Range::NonNegative("sqrt(W/K)");
  const Range off = Range::Any("sqrt(W/K)");
  ConvectionPolynomial<double> l;
  l.l11 = c.Number("l11", diagonal);
  l.l21 = c.Number("l21", off);
  l.l22 = c.Number("l22", diagonal);
  l.l31 = c.Number("l31", off);
  l.l32 = c.Number("l32", off);
  l.l33 = c.Number("l33", diagonal);
  c.Finish();
  return l;
}

}  // namespace

BrakeFile LoadBrakeFile(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  BrakeFile out;
  out.path = path;
  out.name = y.String("name");
  y.Choice("model", {"two_mass_disc_calliper"});
  BrakeThermalParams<double>& p = out.params;
  p.heat_partition = y.Number("heat_partition", Range::Closed(0.0, 1.0, ""));
  p.mass_participation = y.Number("mass_participation", Range::OpenClosed(0.0, 1.0, ""));
  p.disc_mass = y.Number("disc_mass_kg", Range::Positive("kg"));
  p.disc_heat_capacity = y.Number("disc_heat_capacity_J_per_kgK", Range::Positive("J/(kg K)"));
  p.calliper_mass = y.Number("calliper_mass_kg", Range::Positive("kg"));
  p.calliper_heat_capacity =
      y.Number("calliper_heat_capacity_J_per_kgK", Range::Positive("J/(kg K)"));
  p.pad_conductivity = y.Number("pad_conductivity_W_per_mK", Range::NonNegative("W/(m K)"));
  p.pad_area = 1e-6 * y.Number("pad_area_mm2", Range::Positive("mm^2"));
  p.pad_thickness = 1e-3 * y.Number("pad_thickness_mm", Range::Positive("mm"));
  p.disc_emissivity = y.Number("disc_emissivity", Range::Closed(0.0, 1.0, ""));
  p.calliper_emissivity = y.Number("calliper_emissivity", Range::Closed(0.0, 1.0, ""));
  p.disc_radiating_area = y.Number("disc_radiating_area_m2", Range::NonNegative("m^2"));
  p.calliper_radiating_area =
      1e-4 * y.Number("calliper_radiating_area_cm2", Range::NonNegative("cm^2"));
  {
    YamlReader g = y.Map("geometry");
    out.geometry.disc_diameter = 1e-3 * g.Number("disc_diameter_mm", Range::Positive("mm"));
    out.geometry.mounting_hole_diameter =
        1e-3 * g.Number("mounting_hole_diameter_mm", Range::NonNegative("mm"));
    out.geometry.disc_thickness = 1e-3 * g.Number("disc_thickness_mm", Range::Positive("mm"));
    if (!(out.geometry.mounting_hole_diameter < out.geometry.disc_diameter)) {
      g.Fail("mounting_hole_diameter_mm", "must be smaller than disc_diameter_mm");
    }
    g.Finish();
  }
  p.disc_convection = ReadCholesky(y, "disc_convection_cholesky_sqrtW_per_K");
  p.calliper_convection = ReadCholesky(y, "calliper_convection_cholesky_sqrtW_per_K");
  y.Finish();
  return out;
}

}  // namespace hotlap::brake
