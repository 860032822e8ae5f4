#include "hotlap/tyre/tyre_params_io.h"

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::tyre {

namespace {

TemperatureCubic ReadCubic(YamlReader& parent, std::string_view key, CubicKind kind) {
  YamlReader y = parent.Map(key);
  const Range temp_c = Range::Closed(-100.0, 500.0, "degC");
  const Range value = Range::Positive("");
  TemperatureCubicSpec s;
  s.kind = kind;
  s.optimal_temp = CelsiusToKelvin(y.Number("optimal_temp_C", temp_c));
  s.low_temp = CelsiusToKelvin(y.Number("low_temp_C", temp_c));
  s.low_value = y.Number("low_value", value);
  s.high_temp = CelsiusToKelvin(y.Number("high_temp_C", temp_c));
  s.high_value = y.Number("high_value", value);
  s.valid_min_temp = CelsiusToKelvin(y.Number("valid_min_temp_C", temp_c));
  s.valid_max_temp = CelsiusToKelvin(y.Number("valid_max_temp_C", temp_c));
  y.Finish();
  return TemperatureCubic::Create(s, parent.Where(key));
}

GripWearTable ReadGripWearTable(YamlReader& parent, std::string_view key) {
  GripWearTable table;
  for (YamlReader& row : parent.MapList(key, 2)) {
    table.wear_mm.push_back(row.Number("wear_mm", Range::NonNegative("mm")));
    table.factor.push_back(row.Number("factor", Range::OpenClosed(0.0, 1.0, "")));
    row.Finish();
  }
  if (table.wear_mm.front() != 0.0) {
    parent.Fail(key, fmt::format("the first row must be at wear_mm 0, not {:g}", table.wear_mm[0]));
  }
  for (size_t i = 1; i < table.wear_mm.size(); ++i) {
    if (!(table.wear_mm[i] > table.wear_mm[i - 1])) {
      parent.Fail(key,
                  fmt::format("wear_mm must be strictly increasing; row {} has {:g} after {:g}", i,
                              table.wear_mm[i], table.wear_mm[i - 1]));
    }
    if (table.factor[i] > table.factor[i - 1]) {
      parent.Fail(key,
                  fmt::format("grip must not rise with wear; row {} has factor {:g} after {:g}", i,
                              table.factor[i], table.factor[i - 1]));
    }
  }
  return table;
}

}  // namespace

TyreCompound LoadTyreCompound(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  const std::string name = y.String("name");
  y.Choice("model", {"cubic_grip_wear"});
  TemperatureCubic grip = ReadCubic(y, "grip_cubic", CubicKind::kGripMaximum);
  TemperatureCubic wear = ReadCubic(y, "wear_rate_cubic", CubicKind::kWearMinimum);
  GripWearTable table = ReadGripWearTable(y, "grip_vs_wear");
  const double q_ref = y.Number("wear_reference_power_W", Range::Positive("W"));
  y.Finish();
  return TyreCompound{name, grip, wear, std::move(table), q_ref};
}

TyreFile LoadTyreFile(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  TyreFile out;
  out.path = path;
  out.name = y.String("name");
  y.Choice("model", {"two_mass_thermal"});
  out.compound_path = y.FilePath("compound");
  out.compound = std::make_shared<const TyreCompound>(LoadTyreCompound(out.compound_path));

  TyreThermalParams<double>& p = out.params;
  {
    YamlReader g = y.Map("heat_generation");
    p.p1 = g.Number("p1", Range::Closed(0.0, 1.0, ""));
    p.p2 = g.Number("p2_J_per_kgN", Range::NonNegative("J/(kg N)"));
    p.p3 = g.Number("p3_J_per_kgN", Range::NonNegative("J/(kg N)"));
    p.p4 = g.Number("p4_J_per_kgN", Range::NonNegative("J/(kg N)"));
    p.p5 = g.Number("p5_W_per_m2K", Range::NonNegative("W/(m^2 K)"));
    g.Finish();
  }
  {
    YamlReader w = y.Map("wear");
    p.wear_coeff = w.Number("wp1_mm_per_s", Range::NonNegative("mm/s"));
    p.wear_exponent = w.Number("wp2", Range::Closed(0.0, 10.0, ""));
    w.Finish();
  }
  {
    YamlReader c = y.Map("contact_length");
    p.contact_length_coeff = c.Number("p_cp1", Range::Positive("m/N^p_cp2"));
    p.contact_length_exponent = c.Number("p_cp2", Range::Closed(0.0, 2.0, ""));
    c.Finish();
  }
  {
    YamlReader c = y.Map("construction");
    p.tread_mass = c.Number("tread_mass_kg", Range::Positive("kg"));
    p.carcass_mass = c.Number("carcass_mass_kg", Range::Positive("kg"));
    p.tread_heat_capacity = c.Number("tread_heat_capacity_J_per_kgK", Range::Positive("J/(kg K)"));
    p.carcass_heat_capacity =
        c.Number("carcass_heat_capacity_J_per_kgK", Range::Positive("J/(kg K)"));
    p.track_conductance = c.Number("track_conductance_W_per_m2K", Range::NonNegative("W/(m^2 K)"));
    p.contact_width = c.Number("contact_width_m", Range::Positive("m"));
    p.reference_slip_angle =
        DegToRad(c.Number("reference_slip_angle_deg", Range::OpenClosed(0.0, 90.0, "deg")));
    p.non_sliding_fraction_low = c.Number("non_sliding_fraction_low", Range::Closed(0.0, 1.0, ""));
    p.non_sliding_fraction_high =
        c.Number("non_sliding_fraction_high", Range::Closed(0.0, 1.0, ""));
    p.unloaded_radius = c.Number("unloaded_radius_m", Range::Positive("m"));
    p.rim_radius = c.Number("rim_radius_m", Range::Positive("m"));
    p.diameter = c.Number("diameter_m", Range::Positive("m"));
    p.width = c.Number("width_m", Range::Positive("m"));
    p.emissivity = c.Number("emissivity", Range::Closed(0.0, 1.0, ""));
    if (!(p.rim_radius < p.unloaded_radius)) {
      c.Fail("rim_radius_m", fmt::format("{:g} m must be smaller than unloaded_radius_m ({:g} m)",
                                         p.rim_radius, p.unloaded_radius));
    }
    if (!(p.contact_width < p.width)) {
      c.Fail("contact_width_m",
             fmt::format("{:g} m must be smaller than width_m ({:g} m)", p.contact_width, p.width));
    }
    c.Finish();
  }
  y.Finish();
  return out;
}

}  // namespace hotlap::tyre
