#include "hotlap/vehicle/vehicle_params.h"

#include <variant>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"
#include "hotlap/vehicle/vehicle_fields.h"

namespace hotlap::vehicle {

double VehicleParams::Weight() const { return chassis.mass * kGravity; }

std::array<double, 2> VehicleParams::CornerPosition(Corner c) const {
  const double x = IsFront(c) ? chassis.a() : -chassis.b();
  const bool left = c == Corner::kFrontLeft || c == Corner::kRearLeft;
  const double half = 0.5 * Track(c);
  return {x, left ? half : -half};
}

namespace {

// The numbers of `section` (VehicleFields), and then the reader is done with it.
void ReadSection(YamlReader y, std::string_view section, VehicleParams& v) {
  if (section == "powertrain") y.Choice("drive", {"rear_spool"});
  for (const VehicleField& f : VehicleFields()) {
    if (f.section == section) f.Of(v) = y.Number(f.key, f.range);
  }
  y.Finish();
}

CornerSetup ReadCorner(YamlReader y) {
  CornerSetup c;
  c.forces = tyre::LoadTyreForceModel(y.FilePath("file"));
  const CornerSetupField* left_out = nullptr;
  for (const CornerSetupField& f : CornerSetupFields()) {
    const std::optional<double> value =
        f.optional ? y.OptionalNumber(f.key, f.range) : y.Number(f.key, f.range);
    if (value) {
      c.*f.member = f.ToSi(*value);
    } else {
      left_out = &f;
    }
  }
  // Only the rolling radius may be left out, where a .tir model gives it (UNLOADED_RADIUS).
  if (left_out) {
    const auto* mf = std::get_if<tyre::MagicFormulaModel<double>>(&c.forces.params);
    if (!mf) {
      y.Fail(left_out->key,
             fmt::format("is required for a '{}' tyre force model (a .tir file gives its "
                         "UNLOADED_RADIUS); allowed {}",
                         c.forces.kind(), left_out->range.Describe()));
    }
    c.rolling_radius = mf->params.UNLOADED_RADIUS;
  }
  y.Finish();
  return c;
}

}  // namespace

VehicleParams ReadVehicleParams(YamlReader& car) {
  VehicleParams v;
  for (std::string_view section : {"chassis", "aero", "powertrain", "brake_system"}) {
    ReadSection(car.Map(section), section, v);
  }
  YamlReader corners = car.Map("tyre_forces");
  for (Corner c : kAllCorners) {
    v.corners[CornerIndex(c)] = ReadCorner(corners.Map(CornerName(c)));
  }
  corners.Finish();
  return v;
}

}  // namespace hotlap::vehicle
