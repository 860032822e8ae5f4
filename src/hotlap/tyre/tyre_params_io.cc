#include "hotlap/tyre/tyre_params_io.h"

#include <optional>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/field_table.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/tyre/tyre_thermal_fields.h"

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

// The construction's cross-field checks, once its section is read.
void CheckConstruction(const YamlReader& c, const TyreThermalParams<double>& p) {
  if (!(p.rim_radius < p.unloaded_radius)) {
    c.Fail("rim_radius_m", fmt::format("{:g} m must be smaller than unloaded_radius_m ({:g} m)",
                                       p.rim_radius, p.unloaded_radius));
  }
  if (!(p.contact_width < p.width)) {
    c.Fail("contact_width_m",
           fmt::format("{:g} m must be smaller than width_m ({:g} m)", p.contact_width, p.width));
  }
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

TyreFile LoadTyreFile(const std::filesystem::path& path) { return LoadTyreFile(path, {}); }

TyreFile LoadTyreFile(const std::filesystem::path& path,
                      const std::vector<YamlOverride>& overrides) {
  YamlReader y = YamlReader::Load(path, overrides);
  TyreFile out;
  out.path = path;
  out.name = y.String("name");
  y.Choice("model", {"two_mass_thermal"});
  out.compound_path = y.FilePath("compound");
  out.compound = std::make_shared<const TyreCompound>(LoadTyreCompound(out.compound_path));

  TyreThermalParams<double>& p = out.params;
  // The paper's equations unless the file says otherwise (docs/models.md).
  const std::string model = y.Has("thermal_model") ? y.Choice("thermal_model", {"paper", "gas_rim"})
                                                   : std::string("paper");
  p.model = model == "gas_rim" ? TyreThermalModel::kGasRim : TyreThermalModel::kPaper;
  for (std::string_view section : TyreThermalSections()) {
    // The gas-and-rim sections are needed by that model alone; a paper-model file may keep them
    // (checked, unused), so switching thermal_model compares the two on the same file.
    if (IsGasRimSection(section) && !p.HasGasAndRim() && !y.Has(section)) continue;
    YamlReader s = y.Map(section);
    for (const TyreThermalField* f : TyreThermalFieldsIn(section)) {
      const double value = s.Number(f->key, f->range);
      f->Of(p) = FieldToSi(*f, value);
    }
    if (section == "construction") CheckConstruction(s, p);
    if (section == "gas" && p.gas_liner_conductance > 0.0 && !(p.liner_rim_conductance > 0.0)) {
      s.Fail("liner_rim_W_per_K",
             "must be > 0 where gas_liner_W_per_K is: the liner's gas has no other way out");
    }
    // A car without tyre forces has no set-up pressure: the tyre file may give it
    // (vehicle::LoadCar). Read only where present: it is refused for a car with tyre forces, so
    // it is no override key.
    if (section == "gas" && s.Has("cold_pressure_kPa")) {
      p.cold_pressure = 1e3 * s.Number("cold_pressure_kPa", Range::Closed(20.0, 1000.0, "kPa"));
      out.cold_pressure_in_file = true;
    }
    s.Finish();
  }
  y.Finish();
  return out;
}

}  // namespace hotlap::tyre
