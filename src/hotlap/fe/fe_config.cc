#include "hotlap/fe/fe_config.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/fe/fe_config_fields.h"

namespace hotlap::fe {

namespace {

// The numbers and counts of `section` (fe_config_fields.h) from `y`, the section's map.
void ReadNumbers(YamlReader& y, std::string_view section, FeConfig& c) {
  for (const FeConfigField* f : FeConfigFieldsIn(section)) {
    const double v = y.Number(f->key, f->range);
    if (!f->IsCount()) {
      f->number(c) = f->to_si * v;
    } else if (v != static_cast<int>(v)) {
      y.Fail(f->key, fmt::format("{:g} must be a whole number", v));
    } else {
      f->count(c) = static_cast<int>(v);
    }
  }
}

// A section holding numbers only, then the checks `check` makes on them.
template <typename Check>
void ReadSection(YamlReader& y, std::string_view section, FeConfig& c, Check check) {
  YamlReader s = y.Map(section);
  ReadNumbers(s, section, c);
  check(s);
  s.Finish();
}

void ReadSection(YamlReader& y, std::string_view section, FeConfig& c) {
  ReadSection(y, section, c, [](YamlReader&) {});
}

// Each region's rubber (Yeoh), its bulk modulus bulk_to_shear_ratio times the shear.
void ReadRubber(YamlReader& y, FeConfig& c) {
  YamlReader r = y.Map("rubber");
  for (std::string_view region : FeRubberRegions()) {
    YamlReader m = r.Map(region);
    YeohMaterial rubber;
    for (const FeRubberField& f : FeRubberFields()) rubber.*f.member = m.Number(f.key, f.range);
    m.Finish();
    c.rubber.push_back(MakeYeohMaterial(rubber.c10_Pa, rubber.c20_Pa, rubber.c30_Pa,
                                        rubber.density_kg_per_m3, c.bulk_to_shear_ratio));
  }
  r.Finish();
}

// The cords' rebar.
void ReadCords(YamlReader& y, FeConfig& c) {
  YamlReader r = y.Map("cords");
  const std::span<const std::string_view> responses = FeCordResponses();
  for (std::string_view cord : FeCordNames()) {
    YamlReader m = r.Map(cord);
    RebarMaterial b;
    b.name = cord;
    for (const FeCordField& f : FeCordFields()) {
      if (f.bead_has_it || cord != "bead") b.*f.member = m.Number(f.key, f.range);
    }
    const std::string response =
        m.Choice("response", std::vector<std::string>(responses.begin(), responses.end()));
    b.response = static_cast<FibreResponse>(
        std::find(responses.begin(), responses.end(), response) - responses.begin());
    m.Finish();
    c.cords.push_back(b);
  }
  r.Finish();
}

// The profile's tread must lie within the section.
void CheckProfile(YamlReader& p, const FeConfig& c) {
  const TyreMeshOptions& m = c.mesh;
  if (m.tread_half_width_m >= 0.5 * c.size.section_width_m) {
    p.Fail("tread_half_width_mm",
           fmt::format("{:g} must be below half the section width", m.tread_half_width_m / 1e-3));
  }
}

// The contact's penalty factors within the bound that keeps the explicit step stable with any
// mesh: 4 (1 - s^2), s the step's safety factor (road_contact.h).
void CheckRoad(YamlReader& r, const FeConfig& c) {
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
}

// The ABS run: its number, the ABS file and, optionally, the lumped quarter car's own tuning
// (run and drawn beside the FE stop too).
void ReadAbs(YamlReader& y, FeConfig& c) {
  ReadSection(y, "abs", c, [&](YamlReader& s) {
    c.abs_config = s.FilePath("config_file");
    if (s.Has("lumped_config_file")) c.abs_lumped_config = s.FilePath("lumped_config_file");
  });
}
}  // namespace

FeConfig LoadFeConfig(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  FeConfig c;
  c.file = path;
  c.name = y.String("name");
  y.Choice("model", {"fe_tyre_explicit"});
  ReadSection(y, "tyre", c);
  ReadSection(y, "profile", c, [&](YamlReader& p) { CheckProfile(p, c); });
  ReadSection(y, "mesh", c);
  ReadNumbers(y, "", c);
  ReadRubber(y, c);
  ReadCords(y, c);
  ReadSection(y, "solver", c);
  ReadSection(y, "road", c, [&](YamlReader& r) { CheckRoad(r, c); });
  for (std::string_view section : {"rim", "inflate", "footprint", "roll"}) {
    ReadSection(y, section, c);
  }
  ReadAbs(y, c);
  ReadSection(y, "output", c);
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
