#include "hotlap/sim/synth_params.h"

#include <algorithm>
#include <optional>
#include <span>
#include <string_view>

#include "hotlap/common/field_table.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::sim {

namespace {

// The fitted entries of a field table present in `y` (a corner's `tyre:` or `brake:` map): those
// of the top-level section "" directly, those of any other section inside its map when it is
// there. Sections without fitted entries are not read, so their keys are unknown fields.
template <class Field>
std::vector<Override<Field>> ReadFitted(YamlReader& y, std::span<const std::string_view> sections,
                                        const std::vector<const Field*>& fitted) {
  std::vector<Override<Field>> out;
  const auto read = [&](YamlReader& r, std::string_view section) {
    for (const Field* f : fitted) {
      if (f->section != section) continue;
      if (const std::optional<double> v = r.OptionalNumber(f->key, f->range)) {
        out.push_back({f, *v});
      }
    }
  };
  for (std::string_view section : sections) {
    const bool any = std::any_of(fitted.begin(), fitted.end(),
                                 [&](const Field* f) { return f->section == section; });
    if (!any) continue;
    if (section.empty()) {
      read(y, section);
    } else if (y.Has(section)) {
      YamlReader s = y.Map(section);
      read(s, section);
      s.Finish();
    }
  }
  return out;
}

template <class Field, class Params>
void Apply(const std::vector<Override<Field>>& overrides, Params& params) {
  for (const Override<Field>& o : overrides) {
    o.field->Of(params) = FieldToSi(*o.field, o.value);
  }
}

}  // namespace

ParameterOverrides LoadParameterOverrides(const std::filesystem::path& path) {
  YamlReader y = YamlReader::Load(path);
  ParameterOverrides out;
  out.path = path;
  out.name = y.String("name");
  y.Choice("model", {"parameter_overrides"});
  YamlReader corners = y.Map("corners");
  for (Corner c : kAllCorners) {
    if (!corners.Has(CornerName(c))) continue;
    YamlReader corner = corners.Map(CornerName(c));
    CornerOverrides& o = out.corners[CornerIndex(c)];
    if (corner.Has("tyre")) {
      YamlReader t = corner.Map("tyre");
      o.tyre = ReadFitted(t, tyre::TyreThermalSections(), tyre::FittedTyreThermalFields());
      t.Finish();
    }
    if (corner.Has("brake")) {
      YamlReader b = corner.Map("brake");
      o.brake = ReadFitted(b, brake::BrakeThermalSections(), brake::FittedBrakeThermalFields());
      b.Finish();
    }
    corner.Finish();
  }
  corners.Finish();
  y.Finish();
  return out;
}

void ApplyParameterOverrides(const ParameterOverrides& o, vehicle::Car& car) {
  for (Corner c : kAllCorners) {
    const int i = CornerIndex(c);
    Apply(o.corners[i].tyre, car.tyres[i].params);
    Apply(o.corners[i].brake, car.brakes[i].params);
  }
}

}  // namespace hotlap::sim
