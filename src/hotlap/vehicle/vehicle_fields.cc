#include "hotlap/vehicle/vehicle_fields.h"

#include <array>

#include "hotlap/common/units.h"

namespace hotlap::vehicle {

std::span<const VehicleField> VehicleFields() {
  using V = VehicleParams;
  const Range share = Range::Closed(0.2, 0.8, "1");
  // clang-format off
  static const auto table = std::to_array<VehicleField>({
      {"chassis", "mass_kg", [](V& v) -> double& { return v.chassis.mass; }, Range::Closed(100.0, 5000.0, "kg")},
      {"chassis", "yaw_inertia_kgm2", [](V& v) -> double& { return v.chassis.yaw_inertia; }, Range::Closed(10.0, 20000.0, "kg m^2")},
      {"chassis", "wheelbase_m", [](V& v) -> double& { return v.chassis.wheelbase; }, Range::Closed(0.5, 6.0, "m")},
      {"chassis", "front_weight_fraction", [](V& v) -> double& { return v.chassis.front_weight_fraction; }, share},
      {"chassis", "left_weight_fraction", [](V& v) -> double& { return v.chassis.left_weight_fraction; }, share},
      {"chassis", "cog_height_m", [](V& v) -> double& { return v.chassis.cog_height; }, Range::Closed(0.05, 2.0, "m")},
      {"chassis", "track_front_m", [](V& v) -> double& { return v.chassis.track_front; }, Range::Closed(0.5, 3.0, "m")},
      {"chassis", "track_rear_m", [](V& v) -> double& { return v.chassis.track_rear; }, Range::Closed(0.5, 3.0, "m")},
      {"chassis", "roll_stiffness_front_share", [](V& v) -> double& { return v.chassis.roll_stiffness_front_share; }, Range::Closed(0.0, 1.0, "1")},
      {"aero", "air_density_kg_per_m3", [](V& v) -> double& { return v.aero.air_density; }, Range::Closed(0.5, 1.5, "kg/m^3")},
      {"aero", "drag_area_m2", [](V& v) -> double& { return v.aero.drag_area; }, Range::Closed(0.0, 10.0, "m^2")},
      {"aero", "downforce_area_m2", [](V& v) -> double& { return v.aero.downforce_area; }, Range::Closed(-5.0, 20.0, "m^2")},
      {"aero", "front_downforce_share", [](V& v) -> double& { return v.aero.front_downforce_share; }, Range::Closed(0.0, 1.0, "1")},
      {"powertrain", "engine_power_W", [](V& v) -> double& { return v.powertrain.engine_power; }, Range::Positive("W")},
      {"powertrain", "driveline_efficiency", [](V& v) -> double& { return v.powertrain.driveline_efficiency; }, Range::OpenClosed(0.0, 1.0, "1")},
      {"brake_system", "front_share", [](V& v) -> double& { return v.brakes.front_share; }, Range::Closed(0.0, 1.0, "1")},
  });
  // clang-format on
  return table;
}

std::string VehicleField::Path() const { return std::string(section) + "." + std::string(key); }

std::span<const CornerSetupField> CornerSetupFields() {
  static const auto corner = std::to_array<CornerSetupField>({
      {"pressure_kPa", &CornerSetup::pressure, Range::Closed(20.0, 1000.0, "kPa"),
       &KilopascalsToPascals, &PascalsToKilopascals},
      {"camber_deg", &CornerSetup::camber, Range::Closed(-10.0, 10.0, "deg"), &DegToRad, &RadToDeg},
      {"rolling_radius_m", &CornerSetup::rolling_radius, Range::Closed(0.1, 1.0, "m"), nullptr,
       nullptr, true},
  });
  return corner;
}

std::span<const InitialStateField> InitialStateFields() {
  using T = InitialTemperatures;
  static const auto table = std::to_array<InitialStateField>({
      {"tread_temp_C", &T::tread_temp},
      {"carcass_temp_C", &T::carcass_temp},
      {"disc_temp_C", &T::disc_temp},
      {"calliper_temp_C", &T::calliper_temp},
      {"rim_temp_C", &T::rim_temp, &T::carcass_temp},           // the gas-and-rim tyres' rims
      {"disc_bulk_temp_C", &T::disc_bulk_temp, &T::disc_temp},  // the bulk discs' bulk
  });
  return table;
}

Range InitialTemperatureRange() { return Range::Closed(-50.0, 1200.0, "degC"); }

std::optional<double> VehicleFileValue(const VehicleParams& p, std::string_view path) {
  for (const VehicleField& f : VehicleFields()) {
    if (f.Path() == path) return f.Of(p);
  }
  // tyre_forces.<c>.<key>
  constexpr std::string_view kCorners = "tyre_forces.";
  if (!path.starts_with(kCorners)) return std::nullopt;
  const std::string_view rest = path.substr(kCorners.size());
  const size_t dot = rest.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  const std::optional<Corner> c = ParseCorner(rest.substr(0, dot));
  if (!c) return std::nullopt;
  for (const CornerSetupField& f : CornerSetupFields()) {
    if (f.key == rest.substr(dot + 1)) return f.FromSi(p.corners[CornerIndex(*c)].*f.member);
  }
  return std::nullopt;
}

}  // namespace hotlap::vehicle
