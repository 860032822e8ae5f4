#include "hotlap/vehicle/vehicle_params.h"

#include <variant>

#include <fmt/format.h>

#include "hotlap/common/error.h"
#include "hotlap/common/units.h"
#include "hotlap/common/yaml_reader.h"

namespace hotlap::vehicle {

double VehicleParams::Weight() const { return chassis.mass * kGravity; }

std::array<double, 2> VehicleParams::CornerPosition(Corner c) const {
  const double x = IsFront(c) ? chassis.a() : -chassis.b();
  const bool left = c == Corner::kFrontLeft || c == Corner::kRearLeft;
  const double half = 0.5 * Track(c);
  return {x, left ? half : -half};
}

namespace {

ChassisParams ReadChassis(YamlReader y) {
  ChassisParams c;
  c.mass = y.Number("mass_kg", Range::Closed(100.0, 5000.0, "kg"));
  c.yaw_inertia = y.Number("yaw_inertia_kgm2", Range::Closed(10.0, 20000.0, "kg m^2"));
  c.wheelbase = y.Number("wheelbase_m", Range::Closed(0.5, 6.0, "m"));
  const Range share = Range::Closed(0.2, 0.8, "1");
  c.front_weight_fraction = y.Number("front_weight_fraction", share);
  c.left_weight_fraction = y.Number("left_weight_fraction", share);
  c.cog_height = y.Number("cog_height_m", Range::Closed(0.05, 2.0, "m"));
  c.track_front = y.Number("track_front_m", Range::Closed(0.5, 3.0, "m"));
  c.track_rear = y.Number("track_rear_m", Range::Closed(0.5, 3.0, "m"));
  c.roll_stiffness_front_share =
      y.Number("roll_stiffness_front_share", Range::Closed(0.0, 1.0, "1"));
  y.Finish();
  return c;
}

AeroParams ReadAero(YamlReader y) {
  AeroParams a;
  a.air_density = y.Number("air_density_kg_per_m3", Range::Closed(0.5, 1.5, "kg/m^3"));
  a.drag_area = y.Number("drag_area_m2", Range::Closed(0.0, 10.0, "m^2"));
  a.downforce_area = y.Number("downforce_area_m2", Range::Closed(-5.0, 20.0, "m^2"));
  a.front_downforce_share = y.Number("front_downforce_share", Range::Closed(0.0, 1.0, "1"));
  y.Finish();
  return a;
}

PowertrainParams ReadPowertrain(YamlReader y) {
  PowertrainParams p;
  y.Choice("drive", {"rear_spool"});
  p.engine_power = y.Number("engine_power_W", Range::Positive("W"));
  p.driveline_efficiency = y.Number("driveline_efficiency", Range::OpenClosed(0.0, 1.0, "1"));
  y.Finish();
  return p;
}

BrakeSystemParams ReadBrakeSystem(YamlReader y) {
  BrakeSystemParams b;
  b.front_share = y.Number("front_share", Range::Closed(0.0, 1.0, "1"));
  y.Finish();
  return b;
}

CornerSetup ReadCorner(YamlReader y) {
  CornerSetup c;
  c.forces = tyre::LoadTyreForceModel(y.FilePath("file"));
  c.pressure = 1e3 * y.Number("pressure_kPa", Range::Closed(20.0, 1000.0, "kPa"));
  c.camber = DegToRad(y.Number("camber_deg", Range::Closed(-10.0, 10.0, "deg")));
  const std::optional<double> radius =
      y.OptionalNumber("rolling_radius_m", Range::Closed(0.1, 1.0, "m"));
  if (radius) {
    c.rolling_radius = *radius;
  } else if (const auto* mf = std::get_if<tyre::MagicFormulaModel<double>>(&c.forces.params)) {
    c.rolling_radius = mf->params.UNLOADED_RADIUS;
  } else {
    y.Fail("rolling_radius_m",
           fmt::format("is required for a '{}' tyre force model (a .tir file gives its "
                       "UNLOADED_RADIUS); allowed {}",
                       c.forces.kind(), Range::Closed(0.1, 1.0, "m").Describe()));
  }
  y.Finish();
  return c;
}

}  // namespace

VehicleParams ReadVehicleParams(YamlReader& car) {
  VehicleParams v;
  v.chassis = ReadChassis(car.Map("chassis"));
  v.aero = ReadAero(car.Map("aero"));
  v.powertrain = ReadPowertrain(car.Map("powertrain"));
  v.brakes = ReadBrakeSystem(car.Map("brake_system"));
  YamlReader corners = car.Map("tyre_forces");
  for (Corner c : kAllCorners) {
    v.corners[CornerIndex(c)] = ReadCorner(corners.Map(CornerName(c)));
  }
  corners.Finish();
  return v;
}

}  // namespace hotlap::vehicle
