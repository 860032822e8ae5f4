#include "hotlap/brake/brake_params_io.h"

#include "hotlap/brake/brake_thermal_fields.h"
#include "hotlap/common/field_table.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::brake {

namespace {

// The table's entries of one section, read from `y` (that section's map, or the file).
void ReadSection(YamlReader& y, std::string_view section, BrakeThermalParams<double>& p) {
  for (const BrakeThermalField* f : BrakeThermalFieldsIn(section)) {
    const double value = y.Number(f->key, f->range);
    f->Of(p) = FieldToSi(*f, value);
  }
}

BrakeGeometry ReadGeometry(YamlReader& y) {
  BrakeGeometry geometry;
  YamlReader g = y.Map("geometry");
  geometry.disc_diameter = 1e-3 * g.Number("disc_diameter_mm", Range::Positive("mm"));
  geometry.mounting_hole_diameter =
      1e-3 * g.Number("mounting_hole_diameter_mm", Range::NonNegative("mm"));
  geometry.disc_thickness = 1e-3 * g.Number("disc_thickness_mm", Range::Positive("mm"));
  if (!(geometry.mounting_hole_diameter < geometry.disc_diameter)) {
    g.Fail("mounting_hole_diameter_mm", "must be smaller than disc_diameter_mm");
  }
  g.Finish();
  return geometry;
}

}  // namespace

BrakeFile LoadBrakeFile(const std::filesystem::path& path) { return LoadBrakeFile(path, {}); }

BrakeFile LoadBrakeFile(const std::filesystem::path& path,
                        const std::vector<YamlOverride>& overrides) {
  YamlReader y = YamlReader::Load(path, overrides);
  BrakeFile out;
  out.path = path;
  out.name = y.String("name");
  y.Choice("model", {"two_mass_disc_calliper"});
  // The paper's lumped disc unless the file says otherwise (docs/models.md).
  const std::string disc = y.Has("disc_model") ? y.Choice("disc_model", {"lumped", "surface_bulk"})
                                               : std::string("lumped");
  out.params.disc_model = disc == "surface_bulk" ? DiscModel::kSurfaceBulk : DiscModel::kLumped;
  for (std::string_view section : BrakeThermalSections()) {
    // Needed by the bulk disc alone; a lumped disc's file may keep it (checked, unused).
    if (section == kDiscBulkSection && !out.params.HasBulk() && !y.Has(section)) continue;
    if (section.empty()) {
      ReadSection(y, section, out.params);
      out.geometry = ReadGeometry(y);  // documents the part; not a thermal parameter
      continue;
    }
    YamlReader s = y.Map(section);
    ReadSection(s, section, out.params);
    if (section == kDiscBulkSection && out.params.HasBulk() &&
        !(out.params.mass_participation < 1.0)) {
      y.Fail("mass_participation",
             "must be below 1 with disc_model surface_bulk: the rest of the disc is its bulk");
    }
    s.Finish();
  }
  y.Finish();
  return out;
}

}  // namespace hotlap::brake
